// Topology changes: InsertEdge (split one face, or join two: a handle or a
// tube) and DeleteEdge (join the faces beside an edge, open a face into a
// boundary, undo a handle), on the cube, the octahedron and an open grid.
// Counts and genus are exact; faces are face orbits (vv/faces.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <algorithms/delete_edge.hpp>
#include <algorithms/insert_edge.hpp>
#include <vv/io/from_faces.hpp>
#include <vv/vv.hpp>

#include "test_meshes.hpp"

namespace {

using vvtest::G;
using vvtest::V;
using algorithms::face_change;

const algorithms::InsertEdge<V> insert_edge;
const algorithms::DeleteEdge<V> delete_edge;

struct counts {
  std::size_t vertices, edges, faces;
  long genus;
  friend bool operator==(const counts& l, const counts& r) {
    return l.vertices == r.vertices && l.edges == r.edges && l.faces == r.faces && l.genus == r.genus;
  }
};
void PrintTo(const counts& c, std::ostream* os) {
  *os << "{V " << c.vertices << ", E " << c.edges << ", F " << c.faces << ", genus " << c.genus << "}";
}

// Connected pieces of the mesh (by neighbourhoods).
std::size_t components(const G::mesh& S) {
  std::set<unsigned> seen;
  std::size_t pieces = 0;
  for (V start : vv::each(S)) {
    if (!seen.insert(start.label()).second) continue;
    ++pieces;
    std::vector<V> todo = {start};
    while (!todo.empty()) {
      V v = todo.back();
      todo.pop_back();
      for (V u : vv::each(v))
        if (seen.insert(u.label()).second) todo.push_back(u);
    }
  }
  return pieces;
}

// V, E, F and the genus of a closed orientable surface with c pieces:
// V - E + F = 2c - 2g (summing 2 - 2g_i over the pieces).
counts count(const G::mesh& S) {
  counts c{S.size(), vv::edge_count(S), vv::face_orbits(S).size(), 0};
  long chi = static_cast<long>(c.vertices) - static_cast<long>(c.edges) + static_cast<long>(c.faces);
  c.genus = (2 * static_cast<long>(components(S)) - chi) / 2;
  return c;
}

// Every face as its corners' labels, rotated to start at the smallest.
std::set<std::vector<unsigned>> faces(const G::mesh& S) {
  std::vector<V> member;
  for (V v : vv::each(S)) member.push_back(v);
  std::set<std::vector<unsigned>> out;
  for (const auto& face : vv::face_orbits(S)) {
    std::vector<unsigned> labels;
    for (std::uint32_t i : face) labels.push_back(member[i].label());
    out.insert(vvtest::canon(labels));
  }
  return out;
}

// Everything the operations could change: each member's entries in order,
// flag and records.
std::map<unsigned, vvtest::nb_state> snapshot(const G::mesh& S) {
  std::map<unsigned, vvtest::nb_state> out;
  for (V v : vv::each(S)) out[v.label()] = vvtest::state_of(v);
  return out;
}

// Every member's rotation as a cyclic order.
std::map<unsigned, std::vector<unsigned>> rotations(const G::mesh& S) {
  std::map<unsigned, std::vector<unsigned>> out;
  for (V v : vv::each(S)) out[v.label()] = vvtest::cycle(v);
  return out;
}

// The message of the vv::error f throws, without its "file:line: " (which
// must be this file: errors name the caller's line).
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const vv::error& e) {
    std::string what = e.what();
    EXPECT_NE(what.find("topology_test.cpp:"), std::string::npos) << what;
    std::size_t at = what.find(": ");
    return at == std::string::npos ? what : what.substr(at + 2);
  }
  return "no vv::error";
}

struct fixture : ::testing::Test {
  G::context ctx;
  G::mesh S{ctx};
  std::vector<V> v;  // v[i]: the i-th point (label i + 1)

  void build(const std::vector<std::array<double, 3>>& points,
             const std::vector<std::vector<std::uint32_t>>& polygons) {
    vv::build_from_faces(S, points, polygons, "test");
    for (V x : vv::each(S)) v.push_back(x);
  }
  // The cube [-1, 1]^3: bottom face (0 3 2 1) at z = -1, top face (4 5 6 7)
  // at z = 1, each counter-clockwise seen from outside.
  void build_cube() {
    build({{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
           {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}},
          {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}});
  }
  // An open 4 x 3 grid of points, 3 x 2 quads; its boundary is one orbit of
  // 10 edges, going clockwise seen from above.
  void build_grid() {
    std::vector<std::array<double, 3>> points;
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 4; ++x) points.push_back({double(x), double(y), 0});
    std::vector<std::vector<std::uint32_t>> quads;
    for (std::uint32_t y = 0; y < 2; ++y)
      for (std::uint32_t x = 0; x < 3; ++x) {
        std::uint32_t c = 4 * y + x;
        quads.push_back({c, c + 1, c + 5, c + 4});
      }
    build(points, quads);
  }
  void expect_symmetric() { EXPECT_NO_THROW(vv::check_invariants(S, {true, false})); }
  void expect_manifold() { EXPECT_NO_THROW(vv::check_invariants(S, {true, true})); }
};

using InsertEdge = fixture;
using DeleteEdge = fixture;
using InsertAndDelete = fixture;

}  // namespace

// ---------------------------------------------------------------------------
// InsertEdge
// ---------------------------------------------------------------------------

TEST_F(InsertEdge, SplitsOneFaceInTwo) {
  build_cube();
  ASSERT_EQ(count(S), (counts{8, 12, 6, 0}));
  // The diagonal 4-6 of the top face, across the corners that leave 4
  // towards 5 and 6 towards 7.
  EXPECT_EQ(insert_edge(v[4], v[5], v[6], v[7]), face_change::split);
  EXPECT_EQ(count(S), (counts{8, 13, 7, 0}));
  expect_manifold();
  // Around 4 (labels +1): 5, 7, 0 became 5, 6, 7, 0; around 6: 7, 5, 2
  // became 7, 4, 5, 2.
  EXPECT_EQ(vvtest::cycle(v[4]), (std::vector<unsigned>{1, 6, 7, 8}));
  EXPECT_EQ(vvtest::cycle(v[6]), (std::vector<unsigned>{3, 8, 5, 6}));
  // The faces (4, 6, 7) and (6, 4, 5) took the top face's place.
  std::set<std::vector<unsigned>> f = faces(S);
  EXPECT_EQ(f.count({5, 7, 8}), 1u);
  EXPECT_EQ(f.count({5, 6, 7}), 1u);
  EXPECT_EQ(f.count({5, 6, 7, 8}), 0u);
}

TEST_F(InsertEdge, NewRecordsAreDefaultAndOthersKeepTheirs) {
  build_cube();
  vv::sym_edge(v[4], v[5]).mark = 7;
  insert_edge(v[4], v[5], v[6], v[7]);
  EXPECT_EQ(vv::edge(v[4], v[6]).mark, 0);
  EXPECT_EQ(vv::edge(v[6], v[4]).mark, 0);
  EXPECT_EQ(vv::edge(v[4], v[5]).mark, 7);
  EXPECT_EQ(vv::edge(v[5], v[4]).mark, 7);
}

TEST_F(InsertEdge, JoiningTwoFacesOfTheCubeAddsAHandle) {
  build_cube();
  // Bottom corner 0 (leaving towards 3) to top corner 6 (leaving towards 7).
  EXPECT_EQ(insert_edge(v[0], v[3], v[6], v[7]), face_change::joined);
  EXPECT_EQ(count(S), (counts{8, 13, 5, 1}));
  // The joined face runs 0, 6, 7, 4, 5, 6, 0, 3, 2, 1: through 0 and 6
  // twice, which the manifold check refuses.
  expect_symmetric();
  EXPECT_NE(error_of([&] { vv::check_invariants(S, {true, true}); }).find("face orbit visits a vertex twice"),
            std::string::npos);
  std::vector<V> member;
  for (V x : vv::each(S)) member.push_back(x);
  bool found = false;
  for (const auto& face : vv::face_orbits(S)) {
    if (face.size() != 10) continue;
    std::vector<unsigned> labels;
    for (std::uint32_t i : face) labels.push_back(member[i].label());
    // From the corner of 0 where the new edge leaves it.
    for (std::size_t i = 0; i < labels.size(); ++i)
      if (labels[i] == 1 && labels[(i + 1) % labels.size()] == 7) {
        std::rotate(labels.begin(), labels.begin() + static_cast<long>(i), labels.end());
        break;
      }
    EXPECT_EQ(labels, (std::vector<unsigned>{1, 7, 8, 5, 6, 7, 1, 4, 3, 2}));
    found = true;
  }
  EXPECT_TRUE(found);
}

TEST_F(InsertEdge, ATubeThroughTheCubeMakesATorus) {
  build_cube();
  // Top corners 6, 7, 4, 5 (in the top face's order) joined to bottom
  // corners 0, 1, 2, 3 (the bottom face runs 0, 3, 2, 1: the other way
  // round, so each pair of edges bounds a quad). The first edge joins the
  // two faces, each of the others splits the joined face.
  const int top[4] = {6, 7, 4, 5}, bottom[4] = {0, 1, 2, 3};
  const int top_next[4] = {7, 4, 5, 6}, bottom_next[4] = {3, 0, 1, 2};
  const counts after[4] = {{8, 13, 5, 1}, {8, 14, 6, 1}, {8, 15, 7, 1}, {8, 16, 8, 1}};
  for (int k = 0; k < 4; ++k) {
    face_change change = insert_edge(v[top[k]], v[top_next[k]], v[bottom[k]], v[bottom_next[k]]);
    EXPECT_EQ(change, k == 0 ? face_change::joined : face_change::split) << "edge " << k;
    EXPECT_EQ(count(S), after[k]) << "after edge " << k;
    expect_symmetric();
  }
  expect_manifold();
  // The four side faces and four walls of the tube, all quads.
  std::set<std::vector<unsigned>> f = faces(S);
  EXPECT_EQ(f, (std::set<std::vector<unsigned>>{{1, 2, 6, 5}, {2, 3, 7, 6}, {3, 4, 8, 7}, {1, 5, 8, 4},
                                                 {1, 7, 8, 2}, {2, 8, 5, 3}, {3, 5, 6, 4}, {1, 4, 6, 7}}));
  // Deleting a tube edge joins the two walls beside it; the handle stays.
  EXPECT_EQ(delete_edge(v[6], v[0]), face_change::joined);
  EXPECT_EQ(count(S), (counts{8, 15, 7, 1}));
  expect_manifold();
}

TEST_F(InsertEdge, JoiningTwoSeparateSurfacesMakesOne) {
  std::vector<V> first = vvtest::build_double_pyramid(ctx, S);
  std::vector<V> second = vvtest::build_double_pyramid(ctx, S);
  ASSERT_EQ(count(S), (counts{12, 24, 16, 0}));
  ASSERT_EQ(components(S), 2u);
  // The faces (0, 1, 5) of each: the first pyramid's corner of 0 that
  // leaves towards 1 and the second's.
  EXPECT_EQ(insert_edge(first[0], first[1], second[0], second[1]), face_change::joined);
  EXPECT_EQ(components(S), 1u);
  EXPECT_EQ(count(S), (counts{12, 25, 15, 0}));  // V - E + F = 2: one sphere
  // A second edge between the two triangles' corners closes the tube.
  // The joined face runs 0, 0', 1', 5', 0', 0, 1, 5; an edge from 1 (towards
  // 5) to 1' (towards 5') splits it.
  EXPECT_EQ(insert_edge(first[1], first[5], second[1], second[5]), face_change::split);
  EXPECT_EQ(count(S), (counts{12, 26, 16, 0}));
  expect_symmetric();
}

TEST_F(InsertEdge, RefusesALoopADoubleEdgeAndCornersOnNoFace) {
  build_cube();
  const auto before = snapshot(S);
  EXPECT_EQ(error_of([&] { insert_edge(v[4], v[5], v[4], v[7]); }),
            "InsertEdge: cannot join vertex 5 to itself");
  EXPECT_EQ(error_of([&] { insert_edge(v[4], v[7], v[5], v[6]); }),
            "InsertEdge: vertex 5 and vertex 6 are already neighbours");
  EXPECT_EQ(error_of([&] { insert_edge(V(), v[5], v[6], v[7]); }),
            "InsertEdge: an end of the new edge is the null vertex");
  // (4, 6): 6 is not a neighbour of 4, so no face leaves 4 towards it.
  EXPECT_EQ(error_of([&] { insert_edge(v[4], v[6], v[2], v[3]); }),
            "InsertEdge: the corner (vertex 5, vertex 7) is on no face: vertex 5 and vertex 7 are not "
            "mutual neighbours");
  EXPECT_EQ(error_of([&] { insert_edge(v[4], v[5], v[2], v[4]); }),
            "InsertEdge: the corner (vertex 3, vertex 5) is on no face: vertex 3 and vertex 5 are not "
            "mutual neighbours");
  EXPECT_EQ(error_of([&] { insert_edge(v[4], V(), v[2], v[3]); }),
            "InsertEdge: the corner (vertex 5, the null vertex) is on no face: an end is the null vertex");
  EXPECT_EQ(snapshot(S), before);  // nothing was changed by the refusals
  // A one-sided entry: 5 lists 4, 4 does not list 5.
  vv::erase_from(v[5], v[4]);
  const auto one_sided = snapshot(S);
  EXPECT_EQ(error_of([&] { insert_edge(v[5], v[4], v[7], v[6]); }),
            "InsertEdge: the corner (vertex 6, vertex 5) is on no face: vertex 6 and vertex 5 are not "
            "mutual neighbours");
  EXPECT_EQ(snapshot(S), one_sided);
}

// ---------------------------------------------------------------------------
// DeleteEdge
// ---------------------------------------------------------------------------

TEST_F(DeleteEdge, JoinsTheTwoTrianglesBesideAnEdge) {
  v = vvtest::build_double_pyramid(ctx, S);
  ASSERT_EQ(count(S), (counts{6, 12, 8, 0}));
  EXPECT_EQ(delete_edge(v[0], v[1]), face_change::joined);
  EXPECT_EQ(count(S), (counts{6, 11, 7, 0}));
  expect_manifold();
  EXPECT_EQ(vvtest::nb_labels(v[0]), (std::vector<unsigned>{6, 4, 5}));  // was 2 6 4 5
  EXPECT_EQ(vvtest::nb_labels(v[1]), (std::vector<unsigned>{3, 6, 5}));  // was 3 6 1 5
  // The triangles (0, 1, 5) and (1, 0, 4) became the quad (0, 4, 1, 5).
  EXPECT_EQ(faces(S).count({1, 5, 2, 6}), 1u);
}

TEST_F(DeleteEdge, OpensAFaceIntoTheBoundary) {
  build_grid();
  // 6 quads and the boundary, a hole of 10 edges: V - E + F = 12 - 17 + 7
  // = 2 with the hole counted as a face.
  vv::orbit_set o = vv::orbits(S, 4);
  ASSERT_EQ(o.faces.size(), 6u);
  ASSERT_EQ(o.long_orbits, 1u);
  ASSERT_EQ(count(S), (counts{12, 17, 7, 0}));
  // The boundary edge 1-2: the quad (1, 2, 6, 5) opens into the hole.
  EXPECT_EQ(delete_edge(v[1], v[2]), face_change::joined);
  o = vv::orbits(S, 4);
  EXPECT_EQ(o.faces.size(), 5u);
  EXPECT_EQ(o.long_orbits, 1u);
  EXPECT_EQ(count(S), (counts{12, 16, 6, 0}));
  std::size_t hole = 0;
  for (const auto& face : vv::face_orbits(S)) hole = std::max(hole, face.size());
  EXPECT_EQ(hole, 12u);  // 10 - 1 + 3
  expect_manifold();
}

TEST_F(DeleteEdge, SplitsTheFaceOnBothSidesUndoingAHandle) {
  build_cube();
  insert_edge(v[0], v[3], v[6], v[7]);
  ASSERT_EQ(count(S), (counts{8, 13, 5, 1}));
  EXPECT_EQ(delete_edge(v[6], v[0]), face_change::split);
  EXPECT_EQ(count(S), (counts{8, 12, 6, 0}));
  expect_manifold();
}

TEST_F(DeleteEdge, CutsATubeBetweenTwoSurfacesApart) {
  std::vector<V> first = vvtest::build_double_pyramid(ctx, S);
  std::vector<V> second = vvtest::build_double_pyramid(ctx, S);
  insert_edge(first[0], first[1], second[0], second[1]);
  ASSERT_EQ(components(S), 1u);
  EXPECT_EQ(delete_edge(first[0], second[0]), face_change::split);
  EXPECT_EQ(components(S), 2u);
  EXPECT_EQ(count(S), (counts{12, 24, 16, 0}));
}

TEST_F(DeleteEdge, RefusesToLeaveAVertexWithNoNeighbours) {
  v = vvtest::build_double_pyramid(ctx, S);
  // Vertex 0 (label 1) loses three of its four edges: each joins two faces.
  EXPECT_EQ(delete_edge(v[0], v[1]), face_change::joined);
  EXPECT_EQ(delete_edge(v[0], v[5]), face_change::joined);
  EXPECT_EQ(delete_edge(v[3], v[0]), face_change::joined);
  EXPECT_EQ(count(S), (counts{6, 9, 5, 0}));
  expect_symmetric();
  EXPECT_EQ(vvtest::nb_labels(v[0]), (std::vector<unsigned>{5}));
  const auto before = snapshot(S);
  EXPECT_EQ(error_of([&] { delete_edge(v[0], v[4]); }),
            "DeleteEdge: deleting the edge vertex 1-vertex 5 would leave vertex 1 with no neighbours");
  EXPECT_EQ(error_of([&] { delete_edge(v[4], v[0]); }),
            "DeleteEdge: deleting the edge vertex 5-vertex 1 would leave vertex 1 with no neighbours");
  EXPECT_EQ(snapshot(S), before);
}

TEST_F(DeleteEdge, RefusesWhatIsNotAnEdge) {
  v = vvtest::build_double_pyramid(ctx, S);
  const auto before = snapshot(S);
  EXPECT_EQ(error_of([&] { delete_edge(v[0], v[2]); }),
            "DeleteEdge: there is no edge to delete: vertex 1 and vertex 3 are not mutual neighbours");
  EXPECT_EQ(error_of([&] { delete_edge(v[0], v[0]); }),
            "DeleteEdge: there is no edge to delete: vertex 1 and vertex 1 are not mutual neighbours");
  EXPECT_EQ(error_of([&] { delete_edge(v[0], V()); }),
            "DeleteEdge: there is no edge to delete: an end is the null vertex");
  EXPECT_EQ(snapshot(S), before);
  vv::erase_from(v[0], v[1]);  // 1 still lists 0
  const auto one_sided = snapshot(S);
  EXPECT_EQ(error_of([&] { delete_edge(v[1], v[0]); }),
            "DeleteEdge: there is no edge to delete: vertex 2 and vertex 1 are not mutual neighbours");
  EXPECT_EQ(snapshot(S), one_sided);
}

// ---------------------------------------------------------------------------
// Inverses
// ---------------------------------------------------------------------------

TEST_F(InsertAndDelete, InsertingThenDeletingRestoresTheMeshExactly) {
  build_cube();
  // Records and flags are part of what must come back.
  vv::sym_edge(v[4], v[5]).mark = 3;
  vv::edge(v[6], v[7]).b = true;
  vv::flag_in(v[0], v[4]);  // an entry after the new one in 4*
  vv::flag_in(v[7], v[6]);  // the entry the new one goes after in 6*
  vv::flag_in(v[3], v[0]);
  const auto before = snapshot(S);
  const counts cube = count(S);
  insert_edge(v[4], v[5], v[6], v[7]);  // splits the top face
  delete_edge(v[4], v[6]);
  EXPECT_EQ(snapshot(S), before);
  insert_edge(v[0], v[3], v[6], v[7]);  // joins bottom and top: a handle
  delete_edge(v[0], v[6]);
  EXPECT_EQ(snapshot(S), before);
  EXPECT_EQ(count(S), cube);
  expect_manifold();
}

TEST_F(InsertAndDelete, DeletingThenInsertingRestoresEveryRotation) {
  v = vvtest::build_double_pyramid(ctx, S);
  const auto before = rotations(S);
  const counts octahedron = count(S);
  for (V a : v) {
    std::vector<V> neighbours;
    for (V b : vv::each(a)) neighbours.push_back(b);
    for (V b : neighbours) {
      V p = vv::prev_to(b, a), q = vv::prev_to(a, b);
      EXPECT_EQ(delete_edge(a, b), face_change::joined);
      EXPECT_EQ(insert_edge(a, p, b, q), face_change::split);
      EXPECT_EQ(rotations(S), before) << "edge " << a.label() << "-" << b.label();
    }
  }
  EXPECT_EQ(count(S), octahedron);
  expect_manifold();
}

TEST_F(InsertAndDelete, RefuseToEditBesideAFaceThatIsNotClosed) {
  build_cube();
  // 2 forgets 6: the face (2, 3, 7, 6), walked from (7, 6), cannot go on
  // from (6, 2).
  vv::erase_from(v[6], v[2]);
  const auto before = snapshot(S);
  EXPECT_EQ(error_of([&] { insert_edge(v[7], v[6], v[0], v[1]); }),
            "InsertEdge: the face of (vertex 8, vertex 7) is not closed: the neighbourhoods around it "
            "are not symmetric");
  // The same face as the second corner's, the first's being whole.
  EXPECT_EQ(error_of([&] { insert_edge(v[0], v[1], v[7], v[6]); }),
            "InsertEdge: the face of (vertex 8, vertex 7) is not closed: the neighbourhoods around it "
            "are not symmetric");
  // An edge of that face cannot be deleted either.
  EXPECT_EQ(error_of([&] { delete_edge(v[7], v[3]); }),
            "DeleteEdge: the face of (vertex 4, vertex 8) is not closed: the neighbourhoods around it "
            "are not symmetric");
  EXPECT_EQ(snapshot(S), before);
}
