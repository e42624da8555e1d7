#include "mesh_export.hpp"

#include <array>
#include <vector>

#include <vv/io/mesh_io.hpp>

namespace vvi {

std::string export_mesh(const vv_mesh_entry& mesh, const std::string& path, std::size_t max_face) {
  std::string ext = vv::io::extension_of(path);
  if (ext == ".vvm") {
    const char* e = mesh.write_vvm(path.c_str());
    return e ? e : "";
  }
  try {
    if (!vv::detail::is_polygon_format(ext)) vv::detail::unknown_format(path);
    vv_geometry g{};
    if (const char* e = mesh.geometry(max_face, &g)) return e;
    if (!g.positions)
      return path + ": the vertices of mesh " + mesh.name +
             " have no 'pos' property, so only .vvm can hold it";
    std::vector<std::array<double, 3>> points(g.vertex_count);
    for (std::size_t i = 0; i < g.vertex_count; ++i)
      points[i] = {g.positions[3 * i], g.positions[3 * i + 1], g.positions[3 * i + 2]};
    std::vector<std::vector<std::size_t>> faces(g.face_count);
    for (std::size_t f = 0; f < g.face_count; ++f)
      faces[f].assign(g.face_vertices + g.face_offsets[f], g.face_vertices + g.face_offsets[f + 1]);
    vv::write_polygon_file(path, points, std::move(faces));
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace vvi
