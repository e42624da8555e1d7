#include "plugin.hpp"

#include <dlfcn.h>

namespace vvi {

std::unique_ptr<plugin> plugin::open(const std::string& path, std::string& error) {
  std::unique_ptr<plugin> p(new plugin);
  p->path_ = path;
  // RTLD_LOCAL: two models loaded one after the other never share symbols.
  p->handle_ = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!p->handle_) {
    const char* why = dlerror();
    error = path + ": error: cannot load the model: " + (why ? why : "unknown reason");
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
  if (!ok) return nullptr;
  return p;
}

plugin::~plugin() {
  if (handle_) dlclose(handle_);
}

}  // namespace vvi
