// read_mesh / write_mesh: one entry point per direction, choosing the
// format by the file's extension (.vvm, .obj, .off, .ply, .stl), and the
// mesh members readFile / writeFile that programs call.
//
// A written polygon file lists the members in iteration order and the face
// orbits (vv/faces.hpp) as faces; orbits longer than max_face are holes
// and left out. A curve (vv/polylines.hpp) is written as polylines, which
// of the polygon formats only OBJ can hold (`l` lines). The formats
// themselves are compiled once, in vv_formats (vv/io/polygon_files.hpp):
// this header is cheap to include.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "../faces.hpp"
#include "../polylines.hpp"
#include "files.hpp"
#include "from_faces.hpp"
#include "polygon_files.hpp"
#include "positions.hpp"
#include "vvm.hpp"

namespace vv {

struct export_options {
  //! Face orbits longer than this are holes or boundaries: not written.
  std::size_t max_face = std::numeric_limits<std::size_t>::max();
};

//! Replaces m by the mesh in a file; m is unchanged on failure. What a
//! .vvm file let through without a word is added to notes when given. The
//! edits are noted at w (vvinterpreter --check names that line). A path
//! that is no regular file, or a file over io::mesh_file_limit, is refused
//! unread.
template <class Tr>
void read_mesh(mesh<Tr>& m, const std::string& path, detail::vvm_notes* notes = nullptr,
               where w = where::here()) {
  std::string ext = io::extension_of(path);
  if (ext == ".vvm") return read_vvm(m, path, notes, w);
  polygon_soup soup = read_polygon_file(path);
  build_from_faces(m, soup.points, soup.faces, path, w);
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

template <class Tr>
void mesh<Tr>::readFile(const std::string& path, where w) {
  detail::vvm_notes notes;
  at_caller(w, "readFile",
            [&] { read_mesh(*this, io::resolve(ctx_ ? ctx_->base_dir : std::string(), path), &notes, w); });
  detail::say_notes(*ctx_, notes, w);
}

template <class Tr>
void mesh<Tr>::writeFile(const std::string& path, where w) const {
  at_caller(w, "writeFile", [&] { write_mesh(*this, io::resolve(ctx_ ? ctx_->base_dir : std::string(), path)); });
}

}  // namespace vv
