// The file objects of one model. Every VLAB file object (util::Function,
// Contour, Palette, Materials) adds itself to the registry of the model it
// was made in, so that the host's "reread files" reaches it without the
// program putting it into the proxy's lists, and the host can list the
// files a model reads.
//
// A registry is a member of its model (model/program.hpp); there is none
// for the process. A file object finds its model's registry through
// running_registry(): the registry of the model whose code runs on this
// thread, set while the model makes its globals and while each of its entry
// points runs. The object keeps that registry for its life (its copies
// too); an object made outside any model (a C++ program using util::Function
// directly, the interpreter's function editor) is registered nowhere, and
// rereads when told to.
#pragma once

#include <algorithm>
#include <array>
#include <exception>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <vv/io/files.hpp>

#include "file_object.hpp"

namespace vv::model {

class file_registry {
 public:
  file_registry() = default;
  // Objects point to their registry: it stays where it is.
  file_registry(const file_registry&) = delete;
  file_registry& operator=(const file_registry&) = delete;

  void add(file_kind kind, file_object* object) { lists_[static_cast<std::size_t>(kind)].push_back(object); }

  void remove(file_object* object) {
    for (auto& list : lists_) list.erase(std::remove(list.begin(), list.end(), object), list.end());
  }

  //! Where relative file names lead: the model's folder, set before the
  //! program's globals are made, so that `util::Function f("growth.func");`
  //! finds the file beside the .vvp whatever the host's working directory.
  //! Empty: the working directory.
  void set_base_dir(std::string dir) { base_dir_ = std::move(dir); }
  const std::string& base_dir() const { return base_dir_; }

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

  //! Rereads the objects of these lists (the proxy's: materials, palettes,
  //! functions, contours) and the registered objects, kind by kind, each
  //! object once however often it appears. A failure does not stop the
  //! others: every object is tried, then the first error is thrown.
  void reread(const std::array<const std::vector<file_object*>*, file_kind_count>& listed) const {
    std::vector<file_object*> order;
    auto take = [&order](const std::vector<file_object*>& list) {
      for (file_object* object : list)
        if (object && std::find(order.begin(), order.end(), object) == order.end()) order.push_back(object);
    };
    for (std::size_t kind = 0; kind < file_kind_count; ++kind) {
      if (listed[kind]) take(*listed[kind]);
      take(lists_[kind]);
    }
    // `order` is a copy: a reread() that makes or drops file objects does
    // not disturb the walk.
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

 private:
  std::array<std::vector<file_object*>, file_kind_count> lists_;
  std::string base_dir_;
};

//! The registry of the model whose code runs on this thread; null when no
//! model's code runs. Per thread, so that a host running one model on a
//! worker thread and making file objects of its own on another (the
//! function editor) keeps them apart.
inline file_registry*& running_registry() noexcept {
  thread_local file_registry* running = nullptr;
  return running;
}

//! While it exists, file objects made on this thread belong to `r`.
class registry_scope {
 public:
  explicit registry_scope(file_registry& r) noexcept : previous_(running_registry()) { running_registry() = &r; }
  ~registry_scope() { running_registry() = previous_; }
  registry_scope(const registry_scope&) = delete;
  registry_scope& operator=(const registry_scope&) = delete;

 private:
  file_registry* previous_;
};

//! A file name as an object keeps it: resolved against the registry's
//! folder (the working directory without a registry) and normalised, so
//! "model/../data/f.func" reads as "data/f.func" in messages and lists.
inline std::string resolve_file(const file_registry* r, const std::string& file) {
  return std::filesystem::path(io::resolve(r ? r->base_dir() : std::string(), file)).lexically_normal().string();
}

}  // namespace vv::model
