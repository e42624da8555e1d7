// A loaded model plugin: the shared object and its descriptor
// (vvlib/model/abi.hpp). Unloading it destroys the model's state.
#pragma once

#include <memory>
#include <string>

#include <model/abi.hpp>

namespace vvi {

class plugin {
 public:
  //! Loads a plugin; nullptr with `error` set when the file cannot be
  //! loaded, lacks the descriptor (named) or was built for another ABI
  //! (both versions named).
  static std::unique_ptr<plugin> open(const std::string& path, std::string& error);
  ~plugin();
  plugin(const plugin&) = delete;
  plugin& operator=(const plugin&) = delete;

  using block_fn = const char* (*)();
  //! The model's descriptor: its blocks (NULL when absent), meshes,
  //! parameters and the functions over the whole model.
  const vv_plugin& model() const { return *model_; }

  const std::string& path() const { return path_; }
  //! The private copy that is loaded (what /proc/self/maps names).
  const std::string& loaded_copy() const { return copy_; }

 private:
  plugin() = default;
  void* handle_ = nullptr;
  const vv_plugin* model_ = nullptr;
  std::string path_;
  std::string copy_;  // the private copy that is loaded (removed on unload)
};

}  // namespace vvi
