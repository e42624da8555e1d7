#include "runner/plugin.hpp"

#include <dlfcn.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>

#include <atomic>
#include <cstdlib>
#include <filesystem>

#include "runner/fault_guard.hpp"

namespace vvi {

namespace {

std::string temporary_dir() {
  const char* tmp = std::getenv("TMPDIR");
  return tmp && *tmp ? tmp : "/tmp";
}

// Copies left by processes that were killed ("vv-model-PID-N.so").
void remove_stale_copies(const std::string& dir) {
  std::error_code ec;
  for (auto it = std::filesystem::directory_iterator(dir, ec); !ec && it != std::filesystem::directory_iterator();
       it.increment(ec)) {
    std::string name = it->path().filename().string();
    if (name.rfind("vv-model-", 0) != 0) continue;
    long pid = std::strtol(name.c_str() + 9, nullptr, 10);
    std::error_code rm;
    if (pid > 0 && kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) std::filesystem::remove(it->path(), rm);
  }
}

// Every load gets its own copy of the plugin under a name never used
// before: the dynamic loader hands back an already loaded object when the
// name (or the file) is the same, and then the model's globals would not
// be initialised again (a reload of an unchanged build, a rewind while the
// old instance is still loaded). The copy stays while the model is loaded,
// so a debugger and the crash report can read its line tables.
std::string private_copy(const std::string& path, std::string& error) {
  static std::atomic<unsigned> loads{0};
  std::string dir = temporary_dir();
  if (loads == 0) remove_stale_copies(dir);
  std::string copy = dir + "/vv-model-" + std::to_string(getpid()) + "-" + std::to_string(++loads) + ".so";
  std::error_code ec;
  std::filesystem::copy_file(path, copy, std::filesystem::copy_options::overwrite_existing, ec);
  if (ec) error = path + ": error: cannot load the model: cannot copy it to " + dir + ": " + ec.message();
  return ec ? std::string() : copy;
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
  p->handle_ = dlopen(copy.c_str(), RTLD_NOW | RTLD_LOCAL);
  fault_guard::finish();
  p->copy_ = copy;
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
  if (handle_) dlclose(handle_);
  if (!copy_.empty()) unlink(copy_.c_str());
}

}  // namespace vvi
