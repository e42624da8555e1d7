// The polygon formats, through CGAL's polygon-soup readers and writers,
// which keep doubles exact (OpenMesh 9's round coordinates to float).
// Compiled once into vv_formats (see vv/io/polygon_files.hpp).
#include <vv/io/polygon_files.hpp>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Simple_cartesian.h>

#include <cstdio>
#include <sstream>

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
  io::read_text_file(path);  // a clear message for a missing or unreadable file
  std::vector<soup_point> soup_points;
  std::vector<std::vector<std::size_t>> soup_faces;
  if (!CGAL::IO::read_polygon_soup(path, soup_points, soup_faces))
    throw error(path, 0, "not a readable " + ext.substr(1) + " file");
  polygon_soup soup;
  soup.points.reserve(soup_points.size());
  for (const auto& p : soup_points) soup.points.push_back({p.x(), p.y(), p.z()});
  soup.faces.reserve(soup_faces.size());
  for (const auto& f : soup_faces) soup.faces.emplace_back(f.begin(), f.end());
  return soup;
}

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
