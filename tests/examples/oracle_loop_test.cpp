// examples/loop.vvp against OpenMesh's LoopT and CGAL's Loop_subdivision,
// on the double pyramid and on a scanned mesh (CGAL's cow).

#include "oracle.hpp"
#include "peers.hpp"


namespace {

std::vector<oracle::point> openmesh_loop(const oracle::polygons& in, unsigned steps) {
  return peers::openmesh_loop(in, steps).points;
}

std::vector<oracle::point> cgal_loop(const oracle::polygons& in, unsigned steps) {
  return peers::cgal_loop(in, steps).points;
}

}  // namespace

TEST(LoopOracle, PyramidEqualsOpenMeshAndCgal) {
  std::string input = oracle::model("pyramid.vvm");
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
