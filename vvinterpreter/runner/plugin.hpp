// A loaded model plugin: the shared object and its entry points
// (vvlib/vv/plugin/plugin.hpp). Unloading it destroys the model's state.
#pragma once

#include <memory>
#include <string>

#include <vv/plugin/plugin.hpp>

namespace vvi {

class plugin {
 public:
  //! Loads a plugin; nullptr with `error` set when the file cannot be
  //! loaded, lacks an entry point (named) or was built for another ABI.
  static std::unique_ptr<plugin> open(const std::string& path, std::string& error);
  ~plugin();
  plugin(const plugin&) = delete;
  plugin& operator=(const plugin&) = delete;

  using block_fn = const char* (*)();
  int (*abi_version)() = nullptr;
  void (*configure)(const vv_plugin_settings*) = nullptr;
  block_fn start = nullptr, step = nullptr, end = nullptr, close = nullptr;
  block_fn render_init = nullptr, render = nullptr, render_screen = nullptr, reread = nullptr;
  int (*has_block)(const char*) = nullptr;
  vv::proxy* (*proxy)() = nullptr;
  const vv_mesh_entry* (*meshes)(std::size_t*) = nullptr;
  const char* (*union_vvm)(const char* const*, std::size_t, const char*) = nullptr;
  const char* (*union_geometry)(const char* const*, std::size_t, std::size_t, vv_geometry*) = nullptr;
  const void* const* (*error_frames)(std::size_t*) = nullptr;
  const char* (*check)() = nullptr;
  const vv_param_entry* (*params)(std::size_t*) = nullptr;
  const char* (*describe_vertex)(unsigned, const char**) = nullptr;
  const char* (*file_objects)() = nullptr;

  const std::string& path() const { return path_; }
  //! The private copy that is loaded (what /proc/self/maps names).
  const std::string& loaded_copy() const { return copy_; }

 private:
  plugin() = default;
  void* handle_ = nullptr;
  std::string path_;
  std::string copy_;  // the private copy that is loaded (removed on unload)
};

}  // namespace vvi
