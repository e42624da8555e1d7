// Conversion between vv meshes and OpenMesh polygon meshes, which gives vv
// the standard formats OpenMesh reads and writes (OBJ, OFF, PLY, STL).
//
// To OpenMesh: the members in iteration order become the vertices, the face
// orbits (vv/faces.hpp) the faces; orbits longer than max_face are holes.
// From OpenMesh: faces become neighbourhoods (vv/io/from_faces.hpp).
#pragma once

// MeshIO must come before the mesh kernel so readers and writers register.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "../faces.hpp"
#include "from_faces.hpp"
#include "positions.hpp"

namespace vv {

//! OpenMesh polygon mesh with double-precision points.
struct openmesh_traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using openmesh_mesh = OpenMesh::PolyMesh_ArrayKernelT<openmesh_traits>;

//! The polygon mesh of m's face orbits (positions from `pos`, or the origin
//! when the vertices have none). Faces OpenMesh cannot hold (non-manifold
//! orbits) are an error naming how many.
template <class Tr>
openmesh_mesh to_openmesh(const mesh<Tr>& m,
                          std::size_t max_face = std::numeric_limits<std::size_t>::max(),
                          const std::string& target = "mesh") {
  openmesh_mesh om;
  std::vector<openmesh_mesh::VertexHandle> handles;
  handles.reserve(m.size());
  for (std::uint32_t id : m.slots()) {
    if (!id) continue;
    std::array<double, 3> p{0, 0, 0};
    if constexpr (detail::has_pos<typename Tr::vertex_props>::value)
      p = detail::xyz_of(m.ctx()->props(id).pos);
    handles.push_back(om.add_vertex(openmesh_mesh::Point(p[0], p[1], p[2])));
  }
  std::size_t rejected = 0;
  std::vector<openmesh_mesh::VertexHandle> face;
  for (const auto& orbit : orbits(m, max_face).faces) {
    if (orbit.size() < 3) continue;  // two-vertex orbits of curves are no polygons
    face.clear();
    for (std::uint32_t i : orbit) face.push_back(handles[i]);
    OpenMesh::FaceHandle f;
    {
      // OpenMesh reports a rejected face on its error stream; we report it
      // ourselves, once, with the count.
      omerr().disable();
      f = om.add_face(face);
      omerr().enable();
    }
    if (!f.is_valid()) ++rejected;
  }
  if (rejected)
    throw error(target, 0, std::to_string(rejected) +
                               " face orbits do not form a manifold surface and cannot be "
                               "exported to a polygon format (use .vvm)");
  return om;
}

//! Replaces m by the polygon mesh om (see build_from_faces).
template <class Tr>
void from_openmesh(mesh<Tr>& m, const openmesh_mesh& om, const std::string& source = "mesh") {
  std::vector<std::array<double, 3>> points;
  points.reserve(om.n_vertices());
  for (auto v : om.vertices()) {
    const auto& p = om.point(v);
    points.push_back({p[0], p[1], p[2]});
  }
  std::vector<std::vector<std::uint32_t>> faces;
  faces.reserve(om.n_faces());
  for (auto f : om.faces()) {
    std::vector<std::uint32_t> face;
    // Following next-halfedges keeps the face's own (counter-clockwise) order.
    auto start = om.halfedge_handle(f);
    auto h = start;
    do {
      face.push_back(static_cast<std::uint32_t>(om.to_vertex_handle(h).idx()));
      h = om.next_halfedge_handle(h);
    } while (h != start);
    faces.push_back(std::move(face));
  }
  build_from_faces(m, points, faces, source);
}

}  // namespace vv
