// An object whose contents come from a file (a colour palette, a material
// list, a function graph): the host's "reread files" command calls reread()
// on every one the program registered (util::Function and the other VLAB
// file objects register themselves, model/registered_file.hpp) or put into
// the proxy's lists (model/proxy.hpp).
#pragma once

#include <cstddef>
#include <string>

namespace vv {

class file_object {
 public:
  virtual ~file_object() = default;
  virtual void reread() = 0;
  //! The file, for a host that watches it ("" when there is none).
  virtual const std::string& path() const {
    static const std::string none;
    return none;
  }
};

//! The kinds, in the order "reread files" takes them (the proxy's lists).
enum class file_kind : std::size_t { materials, palettes, functions, contours };
inline constexpr std::size_t file_kind_count = 4;

}  // namespace vv
