#include "runner/mesh_export.hpp"

#include <array>
#include <vector>

#include <vv/io/mesh_io.hpp>

namespace vvi {

bool is_written_by_model(const std::string& path) {
  std::string ext = vv::io::extension_of(path);
  return ext == ".vvm" || ext == ".vtp";
}

std::string export_polygons(const vv_geometry& g, const std::string& path, const std::string& what) {
  try {
    if (!vv::detail::is_polygon_format(vv::io::extension_of(path))) vv::detail::unknown_format(path);
    if (!g.positions)
      return path + ": the vertices of " + what + " have no 'pos' property, so only .vvm can hold them";
    std::vector<std::array<double, 3>> points(g.vertex_count);
    for (std::size_t i = 0; i < g.vertex_count; ++i)
      points[i] = {g.positions[3 * i], g.positions[3 * i + 1], g.positions[3 * i + 2]};
    std::vector<std::vector<std::size_t>> faces(g.face_count);
    for (std::size_t f = 0; f < g.face_count; ++f)
      faces[f].assign(g.face_vertices + g.face_offsets[f], g.face_vertices + g.face_offsets[f + 1]);
    std::vector<std::vector<std::size_t>> lines(g.line_count);
    for (std::size_t l = 0; l < g.line_count; ++l)
      lines[l].assign(g.line_vertices + g.line_offsets[l], g.line_vertices + g.line_offsets[l + 1]);
    vv::write_polygon_file(path, points, std::move(faces), lines);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace vvi
