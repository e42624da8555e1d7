// The triangle-mesh schemes of examples/ against independent implementations:
//   sqrt3.vvp         = OpenMesh's Sqrt3T and CGAL's Sqrt3_subdivision (both
//                       use Kobbelt's relaxation a = (4 - 2 cos(2 pi / n)) / 9);
//   butterfly.vvp     = OpenMesh's ModifiedButterflyT on a torus whose vertices
//                       all have valence 6 (where Zorin's modified scheme is
//                       the eight-point scheme of Dyn, Levin and Gregory);
//   stellar_loop.vvp  = loop.vvp = OpenMesh's LoopT;
//   stellar_sqrt3.vvp = sqrt3.vvp.
// Positions agree within 1e-9 of the mesh size; faces (as cycles of
// positions) agree where the connectivity must.

#include "oracle.hpp"
#include "peers.hpp"


namespace {

// Positions within 1e-9 of the mesh size; the faces snap positions to a
// coarser grid (1e-6), so that rounding noise cannot split a point in two.
void expect_same_mesh(const oracle::polygons& ours, const oracle::polygons& theirs, double size,
                      bool faces = true) {
  oracle::expect_same_points(ours.points, theirs.points, 1e-9 * size);
  if (faces) oracle::expect_same_faces(ours, theirs, 1e-6 * size);
}

using oracle::model;

using peers::cgal_sqrt3;
using peers::openmesh_loop;
using peers::openmesh_modified_butterfly;
using peers::openmesh_sqrt3;

// V, E, F after `steps` steps of a 1:4 split (Loop, butterfly) or a sqrt(3)
// step of a closed triangle mesh.
std::array<std::size_t, 3> split4(std::array<std::size_t, 3> c, unsigned steps) {
  for (unsigned i = 0; i < steps; ++i) c = {c[0] + c[1], 2 * c[1] + 3 * c[2], 4 * c[2]};
  return c;
}
std::array<std::size_t, 3> sqrt3(std::array<std::size_t, 3> c, unsigned steps) {
  for (unsigned i = 0; i < steps; ++i) c = {c[0] + c[2], c[1] + 3 * c[2], 3 * c[2]};
  return c;
}
std::array<std::size_t, 3> triangle_counts_of(const oracle::polygons& p) {
  return {p.points.size(), 3 * p.faces.size() / 2, p.faces.size()};
}

}  // namespace

TEST(Sqrt3Oracle, IcosahedronEqualsOpenMeshAndCgal) {
  oracle::polygons base = oracle::read_polygons(model("icosahedron.vvm"));
  ASSERT_EQ(triangle_counts_of(base), (std::array<std::size_t, 3>{12, 30, 20}));
  oracle::polygons ours = oracle::run_example("examples/sqrt3.vvp", "", 3);
  EXPECT_EQ(ours.points.size(), 272u);
  EXPECT_EQ(ours.faces.size(), 540u);  // 20 * 3^3
  double size = oracle::size_of(base.points);
  expect_same_mesh(ours, openmesh_sqrt3(base, 3), size);
  expect_same_mesh(ours, cgal_sqrt3(base, 3), size);
}

TEST(Sqrt3Oracle, ScannedCowEqualsOpenMeshAndCgal) {
  std::string input = oracle::input_vvm("cow", oracle::cgal_mesh_file("cow.off"));
  oracle::polygons base = oracle::read_polygons(input);
  oracle::polygons ours = oracle::run_example("examples/sqrt3.vvp", input, 2);
  EXPECT_EQ(triangle_counts_of(ours), sqrt3(triangle_counts_of(base), 2));
  double size = oracle::size_of(base.points);
  expect_same_mesh(ours, openmesh_sqrt3(base, 2), size);
  expect_same_mesh(ours, cgal_sqrt3(base, 2), size);
}

TEST(ButterflyOracle, RegularTorusEqualsOpenMeshModifiedButterfly) {
  std::string input = model("torus_tri.vvm");
  oracle::polygons base = oracle::read_polygons(input);
  ASSERT_EQ(triangle_counts_of(base), (std::array<std::size_t, 3>{96, 288, 192}));
  oracle::polygons ours = oracle::run_example("examples/butterfly.vvp", input, 2);
  EXPECT_EQ(triangle_counts_of(ours), split4(triangle_counts_of(base), 2));
  expect_same_mesh(ours, openmesh_modified_butterfly(base, 2),
                   oracle::size_of(base.points));
}

TEST(ButterflyOracle, IcosahedronKeepsOldVerticesAndSplitsLikeLoop) {
  // Valence 5 is where the original and the modified butterfly differ, so
  // only the old vertices (interpolated) and the connectivity are checked.
  oracle::polygons base = oracle::read_polygons(model("icosahedron.vvm"));
  oracle::polygons ours = oracle::run_example("examples/butterfly.vvp", "", 2);
  oracle::polygons loop = oracle::run_example("examples/loop.vvp", model("icosahedron.vvm"), 2);
  EXPECT_EQ(triangle_counts_of(ours), split4(triangle_counts_of(base), 2));
  EXPECT_EQ(ours.faces, loop.faces);  // the same vertex order and the same orbits
  for (std::size_t i = 0; i < base.points.size(); ++i)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(ours.points[i][c], base.points[i][c]);
}

TEST(StellarOracle, LoopEqualsLoopExampleAndOpenMesh) {
  for (std::string input : {model("icosahedron.vvm"), model("pyramid.vvm"),
                            oracle::input_vvm("cow", oracle::cgal_mesh_file("cow.off"))}) {
    SCOPED_TRACE(input);
    oracle::polygons base = oracle::read_polygons(input);
    unsigned steps = base.points.size() > 100 ? 2 : 3;
    oracle::polygons stellar = oracle::run_example("examples/stellar_loop.vvp", input, steps);
    oracle::polygons loop = oracle::run_example("examples/loop.vvp", input, steps);
    EXPECT_EQ(triangle_counts_of(stellar), split4(triangle_counts_of(base), steps));
    double size = oracle::size_of(base.points);
    expect_same_mesh(stellar, loop, size);
    expect_same_mesh(stellar, openmesh_loop(base, steps), size);
  }
}

TEST(StellarOracle, Sqrt3EqualsSqrt3Example) {
  for (std::string input : {model("icosahedron.vvm"), model("pyramid.vvm"), model("torus_tri.vvm"),
                            oracle::input_vvm("cow", oracle::cgal_mesh_file("cow.off"))}) {
    SCOPED_TRACE(input);
    oracle::polygons base = oracle::read_polygons(input);
    unsigned steps = base.points.size() > 100 ? 2 : 4;
    oracle::polygons stellar = oracle::run_example("examples/stellar_sqrt3.vvp", input, steps);
    oracle::polygons direct = oracle::run_example("examples/sqrt3.vvp", input, steps);
    EXPECT_EQ(triangle_counts_of(stellar), sqrt3(triangle_counts_of(base), steps));
    expect_same_mesh(stellar, direct, oracle::size_of(base.points));
  }
}
