// algorithms/render.hpp against a recording stand-in for the two GL calls
// it makes (this executable does not link libGL): which primitives, which
// vertices, in which order.
#include <gtest/gtest.h>

#include <GL/gl.h>

#include <algorithm>
#include <array>
#include <set>
#include <vector>

#include <algorithms/render.hpp>
#include <algorithms/stellar.hpp>
#include <util/point.hpp>
#include <vv/io/from_faces.hpp>
#include <vv/vv.hpp>

namespace {

// What the drawers emitted: one entry per glBegin ... glEnd.
struct primitive {
  GLenum mode;
  std::vector<unsigned> labels;
};
std::vector<primitive> recorded;

struct props {
  util::Point<double> pos;
  unsigned label = 0;  // set by the test: glRender() reports it
  void glRender() const { recorded.back().labels.push_back(label); }
};
using graph = vv::graph<props>;
using vertex = graph::vertex;

}  // namespace

extern "C" void glBegin(GLenum mode) { recorded.push_back({mode, {}}); }
extern "C" void glEnd() {}

namespace {

struct Render : ::testing::Test {
  graph::context ctx;
  graph::mesh S{ctx};

  void load(const std::vector<std::array<double, 3>>& p,
            const std::vector<std::vector<std::uint32_t>>& f) {
    vv::build_from_faces(S, p, f, "test mesh");
    for (vertex v : vv::each(S)) v->label = v.label();
    recorded.clear();
  }
  void load_pyramid() {
    S.readXMLFile(VV_SOURCE_DIR "/models/pyramid.vvm");
    for (vertex v : vv::each(S)) v->label = v.label();
    recorded.clear();
  }
  void load_cube() {
    load({{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}},
         {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}});
  }
  // The face orbits as label sequences rotated to start at the lowest.
  std::set<std::vector<unsigned>> faces(std::size_t size) {
    std::vector<unsigned> labels;
    for (vertex v : vv::each(S)) labels.push_back(v.label());
    std::set<std::vector<unsigned>> out;
    for (const auto& f : vv::face_orbits(S)) {
      if (f.size() != size) continue;
      std::vector<unsigned> face;
      for (auto i : f) face.push_back(labels[i]);
      std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
      out.insert(face);
    }
    return out;
  }
  static std::set<std::vector<unsigned>> chunks(const std::vector<unsigned>& flat, std::size_t k) {
    std::set<std::vector<unsigned>> out;
    for (std::size_t i = 0; i + k <= flat.size(); i += k)
      out.insert(std::vector<unsigned>(flat.begin() + long(i), flat.begin() + long(i + k)));
    return out;
  }
};

}  // namespace

TEST_F(Render, PointsEmitsEveryVertexOnceInMeshOrder) {
  load_pyramid();
  algorithms::Draw(S, algorithms::DrawPoints());
  ASSERT_EQ(recorded.size(), 1u);
  EXPECT_EQ(recorded[0].mode, GLenum(GL_POINTS));
  EXPECT_EQ(recorded[0].labels, (std::vector<unsigned>{1, 2, 3, 4, 5, 6}));
}

TEST_F(Render, WireframeEmitsEveryEdgeOnce) {
  load_pyramid();
  algorithms::Draw(S, algorithms::DrawWireframe<vertex>());
  ASSERT_EQ(recorded.size(), 1u);
  EXPECT_EQ(recorded[0].mode, GLenum(GL_LINES));
  ASSERT_EQ(recorded[0].labels.size(), 24u);
  std::set<std::pair<unsigned, unsigned>> edges;
  for (std::size_t i = 0; i < 24; i += 2) {
    unsigned a = recorded[0].labels[i], b = recorded[0].labels[i + 1];
    EXPECT_LT(a, b);
    edges.insert({a, b});
  }
  EXPECT_EQ(edges.size(), 12u);
  EXPECT_EQ(edges.count({5, 6}), 0u);  // the apexes are not joined
}

TEST_F(Render, TrianglesAreTheCounterClockwiseFaces) {
  load_pyramid();
  algorithms::Draw(S, algorithms::DrawTriangles());
  ASSERT_EQ(recorded.size(), 1u);
  EXPECT_EQ(recorded[0].mode, GLenum(GL_TRIANGLES));
  EXPECT_EQ(recorded[0].labels.size(), 24u);
  EXPECT_EQ(chunks(recorded[0].labels, 3), faces(3));
}

TEST_F(Render, UncheckedTrianglesTrustConsecutiveNeighbours) {
  load_cube();
  algorithms::Draw(S, algorithms::DrawTriangles());
  // Around each cube corner the three consecutive pairs are no faces, yet
  // the unchecked drawer emits them (from their lowest corner).
  EXPECT_FALSE(recorded[0].labels.empty());
  recorded.clear();
  algorithms::Draw(S, algorithms::DrawTrianglesChecked());
  EXPECT_TRUE(recorded[0].labels.empty());
}

TEST_F(Render, QuadsOfACube) {
  load_cube();
  algorithms::Draw(S, algorithms::DrawQuads());
  EXPECT_EQ(recorded[0].mode, GLenum(GL_QUADS));
  EXPECT_EQ(chunks(recorded[0].labels, 4), faces(4));
  EXPECT_EQ(recorded[0].labels.size(), 24u);
  recorded.clear();
  algorithms::Draw(S, algorithms::DrawQuadsChecked());
  EXPECT_EQ(chunks(recorded[0].labels, 4), faces(4));
}

TEST_F(Render, CheckedQuadsSkipTriangles) {
  load_pyramid();
  algorithms::Draw(S, algorithms::DrawQuadsChecked());
  EXPECT_TRUE(recorded[0].labels.empty());
}

TEST_F(Render, TrianglesAndQuadsTogether) {
  load_cube();
  vertex any;
  for (vertex v : vv::each(S)) any = v;
  vertex c = algorithms::Centroid<vertex>()(any, vv::any_in(any));  // one quad -> 4 triangles
  S.add(c);
  c->label = c.label();
  recorded.clear();
  algorithms::Draw(S, algorithms::DrawTriAndQuds());  // the vv 1.1 spelling
  ASSERT_EQ(recorded.size(), 2u);
  EXPECT_EQ(recorded[0].mode, GLenum(GL_TRIANGLES));
  EXPECT_EQ(recorded[1].mode, GLenum(GL_QUADS));
  EXPECT_EQ(chunks(recorded[0].labels, 3), faces(3));
  EXPECT_EQ(chunks(recorded[1].labels, 4), faces(4));
  EXPECT_EQ(faces(3).size(), 4u);
  EXPECT_EQ(faces(4).size(), 5u);
}
