// The polygon-file readers of vv_formats, each from the file's bytes (read
// once, within the size limit, by read_polygon_file). Every error is a
// vv::error naming the file and, in the text formats, the line.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include <vv/io/polygon_files.hpp>

namespace vv::formats {

//! Wavefront OBJ: `v` and `f` lines (corners v, v/vt, v/vt/vn or v//vn;
//! negative indices count back from the latest vertex); the other
//! statements of the format are passed over.
polygon_soup read_obj(const std::string& path, const std::string& text);

//! OFF in ASCII (OFF, COFF, NOFF, STOFF and their combinations); binary and
//! higher-dimensional OFF go to CGAL's reader.
polygon_soup read_off(const std::string& path, const std::string& bytes);

//! STL, ASCII or binary; corners at the same point become one vertex, in
//! the order they first appear.
polygon_soup read_stl(const std::string& path, const std::string& bytes);

//! PLY (ASCII or binary), through CGAL's reader after a look at its header.
polygon_soup read_ply(const std::string& path, const std::string& bytes);

//! Checks faces read by a reader that gives no lines (CGAL's) and turns them
//! into a soup: at least three corners, every index a vertex, no vertex
//! twice in a face. Messages name a face by its place in the file, from 0.
polygon_soup checked_soup(const std::string& path, std::vector<std::array<double, 3>> points,
                          const std::vector<std::vector<std::size_t>>& faces);

}  // namespace vv::formats
