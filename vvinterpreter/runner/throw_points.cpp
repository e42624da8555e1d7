#include "runner/throw_points.hpp"

#include <dlfcn.h>
#include <execinfo.h>

#include <cstdlib>
#include <typeinfo>

namespace vvi::throw_points {

namespace {

// Enough to reach the model's innermost frame (the throw, the C++
// library's __throw_* helper, a few inlined frames); each frame costs.
constexpr int max_frames = 16;
thread_local bool keeping = false;
thread_local void* frames[max_frames];
thread_local int frame_count = 0;

}  // namespace

void keep(bool on) {
  keeping = on;
  frame_count = 0;
}

namespace {

// Called by the C++ runtime's throw (below), before anything unwinds.
void note_throw() {
  if (keeping) frame_count = backtrace(frames, max_frames);
}

std::size_t copy_frames(void** out, std::size_t max) {
  std::size_t n = 0;
  for (; n < max && static_cast<int>(n) < frame_count; ++n) out[n] = frames[n];
  return n;
}

}  // namespace

}  // namespace vvi::throw_points

extern "C" {

std::size_t vv_host_throw_frames(void** frames, std::size_t max) { return vvi::throw_points::copy_frames(frames, max); }

// Every throw of the process, the models' and the C++ library's (which
// calls it through its PLT, so the executable's definition comes first),
// goes through here on its way to the real one.
[[noreturn]] void __cxa_throw(void* object, std::type_info* type, void (*destroy)(void*)) {
  using throw_fn = void (*)(void*, std::type_info*, void (*)(void*));
  static const throw_fn real = reinterpret_cast<throw_fn>(dlsym(RTLD_NEXT, "__cxa_throw"));
  vvi::throw_points::note_throw();
  if (!real) std::abort();
  real(object, type, destroy);
  __builtin_unreachable();
}

}  // extern "C"
