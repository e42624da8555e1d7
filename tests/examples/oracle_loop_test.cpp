// examples/loop.vvp against OpenMesh's LoopT and CGAL's Loop_subdivision,
// on the double pyramid and on a scanned mesh (CGAL's cow).
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include "oracle.hpp"

namespace {

struct om_traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using om_mesh = OpenMesh::TriMesh_ArrayKernelT<om_traits>;

std::vector<oracle::point> openmesh_loop(const oracle::polygons& in, unsigned steps) {
  om_mesh m;
  std::vector<om_mesh::VertexHandle> v;
  for (const auto& p : in.points) v.push_back(m.add_vertex({p[0], p[1], p[2]}));
  for (const auto& f : in.faces) m.add_face(v[f[0]], v[f[1]], v[f[2]]);
  OpenMesh::Subdivider::Uniform::LoopT<om_mesh, double> loop;
  loop.attach(m);
  loop(steps);
  loop.detach();
  std::vector<oracle::point> out;
  for (auto h : m.vertices()) out.push_back({m.point(h)[0], m.point(h)[1], m.point(h)[2]});
  return out;
}

using kernel = CGAL::Simple_cartesian<double>;
using cgal_mesh = CGAL::Surface_mesh<kernel::Point_3>;

std::vector<oracle::point> cgal_loop(const oracle::polygons& in, unsigned steps) {
  cgal_mesh m;
  std::vector<cgal_mesh::Vertex_index> v;
  for (const auto& p : in.points) v.push_back(m.add_vertex({p[0], p[1], p[2]}));
  for (const auto& f : in.faces) m.add_face(v[f[0]], v[f[1]], v[f[2]]);
  CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(steps));
  std::vector<oracle::point> out;
  for (auto h : m.vertices()) out.push_back({m.point(h).x(), m.point(h).y(), m.point(h).z()});
  return out;
}

}  // namespace

TEST(LoopOracle, PyramidEqualsOpenMeshAndCgal) {
  std::string input = std::string(VV_SOURCE_DIR) + "/models/pyramid.vvm";
  oracle::polygons ours = oracle::run_example("examples/loop.vvp", "", 3);
  oracle::polygons base = oracle::read_polygons(input);
  ASSERT_EQ(ours.points.size(), 258u);
  oracle::expect_same_points(ours.points, openmesh_loop(base, 3), 1e-9);
  oracle::expect_same_points(ours.points, cgal_loop(base, 3), 1e-9);
}

TEST(LoopOracle, ScannedCowEqualsOpenMeshAndCgal) {
  std::string input = oracle::input_vvm("cow", oracle::cgal_mesh_file("cow.off"));
  oracle::polygons base = oracle::read_polygons(input);
  oracle::polygons ours = oracle::run_example("examples/loop.vvp", input, 2);
  // Each step adds a vertex per edge; edges double and each triangle adds three.
  std::size_t v = base.points.size(), e = 3 * base.faces.size() / 2, f = base.faces.size();
  for (int i = 0; i < 2; ++i) v += e, e = 2 * e + 3 * f, f *= 4;
  ASSERT_EQ(ours.points.size(), v);
  EXPECT_EQ(ours.faces.size(), f);
  double tol = 1e-9 * oracle::size_of(base.points);
  oracle::expect_same_points(ours.points, openmesh_loop(base, 2), tol);
  oracle::expect_same_points(ours.points, cgal_loop(base, 2), tol);
}
