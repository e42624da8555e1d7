// examples/handles.vvp run as users run it (vvinterpreter --batch): the
// counts and genus it prints after each step, the solid torus its first
// step makes (checked with vvlib on the export), and its parameters.
#include <vv/vv.hpp>

#include <util/point.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "run_interpreter.hpp"
#include "test_files.hpp"
#include "positions_graph.hpp"

namespace {

const std::string handles_vvp = VV_SOURCE_DIR "/examples/handles.vvp";

test_run::result batch(std::vector<std::string> args) {
  std::vector<std::string> all = {"--batch", "--quiet"};
  all.insert(all.end(), args.begin(), args.end());
  all.push_back(handles_vvp);
  return test_run::run(test_run::interpreter(all), 300);
}

std::string report(const test_run::result& r) { return "stdout:\n" + r.out + "stderr:\n" + r.err; }

// What the example prints for 4 steps: the cube, the torus of step 1 and
// three corner cuttings of S (V = 2E, E = 4E, F = F + E + V), each with
// the Catmull-Clark level of C (V = V + E + F, E = 2E + the sum of the
// faces' sides, F = that sum: on this all-quad torus 16/32/16 becomes
// 64/128/64, then 256/512/256, then 1024/2048/1024; the same numbers as
// corner cutting's, by two different rules).
const std::string four_steps =
    "start: V 8, E 12, F 6, genus 0\n"
    "step 1: V 16, E 32, F 16, genus 1\n"
    "step 1, Catmull-Clark: V 16, E 32, F 16, genus 1\n"
    "step 2: V 64, E 128, F 64, genus 1\n"
    "step 2, Catmull-Clark: V 64, E 128, F 64, genus 1\n"
    "step 3: V 256, E 512, F 256, genus 1\n"
    "step 3, Catmull-Clark: V 256, E 512, F 256, genus 1\n"
    "step 4: V 1024, E 2048, F 1024, genus 1\n"
    "step 4, Catmull-Clark: V 1024, E 2048, F 1024, genus 1\n";

using positions_graph::graph;

}  // namespace

TEST(HandlesExample, PrintsGenusOneAfterEveryStep) {
  test_run::result r = batch({"--steps", "4"});
  ASSERT_EQ(r.status, 0) << report(r);
  EXPECT_EQ(r.out, four_steps);
}

TEST(HandlesExample, TensionMovesVerticesButKeepsCountsAndGenus) {
  const std::string dir = test_files::scratch_dir();
  test_run::result plain = batch({"--steps", "2", "--export", dir + "handles_plain.vvm"});
  test_run::result tense = batch({"--steps", "2", "--set", "tension=0.8", "--export", dir + "handles_tense.vvm"});
  ASSERT_EQ(plain.status, 0) << report(plain);
  ASSERT_EQ(tense.status, 0) << report(tense);
  EXPECT_EQ(tense.out, plain.out);
  EXPECT_EQ(tense.out, four_steps.substr(0, four_steps.find("step 3")));
  EXPECT_NE(test_files::slurp(dir + "handles_tense.vvm"), test_files::slurp(dir + "handles_plain.vvm"));
}

TEST(HandlesExample, TensionOutsideItsRangeIsRefused) {
  test_run::result r = batch({"--steps", "1", "--set", "tension=0.95"});
  EXPECT_EQ(r.status, 1) << report(r);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "vvinterpreter: " + handles_vvp +
                       ":34: --set tension=0.95: 0.95 is outside the range [0.3, 0.9] of parameter tension\n");
}

TEST(HandlesExample, FirstStepMakesAClosedTorusOfQuads) {
  const std::string out = test_files::scratch_dir() + "handles_step1.vvm";
  test_run::result r = batch({"--steps", "1", "--export", out});
  ASSERT_EQ(r.status, 0) << report(r);
  graph::context ctx;
  graph::mesh S(ctx);
  S.readXMLFile(out);
  EXPECT_NO_THROW(vv::check_invariants(S, {true, true}));  // symmetric, every face a simple orbit
  std::vector<std::vector<std::uint32_t>> faces = vv::face_orbits(S);
  EXPECT_EQ(S.size(), 16u);
  EXPECT_EQ(vv::edge_count(S), 32u);
  ASSERT_EQ(faces.size(), 16u);
  for (const auto& face : faces) EXPECT_EQ(face.size(), 4u);
  EXPECT_EQ(vv::euler_characteristic(S), 0);  // genus 1
  // The tube's four walls stand at the window's edges, |x| or |y| = 0.5.
  std::size_t window_corners = 0;
  for (graph::vertex v : vv::each(S)) {
    const auto& p = v->pos;
    window_corners += std::abs(p.x()) == 0.5 && std::abs(p.y()) == 0.5 && std::abs(p.z()) == 1;
  }
  EXPECT_EQ(window_corners, 8u);
}

namespace {

using Pt = util::Point<double>;

// A mesh of the example, exported after `steps` steps.
struct exported {
  std::vector<Pt> positions;                        // in the mesh's order
  std::vector<std::vector<std::uint32_t>> faces;    // indices into positions
  std::vector<std::size_t> valences;
};

exported export_mesh(const std::string& mesh, unsigned steps) {
  const std::string out = test_files::scratch_dir() + "handles_" + mesh + std::to_string(steps) + ".vvm";
  test_run::result r = batch({"--steps", std::to_string(steps), "--mesh", mesh, "--export", out});
  EXPECT_EQ(r.status, 0) << report(r);
  graph::context ctx;
  graph::mesh M(ctx);
  M.readXMLFile(out);
  EXPECT_NO_THROW(vv::check_invariants(M, {true, true}));
  exported e;
  for (graph::vertex v : vv::each(M)) {
    e.positions.push_back(v->pos);
    e.valences.push_back(vv::valence(v));
  }
  e.faces = vv::face_orbits(M);
  EXPECT_EQ(vv::euler_characteristic(M), 0);  // genus 1
  return e;
}

// Catmull and Clark's rules, from the faces: face points at the corners'
// average, edge points at the average of the ends and the two face points,
// and each old vertex at (Q + 2R + (n - 3) P) / n (Q: the average of its
// face points, R: of its edges' midpoints). The result as a point set.
std::vector<Pt> catmull_clark_points(const exported& m) {
  std::vector<Pt> face_point;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>> faces_of_edge;
  std::vector<Pt> q_sum(m.positions.size()), r_sum(m.positions.size());
  std::vector<int> n(m.positions.size(), 0);
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    Pt c;
    for (std::uint32_t i : m.faces[f]) c += m.positions[i];
    face_point.push_back(c / double(m.faces[f].size()));
    for (std::size_t k = 0; k < m.faces[f].size(); ++k) {
      std::uint32_t a = m.faces[f][k], b = m.faces[f][(k + 1) % m.faces[f].size()];
      faces_of_edge[{std::min(a, b), std::max(a, b)}].push_back(f);
      q_sum[a] += face_point.back();
    }
  }
  std::vector<Pt> points = face_point;
  for (const auto& [edge, faces] : faces_of_edge) {
    EXPECT_EQ(faces.size(), 2u);
    const Pt& a = m.positions[edge.first];
    const Pt& b = m.positions[edge.second];
    points.push_back((a + b + face_point[faces[0]] + face_point[faces[1]]) / 4.0);
    for (std::uint32_t end : {edge.first, edge.second}) {
      r_sum[end] += (a + b) / 2.0;
      ++n[end];
    }
  }
  for (std::size_t i = 0; i < m.positions.size(); ++i)
    points.push_back((q_sum[i] / n[i] + 2.0 * r_sum[i] / n[i] + (n[i] - 3.0) * m.positions[i]) / double(n[i]));
  return points;
}

}  // namespace

// Step 1 puts beside S an exact copy of it, 3 along x; every later step
// is one level of Catmull-Clark on it. Every vertex of the torus has
// valence 4, where the stellar rules are Catmull and Clark's exactly, so
// their positions (worked out here from the faces) must match at 1e-12.
TEST(HandlesExample, MeshCIsTheTorusBesideSSubdividedByCatmullClark) {
  exported s1 = export_mesh("S", 1), c1 = export_mesh("C", 1);
  ASSERT_EQ(c1.positions.size(), s1.positions.size());
  for (std::size_t i = 0; i < s1.positions.size(); ++i) {
    EXPECT_EQ(c1.positions[i], s1.positions[i] + Pt(3, 0, 0));
    EXPECT_EQ(c1.valences[i], 4u);
  }
  EXPECT_EQ(c1.faces, s1.faces);

  exported c = c1;
  for (unsigned steps = 2; steps <= 3; ++steps) {
    std::vector<Pt> expected = catmull_clark_points(c);
    exported next = export_mesh("C", steps);
    ASSERT_EQ(next.positions.size(), expected.size());
    EXPECT_EQ(next.faces.size(), 4 * c.faces.size());  // each quad becomes four
    for (const auto& face : next.faces) EXPECT_EQ(face.size(), 4u);
    std::vector<bool> used(next.positions.size(), false);
    for (const Pt& p : expected) {
      std::size_t best = 0;
      double best_d = 1e300;
      for (std::size_t i = 0; i < next.positions.size(); ++i) {
        double d = (next.positions[i] - p).length();
        if (!used[i] && d < best_d) best = i, best_d = d;
      }
      EXPECT_LT(best_d, 1e-12) << "no vertex of C near " << p;
      used[best] = true;
    }
    c = next;
  }
}
