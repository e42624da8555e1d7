// examples/catmull_clark.vvp against OpenMesh's CatmullClarkT and CGAL's
// CatmullClark_subdivision; examples/doo_sabin.vvp against CGAL's
// DooSabin_subdivision; examples/corner_cutting.vvp against doo_sabin.vvp
// (tension 9/16 on quad meshes) and against its weights worked out by hand
// (on triangles, where it differs from Doo-Sabin).

#include "oracle.hpp"
#include "peers.hpp"


namespace {

using oracle::catmull_clark_counts;
using oracle::counts;
using oracle::counts_of;
using oracle::doo_sabin_counts;
using oracle::expect_counts;

using oracle::model;

using peers::openmesh_catmull_clark;
using peers::cgal_catmull_clark;
using peers::cgal_doo_sabin;

// The same points and the same faces, within 1e-9 of the mesh's size.
void expect_same_mesh(const oracle::polygons& ours, const oracle::polygons& theirs, double size) {
  double tol = 1e-9 * size;
  oracle::expect_same_points(ours.points, theirs.points, tol);
  oracle::expect_same_faces(ours, theirs, tol);
}

// Counts after one Catmull-Clark step of a quad mesh and after one
// Doo-Sabin step of any closed mesh.

bool contains(const std::vector<oracle::point>& points, const oracle::point& q) {
  for (const oracle::point& p : points)
    if (std::fabs(p[0] - q[0]) < 1e-12 && std::fabs(p[1] - q[1]) < 1e-12 && std::fabs(p[2] - q[2]) < 1e-12)
      return true;
  return false;
}

}  // namespace

TEST(CatmullClarkOracle, CubeEqualsOpenMeshAndCgal) {
  oracle::polygons base = oracle::read_polygons(model("cube.vvm"));
  oracle::polygons ours = oracle::run_example("examples/catmull_clark.vvp", "", 3);
  expect_counts(ours, {386, 768, 384});
  double size = oracle::size_of(base.points);
  expect_same_mesh(ours, openmesh_catmull_clark(base, 3), size);
  expect_same_mesh(ours, cgal_catmull_clark(base, 3), size);
}

TEST(CatmullClarkOracle, QuadTorusEqualsOpenMeshAndCgal) {
  std::string input = model("torus_quad.vvm");
  oracle::polygons base = oracle::read_polygons(input);
  oracle::polygons ours = oracle::run_example("examples/catmull_clark.vvp", input, 2);
  expect_counts(ours, catmull_clark_counts(counts_of(base), 2));
  double size = oracle::size_of(base.points);
  expect_same_mesh(ours, openmesh_catmull_clark(base, 2), size);
  expect_same_mesh(ours, cgal_catmull_clark(base, 2), size);
}

TEST(DooSabinOracle, CubeEqualsCgal) {
  oracle::polygons base = oracle::read_polygons(model("cube.vvm"));
  oracle::polygons ours = oracle::run_example("examples/doo_sabin.vvp", "", 3);
  expect_counts(ours, {384, 768, 386});
  expect_same_mesh(ours, cgal_doo_sabin(base, 3), oracle::size_of(base.points));
}

TEST(DooSabinOracle, QuadTorusEqualsCgal) {
  std::string input = model("torus_quad.vvm");
  oracle::polygons base = oracle::read_polygons(input);
  oracle::polygons ours = oracle::run_example("examples/doo_sabin.vvp", input, 2);
  expect_counts(ours, doo_sabin_counts(counts_of(base), 2));
  expect_same_mesh(ours, cgal_doo_sabin(base, 2), oracle::size_of(base.points));
}

TEST(DooSabinOracle, ScannedCowEqualsCgal) {
  // A triangle mesh: the first step uses the k-gon weights with k = 3.
  std::string input = oracle::input_vvm("cow", oracle::cgal_mesh_file("cow.off"));
  oracle::polygons base = oracle::read_polygons(input);
  oracle::polygons ours = oracle::run_example("examples/doo_sabin.vvp", input, 2);
  expect_counts(ours, doo_sabin_counts(counts_of(base), 2));
  expect_same_mesh(ours, cgal_doo_sabin(base, 2), oracle::size_of(base.points));
}

TEST(CornerCuttingOracle, NineSixteenthsIsDooSabinOnQuads) {
  // While the faces are quads: one step of the cube (the next has the
  // triangles of the cube's corners) and any number of steps of the torus
  // (all its vertices have valence 4).
  for (auto [name, steps] : {std::pair<const char*, unsigned>{"cube.vvm", 1}, {"torus_quad.vvm", 3}}) {
    SCOPED_TRACE(name);
    std::string input = model(name);
    oracle::polygons base = oracle::read_polygons(input);
    oracle::polygons ours = oracle::run_example("examples/corner_cutting.vvp", input, steps);
    expect_counts(ours, doo_sabin_counts(counts_of(base), steps));
    expect_same_mesh(ours, oracle::run_example("examples/doo_sabin.vvp", input, steps),
                     oracle::size_of(base.points));
  }
}

TEST(CornerCuttingOracle, CubeCornersAreNotDooSabinTriangles) {
  // The second step of the cube cuts the triangles at its corners, where
  // the two schemes differ: the same mesh, other points.
  std::string input = model("cube.vvm");
  oracle::polygons ours = oracle::run_example("examples/corner_cutting.vvp", input, 2);
  oracle::polygons doo_sabin = oracle::run_example("examples/doo_sabin.vvp", input, 2);
  expect_counts(ours, counts_of(doo_sabin));
  std::size_t same = 0;
  for (const oracle::point& p : ours.points) same += contains(doo_sabin.points, p);
  EXPECT_EQ(same, ours.points.size() - 24);  // all but the corners of the 8 triangles
}

TEST(CornerCuttingOracle, TrianglesUseTheGeneralisedWeights) {
  // On a triangle, with a = 9/16: the corner keeps 9/16 and each other
  // corner weighs (7/16) (3 + 2 cos(2 pi / 3)) / (3 * 3 - 5) = 7/32
  // (Doo-Sabin gives 2/3 and 1/6 instead).
  std::string input = model("pyramid.vvm");
  oracle::polygons base = oracle::read_polygons(input);
  oracle::polygons ours = oracle::run_example("examples/corner_cutting.vvp", input, 1);
  expect_counts(ours, {24, 48, 26});
  // The face (-1 0 -1), (1 0 -1), (0 1.4142 0) at its first corner:
  // 9/16 (-1, 0, -1) + 7/32 (1, 1.4142, -1) = (-11/32, 0.30935625, -25/32).
  EXPECT_TRUE(contains(ours.points, {-11.0 / 32, 7.0 / 32 * 1.4142, -25.0 / 32}))
      << "no new point at (-11/32, 0.30935625, -25/32)";
  // Doo-Sabin's point there, 2/3 (-1, 0, -1) + 1/6 (1, 1.4142, -1), is not one.
  EXPECT_FALSE(contains(ours.points, {-0.5, 1.4142 / 6, -5.0 / 6}));
  // Every corner of every face, by the same rule.
  std::vector<oracle::point> expected;
  for (const auto& f : base.faces)
    for (std::size_t i = 0; i < 3; ++i) {
      oracle::point q{0, 0, 0};
      for (std::size_t j = 0; j < 3; ++j)
        for (int c = 0; c < 3; ++c) q[c] += (i == j ? 9.0 / 16 : 7.0 / 32) * base.points[f[j]][c];
      expected.push_back(q);
    }
  oracle::expect_same_points(ours.points, expected, 1e-12);
}
