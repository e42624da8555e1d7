// Where the calling thread's stack begins, for context::block_scope: the
// handles a block makes on its own stack hold no count.
#pragma once

#include <cstddef>
#include <cstdint>

#if defined(__linux__)
#include <pthread.h>
#endif

namespace vv::detail {

//! The lowest address of the calling thread's stack; 0 where unknown (no
//! handle then goes uncounted). For the main thread the C library reads
//! the process's memory map: callers keep the answer (model/program.hpp
//! keeps it per thread it ran on). No thread_local here: a model's own
//! thread-local storage, in a library loaded and unloaded at run time, is
//! what this must not depend on.
inline std::uintptr_t thread_stack_low() noexcept {
#if defined(__linux__)
  pthread_attr_t attr;
  if (pthread_getattr_np(pthread_self(), &attr) != 0) return 0;
  void* addr = nullptr;
  std::size_t size = 0;
  const bool known = pthread_attr_getstack(&attr, &addr, &size) == 0 && size != 0;
  pthread_attr_destroy(&attr);
  return known ? reinterpret_cast<std::uintptr_t>(addr) : 0;
#else
  return 0;
#endif
}

//! thread_stack_low(), asked again only when the calling thread changes.
class thread_stack_cache {
 public:
  std::uintptr_t low() noexcept {
#if defined(__linux__)
    const pthread_t self = pthread_self();
    if (!known_ || !pthread_equal(self, thread_)) {
      low_ = thread_stack_low();
      thread_ = self;
      known_ = true;
    }
    return low_;
#else
    return 0;
#endif
  }

 private:
#if defined(__linux__)
  pthread_t thread_{};
#endif
  std::uintptr_t low_ = 0;
  bool known_ = false;
};

}  // namespace vv::detail
