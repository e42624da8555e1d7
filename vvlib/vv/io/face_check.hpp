// What makes a list of corners no face, in words: the polygon-file readers
// say it with the face's line where the format has lines, and
// build_from_faces (from_faces.hpp) for the faces it is given.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace vv::io {

//! "a face needs at least 3 vertices; this one has 2", or "" for 3 or more.
inline std::string too_few_corners(std::size_t corners) {
  if (corners >= 3) return "";
  return "a face needs at least 3 vertices; this one has " + std::to_string(corners);
}

//! A vertex that the corners list twice, if any.
template <class Index>
std::optional<Index> repeated_corner(const std::vector<Index>& corners) {
  if (corners.size() <= 16) {  // the usual face: no allocation
    for (std::size_t i = 0; i < corners.size(); ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (corners[i] == corners[j]) return corners[i];
    return std::nullopt;
  }
  std::vector<Index> sorted(corners);
  std::sort(sorted.begin(), sorted.end());
  auto twice = std::adjacent_find(sorted.begin(), sorted.end());
  if (twice == sorted.end()) return std::nullopt;
  return *twice;
}

//! "the face lists vertex 3 twice" (indices shown from `base`, as the file
//! numbers them), or "".
template <class Index>
std::string repeated_corner_problem(const std::vector<Index>& corners, unsigned base) {
  std::optional<Index> twice = repeated_corner(corners);
  if (!twice) return "";
  return "the face lists vertex " + std::to_string(static_cast<std::uint64_t>(*twice) + base) + " twice";
}

//! "vertex 9 does not exist: the file has 4 vertices, numbered from 1"
//! (shown_index as the file writes it).
inline std::string missing_vertex_problem(const std::string& shown_index, std::size_t vertex_count, unsigned base) {
  return "vertex " + shown_index + " does not exist: the file has " + std::to_string(vertex_count) +
         (vertex_count == 1 ? " vertex" : " vertices") +
         (vertex_count == 0 ? "" : ", numbered from " + std::to_string(base));
}
inline std::string missing_vertex_problem(std::uint64_t shown_index, std::size_t vertex_count, unsigned base) {
  return missing_vertex_problem(std::to_string(shown_index), vertex_count, base);
}

}  // namespace vv::io
