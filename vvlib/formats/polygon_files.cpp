// The polygon formats: reading by extension (the readers are in this
// folder: OBJ, OFF and STL read by vv, with lines and reasons; PLY through
// CGAL), and writing through CGAL's polygon-soup writers, which keep
// doubles exact (OpenMesh 9's round coordinates to float). Compiled once
// into vv_formats (see vv/io/polygon_files.hpp).
#include <vv/io/polygon_files.hpp>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>

#include <cstdint>
#include <cstdio>
#include <optional>
#include <sstream>

#include <vv/io/face_check.hpp>

#include "readers.hpp"

namespace vv {

namespace {

using soup_point = CGAL::Simple_cartesian<double>::Point_3;

// OBJ with polylines (CGAL's writers know faces only): `v` lines, then
// faces, then `l` lines; indices count from 1.
std::string obj_text(const std::vector<std::array<double, 3>>& points,
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
std::vector<std::vector<std::size_t>> fan_triangles(const std::vector<std::vector<std::size_t>>& polygons) {
  std::vector<std::vector<std::size_t>> out;
  for (const auto& p : polygons)
    for (std::size_t i = 1; i + 1 < p.size(); ++i) out.push_back({p[0], p[i], p[i + 1]});
  return out;
}

}  // namespace

polygon_soup read_polygon_file(const std::string& path) {
  std::string ext = io::extension_of(path);
  if (!detail::is_polygon_format(ext)) detail::unknown_format(path);
  // Read once, refusing what is no regular file or is too large; the
  // readers work on the bytes.
  std::string why;
  std::optional<std::string> bytes = io::read_file(path, &why, io::mesh_file_limit);
  if (!bytes) throw error(path, 0, "cannot open file: " + why);
  if (ext == ".obj") return formats::read_obj(path, *bytes);
  if (ext == ".off") return formats::read_off(path, *bytes);
  if (ext == ".stl") return formats::read_stl(path, *bytes);
  return formats::read_ply(path, *bytes);
}

namespace formats {

polygon_soup checked_soup(const std::string& path, std::vector<std::array<double, 3>> points,
                          const std::vector<std::vector<std::size_t>>& faces) {
  polygon_soup soup;
  soup.faces.reserve(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const std::vector<std::size_t>& face = faces[f];
    auto fail = [&](const std::string& problem) { throw error(path, 0, "face " + std::to_string(f) + ": " + problem); };
    std::string few = io::too_few_corners(face.size());
    if (!few.empty()) fail(few);
    for (std::size_t i : face)
      if (i >= points.size())  // an index read as a negative number shows as one
        fail(static_cast<std::int64_t>(i) < 0 ? std::to_string(static_cast<std::int64_t>(i)) + " is not a vertex index"
                                               : io::missing_vertex_problem(i, points.size(), 0));
    std::string twice = io::repeated_corner_problem(face, 0);
    if (!twice.empty()) fail(twice);
    soup.faces.emplace_back(face.begin(), face.end());
  }
  soup.points = std::move(points);
  return soup;
}

}  // namespace formats

void write_polygon_file(const std::string& path, const std::vector<std::array<double, 3>>& points,
                        std::vector<std::vector<std::size_t>> faces,
                        const std::vector<std::vector<std::size_t>>& lines) {
  std::string ext = io::extension_of(path);
  if (!detail::is_polygon_format(ext)) detail::unknown_format(path);
  if (!lines.empty()) {
    if (ext != ".obj")
      throw error(path, 0, "a curve (no vertex has more than two neighbours) is written as lines, which " +
                               ext.substr(1) + " files cannot hold; write .obj (l lines) or .vvm");
    io::write_file_atomically(path, obj_text(points, faces, lines));
    return;
  }
  std::vector<soup_point> soup;
  soup.reserve(points.size());
  for (const auto& p : points) soup.emplace_back(p[0], p[1], p[2]);
  if (ext == ".stl") faces = fan_triangles(faces);  // STL holds triangles only
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

}  // namespace vv
