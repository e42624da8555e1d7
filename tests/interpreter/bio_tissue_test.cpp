// The tissue models root_meristem.vvp and daffodil_corona.vvp run as
// users run them (vvinterpreter --batch --end): the summaries their end
// blocks print (exact counts; the root's apex valence and a tip that bends
// towards gravity and stays straight without gravitropism; the corona's
// rim much longer than its circumference), their exports read back with
// vvlib (symmetric neighbourhoods, V - E + F, no degenerate triangle),
// plots, and a second run's export compared byte for byte with the first.
#include <vv/vv.hpp>

#include <util/point.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <utility>
#include <string>
#include <vector>

#include "example_runs.hpp"

namespace {

using namespace example_runs;

using Pt = util::Point<double>;

// What root_meristem.vvp's end block prints.
struct root_summary {
  unsigned steps = 0, valence = 0;
  std::size_t vertices = 0;
  Pt tip, direction;
  double angle = 0;
  bool parsed = false;
};

root_summary parse_root(const std::string& out) {
  root_summary s;
  double x, y, z, dx, dy, dz;
  const int first = std::sscanf(out.c_str(), "growth steps %u: %zu vertices, apex valence %u", &s.steps,
                                &s.vertices, &s.valence);
  const std::size_t line = out.find("tip at");
  if (first != 3 || line == std::string::npos) return s;
  const int second = std::sscanf(out.c_str() + line,
                                 "tip at (%lf, %lf, %lf), direction (%lf, %lf, %lf), bending angle %lf degrees",
                                 &x, &y, &z, &dx, &dy, &dz, &s.angle);
  s.tip = Pt(x, y, z);
  s.direction = Pt(dx, dy, dz);
  s.parsed = second == 7;
  return s;
}

root_summary run_root(const std::string& steps, std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"--steps", steps, "--end"};
  args.insert(args.end(), extra.begin(), extra.end());
  test_run::result r = batch("root_meristem", args);
  EXPECT_EQ(r.status, 0) << report(r);
  root_summary s = parse_root(r.out);
  EXPECT_TRUE(s.parsed) << r.out;
  return s;
}

struct vertex_props {
  Pt pos, vel;
  bool anchored = false;
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos), f("vel", vel), f("anchored", anchored);
  }
};
struct edge_props {
  double rest = 0;
  template <class F>
  void vv_fields(F&& f) {
    f("rest", rest);
  }
};
using graph = vv::graph<vertex_props, edge_props>;

}  // namespace

TEST(RootMeristem, EachStepAddsARingAndTheApexKeepsValenceSix) {
  for (int steps : {0, 1, 6}) {
    SCOPED_TRACE(steps);
    const root_summary s = run_root(std::to_string(steps));
    EXPECT_EQ(s.steps, unsigned(steps));
    EXPECT_EQ(s.vertices, 25u + 6u * steps);  // 4 rings of 6, the apex
    EXPECT_EQ(s.valence, 6u);
  }
}

TEST(RootMeristem, TheRootBendsTowardsGravity) {
  const root_summary bent = run_root("8");
  const root_summary straight = run_root("8", {"--set", "gravitropism=0"});
  // Without gravitropism the root grows straight along +x.
  EXPECT_NEAR(straight.tip.y(), 0, 1e-3);
  EXPECT_NEAR(straight.tip.z(), 0, 1e-3);
  EXPECT_NEAR(straight.angle, 0, 0.01);
  EXPECT_GT(straight.tip.x(), 8);  // grown well beyond the first tube
  // With it the tip ends lower (gravity is -y) than the straight root's,
  // turned down by most of a right angle (77.85 degrees), in the xy plane.
  EXPECT_LT(bent.tip.y(), straight.tip.y() - 3);
  EXPECT_GT(bent.angle, 60);
  EXPECT_LT(bent.angle, 90);
  EXPECT_NEAR(bent.tip.z(), 0, 1e-3);
}

TEST(RootMeristem, TheTubeIsADiscOfNonDegenerateTriangles) {
  const std::string out = test_files::scratch_dir() + "root_meristem_8.vvm";
  test_run::result r = batch("root_meristem", {"--steps", "8", "--export", out});
  ASSERT_EQ(r.status, 0) << report(r);
  graph::context ctx;
  graph::mesh S{ctx};
  S.readXMLFile(out);
  EXPECT_NO_THROW(vv::check_invariants(S, {true, false}));  // symmetric
  std::vector<Pt> at;
  int anchored = 0;
  for (graph::vertex v : vv::each(S)) {
    at.push_back(v->pos);
    if (!v->anchored) continue;
    ++anchored;  // the base ring, where it started: x = 0, radius 1
    EXPECT_EQ(v->pos.x(), 0);
    EXPECT_NEAR(v->pos.y() * v->pos.y() + v->pos.z() * v->pos.z(), 1, 1e-12);
  }
  EXPECT_EQ(anchored, 6);
  // 8 steps: 6 vertices, 18 walls and 12 triangles each; the open base
  // (a hexagon) is no triangle.
  const auto triangles = vv::face_orbits(S, 3);
  EXPECT_EQ(S.size(), 73u);
  EXPECT_EQ(vv::edge_count(S), 210u);
  EXPECT_EQ(triangles.size(), 138u);
  EXPECT_EQ(long(S.size()) - long(vv::edge_count(S)) + long(triangles.size()), 1);
  for (const auto& t : triangles) {
    const double area = (at[t[1]] - at[t[0]]).cross(at[t[2]] - at[t[0]]).length() / 2;
    EXPECT_GT(area, 0.05);
  }
  // Every wall's two halves carry the same rest length.
  for (graph::vertex v : vv::each(S))
    for (graph::vertex n : vv::each(v)) EXPECT_EQ(vv::edge(v, n).rest, vv::edge(n, v).rest);
}

TEST(RootMeristem, TwoRunsExportTheSameBytes) {
  expect_runs_export_the_same_bytes("root_meristem", "5");
}

TEST(RootMeristem, PlotsTheBendingAngleEveryStep) {
  const std::string plots = test_files::scratch_dir() + "root_meristem.csv";
  test_run::result r = batch("root_meristem", {"--steps", "4", "--plots", plots});
  ASSERT_EQ(r.status, 0) << report(r);
  std::istringstream in(test_files::slurp(plots));
  std::string header;
  std::getline(in, header);
  EXPECT_NE(header.find("bending angle (degrees)"), std::string::npos) << header;
  EXPECT_NE(header.find("tip height"), std::string::npos) << header;
  int rows = 0;
  for (std::string line; std::getline(in, line);) ++rows;
  EXPECT_EQ(rows, 5);  // the start and 4 steps
}

// ---- examples/daffodil_corona.vvp ----

namespace {

struct corona_summary {
  unsigned steps = 0;
  std::size_t vertices = 0, rim = 0;
  double length = 0, circumference = 0, ratio = 0, amplitude = 0;
  bool parsed = false;
};

corona_summary run_corona(const std::string& steps, const std::string& exported = "") {
  std::vector<std::string> args = {"--steps", steps, "--end"};
  if (!exported.empty()) args.insert(args.end(), {"--export", exported});
  test_run::result r = batch("daffodil_corona", args);
  EXPECT_EQ(r.status, 0) << report(r);
  corona_summary s;
  const std::size_t line = r.out.find("rim length");
  s.parsed = std::sscanf(r.out.c_str(), "growth steps %u: %zu vertices, %zu rim vertices", &s.steps, &s.vertices,
                         &s.rim) == 3 &&
             line != std::string::npos &&
             std::sscanf(r.out.c_str() + line, "rim length %lf, circumference %lf, ratio %lf, wave amplitude %lf",
                         &s.length, &s.circumference, &s.ratio, &s.amplitude) == 4;
  EXPECT_TRUE(s.parsed) << r.out;
  return s;
}

struct corona_vertex {
  Pt pos;
  bool rim = false, anchored = false;
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos), f("rim", rim), f("anchored", anchored);
  }
};
using corona_graph = vv::graph<corona_vertex, edge_props>;

}  // namespace

TEST(DaffodilCorona, TheRimDividesAsItGrows) {
  // 12 rim vertices; every rim edge passes split_length at once: rest
  // 1.035 grows by 1.15 a step, past 1.4 in step 3; halved, past it again
  // in step 8.
  for (auto [steps, rim] : {std::pair<int, std::size_t>{0, 12}, {2, 12}, {3, 24}, {7, 24}, {8, 48}}) {
    SCOPED_TRACE(steps);
    const corona_summary s = run_corona(std::to_string(steps));
    EXPECT_EQ(s.steps, unsigned(steps));
    EXPECT_EQ(s.rim, rim);
    EXPECT_EQ(s.vertices, 48 + rim);  // 4 rings of 12 below the rim
  }
}

TEST(DaffodilCorona, TheRimBucklesIntoWaves) {
  const corona_summary start = run_corona("0");
  // A regular 12-gon (and a faint ripple): 12 sin(15 degrees) / pi.
  EXPECT_NEAR(start.ratio, 12 * std::sin(3.14159265358979 / 12) / 3.14159265358979, 0.002);
  const corona_summary grown = run_corona("12");
  // Much longer than the circle of its mean radius: folded into waves
  // that rise and fall out of the rim's plane.
  EXPECT_GT(grown.ratio, 2);
  EXPECT_GT(grown.length, 2 * grown.circumference);
  EXPECT_GT(grown.amplitude, 1);
  EXPECT_GT(grown.circumference, start.circumference);  // and it widened
}

TEST(DaffodilCorona, TheSheetIsAnAnnulusOfNonDegenerateTriangles) {
  const std::string out = test_files::scratch_dir() + "daffodil_corona_12.vvm";
  run_corona("12", out);
  corona_graph::context ctx;
  corona_graph::mesh S{ctx};
  S.readXMLFile(out);
  EXPECT_NO_THROW(vv::check_invariants(S, {true, false}));  // symmetric
  std::vector<Pt> at;
  std::size_t rim = 0, anchored = 0;
  for (corona_graph::vertex v : vv::each(S)) {
    at.push_back(v->pos);
    rim += v->rim;
    anchored += v->anchored;
  }
  EXPECT_EQ(rim, 48u);
  EXPECT_EQ(anchored, 12u);
  const auto triangles = vv::face_orbits(S, 3);
  EXPECT_EQ(S.size(), 96u);
  EXPECT_EQ(vv::edge_count(S), 228u);
  EXPECT_EQ(triangles.size(), 132u);
  EXPECT_EQ(long(S.size()) - long(vv::edge_count(S)) + long(triangles.size()), 0);  // an annulus
  for (const auto& t : triangles) {
    const double area = (at[t[1]] - at[t[0]]).cross(at[t[2]] - at[t[0]]).length() / 2;
    EXPECT_GT(area, 0.1);  // the smallest is 0.26
  }
  for (corona_graph::vertex v : vv::each(S))
    for (corona_graph::vertex n : vv::each(v)) EXPECT_EQ(vv::edge(v, n).rest, vv::edge(n, v).rest);
}

TEST(DaffodilCorona, TwoRunsExportTheSameBytes) {
  const std::string dir = test_files::scratch_dir();
  run_corona("8", dir + "dc_a.vvm");
  run_corona("8", dir + "dc_b.vvm");
  EXPECT_EQ(test_files::slurp(dir + "dc_a.vvm"), test_files::slurp(dir + "dc_b.vvm"));
  EXPECT_FALSE(test_files::slurp(dir + "dc_a.vvm").empty());
}

TEST(DaffodilCorona, PlotsTheRimRatioAndWaveAmplitudeEveryStep) {
  const std::string plots = test_files::scratch_dir() + "daffodil_corona.csv";
  test_run::result r = batch("daffodil_corona", {"--steps", "3", "--plots", plots});
  ASSERT_EQ(r.status, 0) << report(r);
  std::istringstream in(test_files::slurp(plots));
  std::string header;
  std::getline(in, header);
  EXPECT_NE(header.find("rim length / circumference"), std::string::npos) << header;
  EXPECT_NE(header.find("wave amplitude"), std::string::npos) << header;
  int rows = 0;
  for (std::string line; std::getline(in, line);) ++rows;
  EXPECT_EQ(rows, 4);  // the start and 3 steps
}
