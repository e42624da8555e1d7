// The vv 1.1 algorithms: Insert, the stellar operations (EdgeSplit, Flip,
// Centroid, Remove) and Symmetric, on the double pyramid and a cube, with
// neighbourhoods and counts worked out by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include <algorithms/insert.hpp>
#include <algorithms/stellar.hpp>
#include <algorithms/symmetric.hpp>
#include <util/point.hpp>
#include <vv/io/from_faces.hpp>
#include <vv/vv.hpp>

#include "positions_graph.hpp"

namespace {

using positions_graph::graph;
using positions_graph::vertex;

struct fixture : ::testing::Test {
  graph::context ctx;
  graph::mesh S{ctx};
  std::vector<vertex> v;  // v[i]: the i-th vertex of the file

  void load_pyramid() {
    S.readXMLFile(VV_SOURCE_DIR "/models/pyramid.vvm");
    for (vertex x : vv::each(S)) v.push_back(x);
  }
  void load_cube() {
    std::vector<std::array<double, 3>> p = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                            {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    std::vector<std::vector<std::uint32_t>> f = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                 {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    vv::build_from_faces(S, p, f, "cube");
    for (vertex x : vv::each(S)) v.push_back(x);
  }
  // The neighbourhood of x as labels, in rotation order from its first entry.
  std::vector<unsigned> nb(const vertex& x) {
    std::vector<unsigned> out;
    for (vertex u : vv::each(x)) out.push_back(u.label());
    return out;
  }
  // The same, rotated to start at the smallest label (cyclic comparison).
  std::vector<unsigned> cyclic(const vertex& x) {
    std::vector<unsigned> out = nb(x);
    std::rotate(out.begin(), std::min_element(out.begin(), out.end()), out.end());
    return out;
  }
  void expect_closed_surface(std::size_t V, std::size_t E, std::size_t F) {
    vv::check_invariants(S, {true, true});
    EXPECT_EQ(S.size(), V);
    EXPECT_EQ(vv::edge_count(S), E);
    EXPECT_EQ(vv::face_orbits(S).size(), F);
    EXPECT_EQ(vv::euler_characteristic(S), 2);
  }
};

using Insert = fixture;
using EdgeSplit = fixture;
using Flip = fixture;
using Centroid = fixture;
using Remove = fixture;
using Symmetric = fixture;

}  // namespace

TEST_F(Insert, PutsANewVertexBetweenTwoNeighbours) {
  load_pyramid();
  vertex x = algorithms::Insert<vertex>()(v[0], v[1]);
  EXPECT_EQ(x.label(), 7u);
  EXPECT_EQ(nb(x), (std::vector<unsigned>{1, 2}));
  EXPECT_EQ(nb(v[0]), (std::vector<unsigned>{7, 6, 4, 5}));  // was 2 6 4 5
  EXPECT_EQ(nb(v[1]), (std::vector<unsigned>{3, 6, 7, 5}));  // was 3 6 1 5
  S.add(x);
  vv::check_invariants(S, {true, false});
}

TEST_F(Insert, RefusesVerticesThatAreNotMutualNeighbours) {
  load_pyramid();
  EXPECT_THROW(algorithms::Insert<vertex>()(v[0], v[2]), vv::error);  // opposite corners
  vv::erase_from(v[0], v[1]);
  EXPECT_THROW(algorithms::Insert<vertex>()(v[0], v[1]), vv::error);  // asymmetric
  EXPECT_THROW(algorithms::Insert<vertex>()(v[0], vertex()), vv::error);
  EXPECT_EQ(ctx.live_vertices(), 6u);  // nothing was created
}

TEST_F(EdgeSplit, SplitsTheEdgeAndBothTriangles) {
  load_pyramid();
  // Around v0 (1 5 3 4 in file indices): l = nextto v1 = v5, r = prevto v1 = v4.
  vertex x = algorithms::EdgeSplit<vertex>()(v[0], v[1]);
  S.add(x);
  EXPECT_EQ(nb(x), (std::vector<unsigned>{v[0].label(), v[4].label(), v[1].label(), v[5].label()}));
  EXPECT_TRUE(vv::is_in(x, v[4]) && vv::is_in(x, v[5]));
  EXPECT_FALSE(vv::is_in(v[1], v[0]));
  EXPECT_EQ(x->pos, util::Point<double>(0, 0, -1));  // the midpoint
  expect_closed_surface(7, 15, 10);
}

TEST_F(Flip, ReplacesTheEdgeByTheOtherDiagonal) {
  load_pyramid();
  ASSERT_TRUE(algorithms::Flip<vertex>()(v[0], v[1]));
  EXPECT_FALSE(vv::is_in(v[1], v[0]));
  EXPECT_FALSE(vv::is_in(v[0], v[1]));
  EXPECT_TRUE(vv::is_in(v[5], v[4]));
  EXPECT_TRUE(vv::is_in(v[4], v[5]));
  EXPECT_EQ(vv::valence(v[0]), 3u);
  EXPECT_EQ(vv::valence(v[4]), 5u);
  expect_closed_surface(6, 12, 8);
}

TEST_F(Flip, FlippingTheNewEdgeRestoresTheOld) {
  load_pyramid();
  std::vector<std::vector<unsigned>> before;
  for (const vertex& x : v) before.push_back(cyclic(x));
  ASSERT_TRUE(algorithms::Flip<vertex>()(v[0], v[1]));
  ASSERT_TRUE(algorithms::Flip<vertex>()(v[4], v[5]));
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_EQ(cyclic(v[i]), before[i]) << "vertex " << i;
}

TEST_F(Flip, RefusesWhenTheOtherDiagonalExists) {
  // In a tetrahedron the two opposite corners of every edge are joined.
  std::vector<std::array<double, 3>> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  vv::build_from_faces(S, p, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}, "tetrahedron");
  for (vertex x : vv::each(S)) v.push_back(x);
  std::vector<std::vector<unsigned>> before;
  for (const vertex& x : v) before.push_back(nb(x));
  EXPECT_FALSE(algorithms::Flip<vertex>()(v[0], v[1]));
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_EQ(nb(v[i]), before[i]);
  expect_closed_surface(4, 6, 4);
}

TEST_F(Flip, RefusesAnEdgeThatIsNotMutual) {
  load_pyramid();
  EXPECT_THROW(algorithms::Flip<vertex>()(v[0], v[2]), vv::error);
}

TEST_F(Centroid, SplitsATriangleIntoThree) {
  load_pyramid();
  // The face of the oriented edge v0 -> v1 is (v0, v1, v5).
  vertex x = algorithms::Centroid<vertex>()(v[0], v[1]);
  S.add(x);
  EXPECT_EQ(nb(x), (std::vector<unsigned>{v[0].label(), v[1].label(), v[5].label()}));
  EXPECT_NEAR(x->pos.x(), 0, 1e-15);
  EXPECT_NEAR(x->pos.y(), -1.4142 / 3, 1e-15);
  EXPECT_NEAR(x->pos.z(), -2.0 / 3, 1e-15);
  expect_closed_surface(7, 15, 10);
}

TEST_F(Centroid, SplitsAQuadIntoFourTriangles) {
  load_cube();
  vertex x = algorithms::Centroid<vertex>()(v[0], v[3]);  // the bottom face 0 3 2 1
  S.add(x);
  EXPECT_EQ(vv::valence(x), 4u);
  EXPECT_EQ(x->pos, util::Point<double>(0, 0, -1));
  expect_closed_surface(9, 16, 9);  // 5 quads + 4 triangles
}

TEST_F(Remove, UndoesACentroid) {
  load_pyramid();
  std::vector<std::vector<unsigned>> before;
  for (const vertex& x : v) before.push_back(cyclic(x));
  vertex c = algorithms::Centroid<vertex>()(v[0], v[1]);
  S.add(c);
  algorithms::Remove<vertex>()(c, S);
  EXPECT_FALSE(S.contains(c));
  EXPECT_EQ(vv::valence(c), 0u);
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_EQ(cyclic(v[i]), before[i]) << "vertex " << i;
  expect_closed_surface(6, 12, 8);
}

TEST_F(Remove, LeavesAPolygonWhereTheFanWas) {
  load_pyramid();
  algorithms::Remove<vertex>()(v[4], S);  // the top apex
  vv::check_invariants(S, {true, false});
  EXPECT_EQ(S.size(), 5u);
  auto faces = vv::face_orbits(S);
  std::vector<std::size_t> sizes;
  for (const auto& f : faces) sizes.push_back(f.size());
  std::sort(sizes.begin(), sizes.end());
  EXPECT_EQ(sizes, (std::vector<std::size_t>{3, 3, 3, 3, 4}));  // the square hole is a face
}

TEST_F(Symmetric, RestoresAnErasedEntryInItsPlace) {
  load_pyramid();
  std::vector<unsigned> before = cyclic(v[1]);
  vv::erase_from(v[0], v[1]);
  EXPECT_NE(cyclic(v[1]), before);
  algorithms::Symmetric<vertex>()(S);
  EXPECT_EQ(cyclic(v[1]), before);
  expect_closed_surface(6, 12, 8);
}

TEST_F(Symmetric, AppendsWhenNoNeighbouringTriangleHelps) {
  graph::mesh M(ctx);
  vertex a = ctx.new_vertex(), b = ctx.new_vertex(), c = ctx.new_vertex(), d = ctx.new_vertex();
  vv::make_nb(a, {b, c});
  vv::make_nb(b, {d});  // b knows d but not a; c and d know nobody
  M.add(a), M.add(b), M.add(c), M.add(d);
  algorithms::Symmetric<vertex>()(M);
  vv::check_invariants(M, {true, false});
  EXPECT_EQ(nb(a), (std::vector<unsigned>{2, 3}));
  EXPECT_EQ(nb(b), (std::vector<unsigned>{4, 1}));  // a appended after d
  EXPECT_EQ(nb(c), (std::vector<unsigned>{1}));
  EXPECT_EQ(nb(d), (std::vector<unsigned>{2}));
}
