// read_mesh / write_mesh: one entry point per direction, choosing the
// format by the file's extension (.vvm, .obj, .off, .ply, .stl).
//
// Polygon formats go through CGAL's polygon-soup readers and writers, which
// keep doubles exact (OpenMesh 9's writers and readers round coordinates to
// float). A written polygon file lists the members in iteration order and
// the face orbits (vv/orbits.hpp) as faces; orbits longer than max_face are
// holes and left out. A curve (vv/polylines.hpp) is written as polylines,
// which of the polygon formats only OBJ can hold (`l` lines).
#pragma once

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>

#include <array>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "../orbits.hpp"
#include "../polylines.hpp"
#include "files.hpp"
#include "from_faces.hpp"
#include "positions.hpp"
#include "vvm.hpp"

namespace vv {

struct export_options {
  //! Face orbits longer than this are holes or boundaries: not written.
  std::size_t max_face = std::numeric_limits<std::size_t>::max();
};

namespace detail {

using soup_point = CGAL::Simple_cartesian<double>::Point_3;

inline bool is_polygon_format(const std::string& ext) {
  return ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".stl";
}
[[noreturn]] inline void unknown_format(const std::string& path) {
  throw error(path, 0, "unknown mesh format \"" + io::extension_of(path) +
                           "\" (known: .vvm .obj .off .ply .stl)");
}

// OBJ with polylines (CGAL's writers know faces only): `v` lines, then
// faces, then `l` lines; indices count from 1.
inline std::string obj_text(const std::vector<std::array<double, 3>>& points,
                            const std::vector<std::vector<std::size_t>>& faces,
                            const std::vector<std::vector<std::size_t>>& lines) {
  std::string out;
  char number[32];
  for (const auto& p : points) {
    out += "v";
    for (double c : p) {
      std::snprintf(number, sizeof number, " %.17g", c);
      out += number;
    }
    out += "\n";
  }
  auto indices = [&](char kind, const std::vector<std::size_t>& list) {
    out += kind;
    for (std::size_t i : list) out += " " + std::to_string(i + 1);
    out += "\n";
  };
  for (const auto& f : faces) indices('f', f);
  for (const auto& l : lines) indices('l', l);
  return out;
}

// A polygon has a fan of triangles from its first corner (for STL).
inline std::vector<std::vector<std::size_t>> fan_triangles(
    const std::vector<std::vector<std::size_t>>& polygons) {
  std::vector<std::vector<std::size_t>> out;
  for (const auto& p : polygons)
    for (std::size_t i = 1; i + 1 < p.size(); ++i) out.push_back({p[0], p[i], p[i + 1]});
  return out;
}

}  // namespace detail

//! Replaces m by the mesh in a file; m is unchanged on failure.
template <class Tr>
void read_mesh(mesh<Tr>& m, const std::string& path) {
  std::string ext = io::extension_of(path);
  if (ext == ".vvm") return read_vvm(m, path);
  if (!detail::is_polygon_format(ext)) detail::unknown_format(path);
  io::read_text_file(path);  // a clear message for a missing or unreadable file
  std::vector<detail::soup_point> soup_points;
  std::vector<std::vector<std::size_t>> soup_faces;
  if (!CGAL::IO::read_polygon_soup(path, soup_points, soup_faces))
    throw error(path, 0, "not a readable " + ext.substr(1) + " file");
  std::vector<std::array<double, 3>> points;
  points.reserve(soup_points.size());
  for (const auto& p : soup_points) points.push_back({p.x(), p.y(), p.z()});
  std::vector<std::vector<std::uint32_t>> faces;
  faces.reserve(soup_faces.size());
  for (const auto& f : soup_faces) faces.emplace_back(f.begin(), f.end());
  build_from_faces(m, points, faces, path);
}

//! Writes a polygon file (.obj .off .ply .stl by extension), atomically:
//! points and faces as indices into them (STL gets fans of triangles), and
//! polylines (OBJ only: other formats refuse them).
inline void write_polygon_file(const std::string& path,
                               const std::vector<std::array<double, 3>>& points,
                               std::vector<std::vector<std::size_t>> faces,
                               const std::vector<std::vector<std::size_t>>& lines = {}) {
  std::string ext = io::extension_of(path);
  if (!detail::is_polygon_format(ext)) detail::unknown_format(path);
  if (!lines.empty()) {
    if (ext != ".obj")
      throw error(path, 0, "a curve (no vertex has more than two neighbours) is written as lines, which " +
                               ext.substr(1) + " files cannot hold; write .obj (l lines) or .vvm");
    io::write_file_atomically(path, detail::obj_text(points, faces, lines));
    return;
  }
  std::vector<detail::soup_point> soup;
  soup.reserve(points.size());
  for (const auto& p : points) soup.emplace_back(p[0], p[1], p[2]);
  if (ext == ".stl") faces = detail::fan_triangles(faces);  // STL holds triangles only
  // Written to memory first: CGAL's file writers never report a failed
  // flush or close, so a full disk would leave a truncated file. The bytes
  // then go through vvlib's checked, atomic writer.
  std::ostringstream os(std::ios::binary);
  bool binary = ext == ".ply" || ext == ".stl";
  CGAL::IO::set_mode(os, binary ? CGAL::IO::BINARY : CGAL::IO::ASCII);
  // 17 significant digits: every double reads back exactly.
  auto np = CGAL::parameters::stream_precision(17);
  bool ok = ext == ".obj"   ? CGAL::IO::write_OBJ(os, soup, faces, np)
            : ext == ".off" ? CGAL::IO::write_OFF(os, soup, faces, np)
            : ext == ".ply" ? CGAL::IO::write_PLY(os, soup, faces, np)
                            : CGAL::IO::write_STL(os, soup, faces, np);
  if (!ok) throw error(path, 0, "cannot write file: the " + ext.substr(1) + " writer failed");
  io::write_file_atomically(path, os.str());
}

//! Writes m to a file, atomically; nothing is written on failure.
template <class Tr>
void write_mesh(const mesh<Tr>& m, const std::string& path, const export_options& opt = {}) {
  std::string ext = io::extension_of(path);
  if (ext == ".vvm") return write_vvm(m, path);
  if (!detail::is_polygon_format(ext)) detail::unknown_format(path);
  if constexpr (!detail::has_pos<typename Tr::vertex_props>::value)
    throw error(path, 0, "the vertices have no 'pos' property, so a " + ext.substr(1) +
                             " file cannot hold them (.vvm can)");
  std::vector<std::array<double, 3>> points;
  points.reserve(m.size());
  for (std::uint32_t id : m.slots()) {
    if (!id) continue;
    std::array<double, 3> p{0, 0, 0};
    if constexpr (detail::has_pos<typename Tr::vertex_props>::value)
      p = detail::xyz_of(m.ctx()->props(id).pos);
    points.push_back(p);
  }
  std::vector<std::vector<std::size_t>> faces;
  if (is_curve(m)) return write_polygon_file(path, points, std::move(faces), polylines(m));
  for (const auto& orbit : orbits(m, opt.max_face).faces)
    if (orbit.size() >= 3) faces.emplace_back(orbit.begin(), orbit.end());
  write_polygon_file(path, points, std::move(faces));
}

}  // namespace vv
