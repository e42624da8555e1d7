// OpenMesh's uniform subdividers on oracle::polygons (see peers.hpp).

// MeshIO first: OpenMesh's subdivider headers use size_t without declaring it.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/ModifiedButterFlyT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/Sqrt3T.hh>

#include <cstdint>
#include <vector>

#include "peers.hpp"

namespace peers {

namespace {

struct om_traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using om_tri_mesh = OpenMesh::TriMesh_ArrayKernelT<om_traits>;
using om_poly_mesh = OpenMesh::PolyMesh_ArrayKernelT<om_traits>;

template <class Mesh, template <class, class> class Subdivider>
oracle::polygons subdivide(const oracle::polygons& in, unsigned steps) {
  Mesh m;
  std::vector<typename Mesh::VertexHandle> v;
  for (const auto& p : in.points) v.push_back(m.add_vertex({p[0], p[1], p[2]}));
  for (const auto& f : in.faces) {
    std::vector<typename Mesh::VertexHandle> face;
    for (std::uint32_t i : f) face.push_back(v[i]);
    EXPECT_TRUE(m.add_face(face).is_valid()) << "OpenMesh rejected a face of the input";
  }
  Subdivider<Mesh, double> subdivider;
  subdivider.attach(m);
  subdivider(steps);
  subdivider.detach();
  oracle::polygons out;
  for (auto h : m.vertices()) out.points.push_back({m.point(h)[0], m.point(h)[1], m.point(h)[2]});
  for (auto f : m.faces()) {
    std::vector<std::uint32_t> face;
    for (auto h : m.fv_range(f)) face.push_back(static_cast<std::uint32_t>(h.idx()));
    out.faces.push_back(face);
  }
  return out;
}

}  // namespace

oracle::polygons openmesh_loop(const oracle::polygons& in, unsigned steps) {
  return subdivide<om_tri_mesh, OpenMesh::Subdivider::Uniform::LoopT>(in, steps);
}

oracle::polygons openmesh_sqrt3(const oracle::polygons& in, unsigned steps) {
  return subdivide<om_tri_mesh, OpenMesh::Subdivider::Uniform::Sqrt3T>(in, steps);
}

oracle::polygons openmesh_modified_butterfly(const oracle::polygons& in, unsigned steps) {
  return subdivide<om_tri_mesh, OpenMesh::Subdivider::Uniform::ModifiedButterflyT>(in, steps);
}

oracle::polygons openmesh_catmull_clark(const oracle::polygons& in, unsigned steps) {
  return subdivide<om_poly_mesh, OpenMesh::Subdivider::Uniform::CatmullClarkT>(in, steps);
}

}  // namespace peers
