// The registry of file objects: every VLAB file object (util::Function,
// Contour, Palette, Materials) adds itself while it exists, so that the
// host's "reread files" reaches it without the program putting it into the
// proxy's lists, and a host can list the files a model reads.
//
// Each model (a plugin) has its own registry: the inline function's static
// lives in the model's code. The registry is not locked; the host calls
// into a model from one thread at a time.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <exception>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "io/files.hpp"
#include "plugin/proxy.hpp"

namespace vv {

//! The kinds, in the order "reread files" takes them (the proxy's lists).
enum class file_kind : std::size_t { materials, palettes, functions, contours };
inline constexpr std::size_t file_kind_count = 4;

class file_registry {
 public:
  void add(file_kind kind, file_object* object) { lists_[static_cast<std::size_t>(kind)].push_back(object); }

  void remove(file_object* object) {
    for (auto& list : lists_) list.erase(std::remove(list.begin(), list.end(), object), list.end());
  }

  //! Where relative file names lead: the model's folder, set before the
  //! program's globals are made (the generated code does it first), so
  //! that `util::Function f("growth.func");` finds the file beside the
  //! .vvp whatever the host's working directory. Empty: the working directory.
  void set_base_dir(std::string dir) { base_dir_ = std::move(dir); }
  std::string resolve(const std::string& file) const {
    // "model/../data/f.func" reads as "data/f.func" in messages and lists.
    return std::filesystem::path(io::resolve(base_dir_, file)).lexically_normal().string();
  }

  const std::vector<file_object*>& objects(file_kind kind) const {
    return lists_[static_cast<std::size_t>(kind)];
  }

  std::size_t size() const {
    std::size_t n = 0;
    for (const auto& list : lists_) n += list.size();
    return n;
  }

  //! The files of the registered objects, kind by kind, each once; objects
  //! without a file are left out.
  std::vector<std::string> paths() const {
    std::vector<std::string> out;
    for (const auto& list : lists_)
      for (const file_object* object : list)
        if (!object->path().empty() && std::find(out.begin(), out.end(), object->path()) == out.end())
          out.push_back(object->path());
    return out;
  }

 private:
  std::array<std::vector<file_object*>, file_kind_count> lists_;
  std::string base_dir_;
};

//! The registry of this program. Created by the first file object, so it
//! outlives every object that registers (static objects included).
inline file_registry& file_objects() {
  static file_registry registry;
  return registry;
}

//! Rereads the objects in the proxy's lists (materials, palettes,
//! functions, contours) and the registered objects, kind by kind, each
//! object once however often it appears. A failure does not stop the
//! others: every object is tried, then the first error is thrown.
inline void reread_file_objects(std::initializer_list<const std::vector<file_object*>*> proxy_lists) {
  std::vector<file_object*> order;
  auto take = [&order](const std::vector<file_object*>& list) {
    for (file_object* object : list)
      if (object && std::find(order.begin(), order.end(), object) == order.end()) order.push_back(object);
  };
  std::size_t kind = 0;
  for (const std::vector<file_object*>* list : proxy_lists) {
    take(*list);
    if (kind < file_kind_count) take(file_objects().objects(static_cast<file_kind>(kind++)));
  }
  for (; kind < file_kind_count; ++kind) take(file_objects().objects(static_cast<file_kind>(kind)));

  // `order` is a copy: a reread() that makes or drops file objects does not
  // disturb the walk.
  std::exception_ptr first_failure;
  for (file_object* object : order) {
    try {
      object->reread();
    } catch (...) {
      if (!first_failure) first_failure = std::current_exception();
    }
  }
  if (first_failure) std::rethrow_exception(first_failure);
}

//! The base of the VLAB file objects: the file's path and the registration
//! under `Kind` for as long as the object exists. A copy registers too.
//! There is no move: moving copies, so the source keeps its file and values.
template <file_kind Kind>
class registered_file : public file_object {
 public:
  const std::string& path() const override { return path_; }
  //! vv 1.1's name for path().
  const std::string& getFilename() const { return path_; }

 protected:
  //! The file is resolved once, here: path() names the file read, in
  //! errors and for a host that watches it.
  explicit registered_file(const std::string& file = {})
      : path_(file.empty() ? file : file_objects().resolve(file)) {
    file_objects().add(Kind, this);
  }
  registered_file(const registered_file& other) : file_object(other), path_(other.path_) {
    file_objects().add(Kind, this);
  }
  // Registered as it is; only the file changes.
  registered_file& operator=(const registered_file& other) {
    path_ = other.path_;
    return *this;
  }
  ~registered_file() override { file_objects().remove(this); }

 private:
  std::string path_;
};

}  // namespace vv
