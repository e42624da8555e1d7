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
  bool ok = true;
  auto bind = [&](auto& fn, const char* name) {
    if (!ok) return;
    dlerror();
    void* sym = dlsym(p->handle_, name);
    if (!sym) {
      ok = false;
      const char* why = dlerror();
      error = path + ": error: not a vv model: the entry point " + name + " is missing" +
              (why ? std::string(" (") + why + ")" : std::string());
      return;
    }
    fn = reinterpret_cast<std::remove_reference_t<decltype(fn)>>(sym);
  };
  bind(p->abi_version, "vv_plugin_abi_version");
  if (ok && p->abi_version() != VV_PLUGIN_ABI_VERSION) {
    error = path + ": error: the model was built for plugin ABI " + std::to_string(p->abi_version()) +
            ", this interpreter loads ABI " + std::to_string(VV_PLUGIN_ABI_VERSION) + "; rebuild it";
    return nullptr;
  }
  bind(p->configure, "vv_plugin_configure");
  bind(p->start, "vv_plugin_start");
  bind(p->step, "vv_plugin_step");
  bind(p->end, "vv_plugin_end");
  bind(p->close, "vv_plugin_close");
  bind(p->render_init, "vv_plugin_render_init");
  bind(p->render, "vv_plugin_render");
  bind(p->render_screen, "vv_plugin_render_screen");
  bind(p->reread, "vv_plugin_reread");
  bind(p->has_block, "vv_plugin_has_block");
  bind(p->proxy, "vv_plugin_proxy");
  bind(p->meshes, "vv_plugin_meshes");
  bind(p->union_vvm, "vv_plugin_union_vvm");
  bind(p->union_geometry, "vv_plugin_union_geometry");
  bind(p->error_frames, "vv_plugin_error_frames");
  bind(p->check, "vv_plugin_check");
  bind(p->params, "vv_plugin_params");
  bind(p->describe_vertex, "vv_plugin_describe_vertex");
  bind(p->file_objects, "vv_plugin_file_objects");
  if (!ok) return nullptr;
  return p;
}

plugin::~plugin() {
  if (handle_) dlclose(handle_);
  if (!copy_.empty()) unlink(copy_.c_str());
}

}  // namespace vvi
