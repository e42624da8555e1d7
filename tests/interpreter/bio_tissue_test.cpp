// The tissue model root_meristem.vvp run as users run it (vvinterpreter
// --batch --end): the summary its end block prints (exact counts, the
// apex's valence, a tip that bends towards gravity and stays straight
// without gravitropism), its export read back with vvlib (symmetric
// neighbourhoods, V - E + F of a disc, no degenerate triangle), its plots
// and a second run's export compared byte for byte with the first.
#include <vv/vv.hpp>

#include <util/point.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "run_interpreter.hpp"
#include "test_files.hpp"

namespace {

using Pt = util::Point<double>;

test_run::result batch(const std::string& name, std::vector<std::string> args) {
  std::vector<std::string> all = {"--batch", "--quiet"};
  all.insert(all.end(), args.begin(), args.end());
  all.push_back(VV_SOURCE_DIR "/examples/" + name + ".vvp");
  return test_run::run(test_run::interpreter(all), 300);
}

std::string report(const test_run::result& r) { return "stdout:\n" + r.out + "stderr:\n" + r.err; }

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
  const std::string dir = test_files::scratch_dir();
  test_run::result a = batch("root_meristem", {"--steps", "5", "--export", dir + "rm_a.vvm"});
  test_run::result b = batch("root_meristem", {"--steps", "5", "--export", dir + "rm_b.vvm"});
  ASSERT_EQ(a.status, 0) << report(a);
  ASSERT_EQ(b.status, 0) << report(b);
  EXPECT_EQ(test_files::slurp(dir + "rm_a.vvm"), test_files::slurp(dir + "rm_b.vvm"));
  EXPECT_FALSE(test_files::slurp(dir + "rm_a.vvm").empty());
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
