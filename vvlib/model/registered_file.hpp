// What the four VLAB file objects (util::Function, Contour, Palette,
// Materials) share: the file's path, the registration in their model's
// registry (model/file_registry.hpp) for as long as they exist, and how
// they read it. Each class says only how its file becomes its contents:
//
//   class Palette : public vv::model::registered_file<Palette, vv::file_kind::palettes, colours> {
//     static colours read(const std::string& path);  // throws vv::error, changes nothing
//   };
//
// Construction with a file reads it whole (an error throws and leaves
// nothing registered); reread() reads it again and replaces the contents
// only when the whole file was good; a copy registers too and shares the
// file and the contents. There is no move: moving copies, so the source
// keeps its file and values.
#pragma once

#include <string>
#include <utility>

#include "file_object.hpp"
#include "file_registry.hpp"

namespace vv::model {

template <class Derived, file_kind Kind, class Contents>
class registered_file : public file_object {
 public:
  const std::string& path() const override { return path_; }
  //! vv 1.1's name for path().
  const std::string& getFilename() const { return path_; }

  //! Its file and its contents, as a model's checkpoint saves them (the
  //! contents may differ from the file's: setPoints, a file changed since).
  template <class F>
  void vv_state_fields(F&& f) {
    f("path", path_, 0);
    f("contents", contents_, 0);
  }

  //! Reads the file again; on an error the object keeps its contents and
  //! the error (vv::error, with the file and the line) is thrown. Without a
  //! file, nothing happens.
  void reread() override {
    if (!path_.empty()) contents_ = Derived::read(path_);
  }

 protected:
  //! No file: the contents as Contents() makes them.
  registered_file() : registry_(running_registry()) { enrol(); }
  //! Reads the file, resolved once, here: path() names the file read, in
  //! errors and for a host that watches it.
  explicit registered_file(const std::string& file)
      : registry_(running_registry()),
        path_(file.empty() ? file : resolve_file(registry_, file)),
        contents_(path_.empty() ? Contents() : Derived::read(path_)) {
    enrol();  // only once the file was read
  }
  registered_file(const registered_file& other)
      : file_object(other), registry_(other.registry_), path_(other.path_), contents_(other.contents_) {
    enrol();
  }
  // Registered as it is; the file and the contents change.
  registered_file& operator=(const registered_file& other) {
    path_ = other.path_;
    contents_ = other.contents_;
    return *this;
  }
  ~registered_file() override {
    if (registry_) registry_->remove(this);
  }

  const Contents& contents() const { return contents_; }
  Contents& contents() { return contents_; }

 private:
  void enrol() {
    if (registry_) registry_->add(Kind, this);
  }

  file_registry* registry_;  //!< of the model this object was made in; null: none
  std::string path_;
  Contents contents_;
};

}  // namespace vv::model
