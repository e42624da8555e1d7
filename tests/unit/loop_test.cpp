// Loop subdivision written against vvlib (examples/cpp/loop_subdivision.hpp)
// checked against exact counts and against OpenMesh's LoopT as an
// independent oracle, plus determinism of the exported result.
#include <gtest/gtest.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <vv/io/from_faces.hpp>

#include "../../examples/cpp/loop_subdivision.hpp"

namespace {

using graph = loop_example::graph;
using point3 = std::array<double, 3>;

struct om_traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using om_tri_mesh = OpenMesh::TriMesh_ArrayKernelT<om_traits>;

struct polygon_mesh {
  std::vector<point3> points;
  std::vector<std::vector<std::uint32_t>> faces;
};

polygon_mesh faces_of(const graph::mesh& m) {
  polygon_mesh out;
  for (graph::vertex v : vv::each(m)) out.points.push_back({v->pos.x(), v->pos.y(), v->pos.z()});
  out.faces = vv::face_orbits(m);
  return out;
}

// OpenMesh's Loop subdivision of the same triangles, as sorted points.
std::vector<point3> openmesh_loop(const polygon_mesh& in, int steps) {
  om_tri_mesh om;
  std::vector<om_tri_mesh::VertexHandle> vh;
  for (const auto& p : in.points) vh.push_back(om.add_vertex({p[0], p[1], p[2]}));
  for (const auto& f : in.faces) om.add_face(vh[f[0]], vh[f[1]], vh[f[2]]);
  OpenMesh::Subdivider::Uniform::LoopT<om_tri_mesh, double> loop;
  loop.attach(om);
  loop(static_cast<std::size_t>(steps));
  loop.detach();
  std::vector<point3> out;
  for (auto v : om.vertices()) out.push_back({om.point(v)[0], om.point(v)[1], om.point(v)[2]});
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<point3> sorted_points(const graph::mesh& m) {
  std::vector<point3> out = faces_of(m).points;
  std::sort(out.begin(), out.end());
  return out;
}

// Points equal within tol, in any order (sorted lexicographically; a point
// that sorts differently because of rounding is matched by search).
void expect_same_points(const std::vector<point3>& a, const std::vector<point3>& b, double tol) {
  ASSERT_EQ(a.size(), b.size());
  auto close = [&](const point3& p, const point3& q) {
    return std::fabs(p[0] - q[0]) <= tol && std::fabs(p[1] - q[1]) <= tol &&
           std::fabs(p[2] - q[2]) <= tol;
  };
  std::size_t unmatched = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (close(a[i], b[i])) continue;
    bool found = std::any_of(b.begin(), b.end(), [&](const point3& q) { return close(a[i], q); });
    if (!found) ++unmatched;
  }
  EXPECT_EQ(unmatched, 0u) << "points of vvlib's result without a partner in OpenMesh's";
}

void read_pyramid(graph::mesh& S) { S.readXMLFile(VV_SOURCE_DIR "/models/pyramid.vvm"); }

// The icosahedron: every vertex has valence 5 (another Loop weight).
void make_icosahedron(graph::mesh& S) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  std::vector<point3> p = {{-1, t, 0}, {1, t, 0},  {-1, -t, 0}, {1, -t, 0},
                           {0, -1, t}, {0, 1, t},  {0, -1, -t}, {0, 1, -t},
                           {t, 0, -1}, {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::vector<std::uint32_t>> f = {
      {0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  vv::build_from_faces(S, p, f, "icosahedron");
}

}  // namespace

TEST(Loop, PyramidCountsAfterOneTwoThreeSteps) {
  graph::context ctx;
  graph::mesh S(ctx);
  read_pyramid(S);
  const std::size_t expected[3][3] = {{18, 48, 32}, {66, 192, 128}, {258, 768, 512}};
  for (const auto& vef : expected) {
    loop_example::subdivide(S);
    vv::check_invariants(S, {true, true});
    EXPECT_EQ(S.size(), vef[0]);
    EXPECT_EQ(vv::edge_count(S), vef[1]);
    EXPECT_EQ(vv::face_orbits(S).size(), vef[2]);
    EXPECT_EQ(vv::euler_characteristic(S), 2);
    for (const auto& face : vv::face_orbits(S)) EXPECT_EQ(face.size(), 3u);
  }
}

TEST(Loop, PyramidPositionsEqualOpenMeshLoopT) {
  graph::context ctx;
  graph::mesh S(ctx);
  read_pyramid(S);
  polygon_mesh input = faces_of(S);
  for (int steps = 1; steps <= 3; ++steps) {
    loop_example::subdivide(S);
    expect_same_points(sorted_points(S), openmesh_loop(input, steps), 1e-12);
  }
}

TEST(Loop, IcosahedronPositionsEqualOpenMeshLoopT) {
  graph::context ctx;
  graph::mesh S(ctx);
  make_icosahedron(S);
  polygon_mesh input = faces_of(S);
  for (int steps = 1; steps <= 2; ++steps) loop_example::subdivide(S);
  EXPECT_EQ(S.size(), 162u);  // 12 + 30 + 120
  expect_same_points(sorted_points(S), openmesh_loop(input, 2), 1e-12);
}

TEST(Loop, OldVertexWeightMatchesTheFormula) {
  // w = (3/8 + 1/4 cos(2 pi / n))^2 + 3/8; regular valence 6 gives 5/8.
  EXPECT_DOUBLE_EQ(loop_example::old_vertex_weight(6), 0.625);
  EXPECT_NEAR(loop_example::old_vertex_weight(3), 0.4375, 1e-15);  // cos = -1/2: (1/4)^2 + 3/8
  EXPECT_NEAR(loop_example::old_vertex_weight(4), 0.515625, 1e-15);  // cos = 0: (3/8)^2 + 3/8
}

TEST(Loop, SameProgramTwiceGivesByteIdenticalVvm) {
  auto run = [] {
    graph::context ctx;
    graph::mesh S(ctx);
    read_pyramid(S);
    for (int i = 0; i < 3; ++i) loop_example::subdivide(S);
    return vv::vvm_text(S);
  };
  std::string first = run();
  std::string second = run();
  EXPECT_EQ(first.size(), second.size());
  EXPECT_TRUE(first == second) << "the two exports differ";
  EXPECT_NE(first.find("<v pos="), std::string::npos);
}

TEST(Loop, ExportedVvmReadsBackToTheSameMesh) {
  graph::context ctx;
  graph::mesh S(ctx);
  read_pyramid(S);
  loop_example::subdivide(S);
  std::string text = vv::vvm_text(S);
  graph::mesh R(ctx);
  vv::parse_vvm(R, vv::io::text_file("loop1.vvm", text));
  EXPECT_EQ(R.size(), S.size());
  EXPECT_EQ(vv::face_orbits(R), vv::face_orbits(S));
  EXPECT_EQ(sorted_points(R), sorted_points(S));
  EXPECT_EQ(vv::vvm_text(R), text);
}
