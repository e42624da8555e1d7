// The independent implementations the examples are checked against:
// OpenMesh's uniform subdividers and CGAL's Subdivision_method_3, both on
// double-precision points, converting to and from oracle::polygons.
//
//   oracle::polygons p = peers::openmesh<peers::om_tri_mesh, OpenMesh::Subdivider::Uniform::LoopT>(in, 2);
//   oracle::polygons q = peers::cgal(in, 2, [](auto& m, auto params) {
//     CGAL::Subdivision_method_3::Loop_subdivision(m, params); });
#pragma once

// MeshIO first: OpenMesh's subdivider headers use size_t without declaring it.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include <cstdint>
#include <vector>

#include "oracle.hpp"

namespace peers {

struct om_traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using om_tri_mesh = OpenMesh::TriMesh_ArrayKernelT<om_traits>;   // LoopT, Sqrt3T, ModifiedButterFlyT
using om_poly_mesh = OpenMesh::PolyMesh_ArrayKernelT<om_traits>;  // CatmullClarkT

//! `steps` steps of an OpenMesh uniform subdivider on a copy of `in`.
template <class Mesh, template <class, class> class Subdivider>
oracle::polygons openmesh(const oracle::polygons& in, unsigned steps) {
  Mesh m;
  std::vector<typename Mesh::VertexHandle> v;
  for (const auto& p : in.points) v.push_back(m.add_vertex({p[0], p[1], p[2]}));
  for (const auto& f : in.faces) {
    std::vector<typename Mesh::VertexHandle> face;
    for (std::uint32_t i : f) face.push_back(v[i]);
    EXPECT_TRUE(m.add_face(face).is_valid()) << "OpenMesh rejected a face of the input";
  }
  Subdivider<Mesh, double> subdivide;
  subdivide.attach(m);
  subdivide(steps);
  subdivide.detach();
  oracle::polygons out;
  for (auto h : m.vertices()) out.points.push_back({m.point(h)[0], m.point(h)[1], m.point(h)[2]});
  for (auto f : m.faces()) {
    std::vector<std::uint32_t> face;
    for (auto h : m.fv_range(f)) face.push_back(static_cast<std::uint32_t>(h.idx()));
    out.faces.push_back(face);
  }
  return out;
}

using cgal_mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;

inline cgal_mesh to_cgal(const oracle::polygons& in) {
  cgal_mesh m;
  std::vector<cgal_mesh::Vertex_index> v;
  for (const auto& p : in.points) v.push_back(m.add_vertex({p[0], p[1], p[2]}));
  for (const auto& f : in.faces) {
    std::vector<cgal_mesh::Vertex_index> face;
    for (std::uint32_t i : f) face.push_back(v[i]);
    EXPECT_NE(m.add_face(face), cgal_mesh::null_face()) << "CGAL rejected a face of the input";
  }
  return m;
}

inline oracle::polygons from_cgal(const cgal_mesh& m) {
  // Subdivision leaves removed elements behind: number the live vertices.
  oracle::polygons out;
  std::vector<std::uint32_t> index(m.number_of_vertices() + m.number_of_removed_vertices());
  for (auto h : m.vertices()) {
    index[h.idx()] = static_cast<std::uint32_t>(out.points.size());
    out.points.push_back({m.point(h).x(), m.point(h).y(), m.point(h).z()});
  }
  for (auto f : m.faces()) {
    std::vector<std::uint32_t> face;
    for (auto h : CGAL::vertices_around_face(m.halfedge(f), m)) face.push_back(index[h.idx()]);
    out.faces.push_back(face);
  }
  return out;
}

//! `steps` steps of a CGAL subdivision method: method(mesh, named parameters).
template <class Method>
oracle::polygons cgal(const oracle::polygons& in, unsigned steps, Method method) {
  cgal_mesh m = to_cgal(in);
  method(m, CGAL::parameters::number_of_iterations(steps));
  return from_cgal(m);
}

}  // namespace peers
