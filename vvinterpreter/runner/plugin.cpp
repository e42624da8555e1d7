#include "runner/plugin.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>

#include <vv/io/files.hpp>

#include "runner/fault_guard.hpp"
#include "runner/throw_points.hpp"

namespace vvi {

namespace {

// Every load gets its own copy of the plugin under a name never used
// before: the dynamic loader hands back an already loaded object when the
// name (or the file) is the same, and then the model's globals would not
// be initialised again (a reload of an unchanged build, a rewind while the
// old instance is still loaded). The name is a temporary's of vvlib
// (vv/io/output_file.hpp): it holds this process's PID, its PID namespace,
// the load's number and random letters, made with O_EXCL, so runs in other
// containers sharing $TMPDIR, or other threads, never write over it. The
// copy is removed once loaded (the mapping keeps it); copies of processes
// killed before that are removed by the next load.
std::string private_copy(const std::string& path, std::string& error) {
  static std::atomic<unsigned> loads{0};
  std::string dir = vv::io::temporary_folder();
  auto fail = [&](const std::string& why) {
    error = path + ": error: cannot load the model: cannot copy it to " + dir + ": " + why;
    return std::string();
  };
  std::string why;
  std::optional<std::string> bytes = vv::io::read_file(path, &why);
  if (!bytes) {
    error = path + ": error: cannot load the model: " + why;
    return "";
  }
  vv::io::remove_dead_temporaries(dir);
  vv::io::unique_file copy = vv::io::create_temporary(dir, "vv-model-" + std::to_string(++loads), ".so");
  if (copy.fd < 0) return fail(copy.error);
  int e = vv::io::detail::write_all(copy.fd, bytes->data(), bytes->size());
  if (::close(copy.fd) != 0 && e == 0) e = errno;
  if (e != 0) {
    ::unlink(copy.path.c_str());
    return fail(std::strerror(e));
  }
  return copy.path;
}

// Whether a debugger (or another tracer) is attached: gdb reads the
// loaded file again after the load (to unwind through it, for sections it
// reads lazily), so under one the copy stays until the model is unloaded.
bool traced() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("TracerPid:", 0) == 0) return std::strtol(line.c_str() + 10, nullptr, 10) != 0;
  return false;
}

std::string abi_mismatch(const std::string& path, int version) {
  return path + ": error: the model was built for plugin ABI " + std::to_string(version) +
         ", this interpreter loads ABI " + std::to_string(VV_PLUGIN_ABI_VERSION) + "; rebuild it";
}

// A model built before the descriptor (plugin ABI 4 and older) exported
// one function per entry, the first of them its version: name both
// versions rather than call it "not a vv model". "" when it is none.
std::string other_abi(void* handle, const std::string& path) {
  auto version = reinterpret_cast<int (*)()>(dlsym(handle, "vv_plugin_abi_version"));
  return version ? abi_mismatch(path, version()) : std::string();
}

std::string dlerror_text() {
  const char* why = dlerror();
  return why ? why : "unknown reason";
}

}  // namespace

std::unique_ptr<plugin> plugin::open(const std::string& path, std::string& error) {
  std::unique_ptr<plugin> p(new plugin);
  p->path_ = path;
  std::string copy = private_copy(path, error);
  if (copy.empty()) return nullptr;
  // RTLD_LOCAL: two models loaded one after the other never share symbols.
  // No try/catch around this: an exception thrown by a global initialiser
  // must reach std::terminate with the throw still on the stack, so the
  // crash report names its .vvp line.
  fault_guard::note_module(copy, path);
  fault_guard::begin("loading");
  throw_points::keep(true);  // its global initialisers run now
  p->handle_ = dlopen(copy.c_str(), RTLD_NOW | RTLD_LOCAL);
  throw_points::keep(false);
  fault_guard::finish();
  // Loaded or not, the file is no longer needed: /proc/self/maps names it
  // "(deleted)", and the crash report reads the line tables of the plugin
  // it was copied from (note_module). Under a debugger it goes on unload.
  p->copy_ = copy;
  p->copy_removed_ = !traced() && ::unlink(copy.c_str()) == 0;
  if (!p->handle_) {
    std::string why = dlerror_text();
    // The loader names the private copy; the user knows the plugin.
    for (std::size_t at; (at = why.find(copy)) != std::string::npos;) why.replace(at, copy.size(), path);
    error = path + ": error: cannot load the model: " + why;
    return nullptr;
  }
  p->model_ = static_cast<const vv_plugin*>(dlsym(p->handle_, VV_PLUGIN_DESCRIPTOR_SYMBOL));
  if (!p->model_) {
    error = other_abi(p->handle_, path);
    if (error.empty())
      error = path + ": error: not a vv model: the entry point " VV_PLUGIN_DESCRIPTOR_SYMBOL " is missing";
    return nullptr;
  }
  if (p->model_->abi_version != VV_PLUGIN_ABI_VERSION) {
    error = abi_mismatch(path, p->model_->abi_version);
    return nullptr;
  }
  return p;
}

plugin::~plugin() {
  // Its global destructors run now: a throw there ends the process, and the
  // crash report names the throw's line from this record (fault_guard.cpp).
  throw_points::keep(true);
  if (handle_) dlclose(handle_);
  throw_points::keep(false);
  if (!copy_removed_ && !copy_.empty()) ::unlink(copy_.c_str());
}

}  // namespace vvi
