// <algorithms/stellar_dual.hpp>: face_starts names each face of a closed
// polygon mesh once, FlipOrFail flips or throws; on the cube, the double
// pyramid and a tetrahedron, with faces worked out by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <vector>

#include <algorithms/stellar_dual.hpp>
#include <util/point.hpp>
#include <vv/io/from_faces.hpp>
#include <vv/vv.hpp>

#include "positions_graph.hpp"

namespace {

using positions_graph::graph;
using positions_graph::vertex;

struct StellarDual : ::testing::Test {
  graph::context ctx;
  graph::mesh S{ctx};
  std::vector<vertex> v;  // v[i]: the i-th vertex given

  void build(const std::vector<std::array<double, 3>>& p, const std::vector<std::vector<std::uint32_t>>& f) {
    vv::build_from_faces(S, p, f, "test");
    for (vertex x : vv::each(S)) v.push_back(x);
  }
  void build_cube() {
    build({{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}},
          {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}});
  }
  // The face on the left of a -> b, as vertex numbers (indices into v),
  // walked (a, b) -> (b, prevto a in b).
  std::vector<std::uint32_t> face(vertex a, vertex b) {
    std::vector<std::uint32_t> out;
    vertex x = a, y = b;
    do {
      out.push_back(static_cast<std::uint32_t>(std::find(v.begin(), v.end(), x) - v.begin()));
      vertex z = vv::prev_to(x, y);
      x = y;
      y = z;
    } while (x != a);
    return out;
  }
};

TEST_F(StellarDual, FaceStartsNamesEachFaceOfTheCubeOnceFromItsLowestCorner) {
  build_cube();
  auto starts = algorithms::face_starts(S);
  ASSERT_EQ(starts.size(), 6u);
  // The faces as given, each rotated to start at its lowest corner.
  std::set<std::vector<std::uint32_t>> expected = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                   {1, 2, 6, 5}, {2, 3, 7, 6}, {0, 4, 7, 3}};
  std::set<std::vector<std::uint32_t>> got;
  for (auto& [a, b] : starts) got.insert(face(a, b));
  EXPECT_EQ(got, expected);
}

TEST_F(StellarDual, FaceStartsOfTheDoublePyramidAreItsEightTriangles) {
  S.readXMLFile(VV_SOURCE_DIR "/models/pyramid.vvm");
  for (vertex x : vv::each(S)) v.push_back(x);
  auto starts = algorithms::face_starts(S);
  EXPECT_EQ(starts.size(), 8u);
  for (auto& [a, b] : starts) {
    std::vector<std::uint32_t> f = face(a, b);
    EXPECT_EQ(f.size(), 3u);
    EXPECT_EQ(f.front(), *std::min_element(f.begin(), f.end()));
  }
}

TEST_F(StellarDual, FaceStartsRefusesAFaceThatDoesNotClose) {
  build_cube();
  vv::erase_from(v[1], v[0]);  // v0 no longer sees v1: the faces there break
  EXPECT_THROW(algorithms::face_starts(S), vv::error);
}

TEST_F(StellarDual, FlipOrFailFlipsLikeFlip) {
  S.readXMLFile(VV_SOURCE_DIR "/models/pyramid.vvm");
  for (vertex x : vv::each(S)) v.push_back(x);
  // v0-v1 lies between (v0, v1, l) and (v0, r, v1); it becomes l-r.
  vertex l = vv::next_to(v[1], v[0]), r = vv::prev_to(v[1], v[0]);
  algorithms::FlipOrFail<vertex>()(v[0], v[1]);
  EXPECT_FALSE(vv::is_in(v[1], v[0]));
  EXPECT_TRUE(vv::is_in(l, r));
  EXPECT_TRUE(vv::is_in(r, l));
  vv::check_invariants(S, {true, true});
}

TEST_F(StellarDual, FlipOrFailThrowsWhereFlipCannot) {
  // In a tetrahedron the far corners of every edge are already joined.
  build({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}});
  EXPECT_THROW(algorithms::FlipOrFail<vertex>()(v[0], v[1]), vv::error);
  EXPECT_TRUE(vv::is_in(v[1], v[0]));  // nothing changed
}

}  // namespace
