// Polygon files (.obj .off .ply .stl) as points and index lists. The format
// code is compiled once, into the library vv_formats (vvlib/formats/),
// which programs and models link: the CGAL headers that do the work take
// seconds to compile, so no model includes them.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "../error.hpp"
#include "files.hpp"

#define VV_FORMATS_API __attribute__((visibility("default")))

namespace vv {

struct polygon_soup {
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::uint32_t>> faces;  //!< indices into points
};

//! Reads a polygon file (.obj .off .ply .stl by extension); vv::error
//! naming the file when it is missing, unreadable or malformed (with the
//! line and the reason in OBJ, OFF, ASCII STL and the PLY header), and
//! when it is no regular file or is over io::mesh_file_limit.
VV_FORMATS_API polygon_soup read_polygon_file(const std::string& path);

//! Writes a polygon file (.obj .off .ply .stl by extension), atomically:
//! points and faces as indices into them (STL gets fans of triangles), and
//! polylines (OBJ `l` lines; the other formats refuse them). Every double
//! is written so that it reads back exactly.
VV_FORMATS_API void write_polygon_file(const std::string& path,
                                       const std::vector<std::array<double, 3>>& points,
                                       std::vector<std::vector<std::size_t>> faces,
                                       const std::vector<std::vector<std::size_t>>& lines = {});

namespace detail {

inline bool is_polygon_format(const std::string& ext) {
  return ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".stl";
}
[[noreturn]] inline void unknown_format(const std::string& path) {
  throw error(path, 0, "unknown mesh format \"" + io::extension_of(path) +
                           "\" (known: .vvm .obj .off .ply .stl)");
}

}  // namespace detail

}  // namespace vv
