// The growth models of examples/ run as users run them (vvinterpreter
// --batch --end): the summary each end block prints, checked exactly where
// events decide it (the Koch string's module counts, the primordia, the
// shell's rings) and within the biology's bounds where the dynamics decide
// it (the divergence angle); their exports, read back with vvlib, checked
// for symmetric neighbourhoods and V - E + F; and a second run's export
// compared byte for byte with the first.
#include <vv/vv.hpp>

#include <util/point.hpp>

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "example_runs.hpp"

namespace {

using namespace example_runs;

using Pt = util::Point<double>;

// The models' vertex properties, as their .vvp files declare them.
struct module_props {
  char symbol = 0;
  Pt pos;
  template <class F>
  void vv_fields(F&& f) {
    f("symbol", symbol), f("pos", pos);
  }
};

struct apex_cell {
  Pt pos;
  double r = 0, theta = 0, inhibitor = 0;
  bool primordium = false;
  int ring = 0;
  double age = 0;
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos), f("r", r), f("theta", theta), f("inhibitor", inhibitor);
    f("primordium", primordium), f("ring", ring), f("age", age);
  }
};

struct shell_cell {
  Pt pos;
  double u = 0, w = 0;
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos), f("u", u), f("w", w);
  }
};

struct reading_mark {
  int reads = 0;
  template <class F>
  void vv_fields(F&& f) {
    f("reads", reads);
  }
  friend bool operator==(const reading_mark& a, const reading_mark& b) { return a.reads == b.reads; }
  friend bool operator!=(const reading_mark& a, const reading_mark& b) { return !(a == b); }
};

using apex_graph = vv::graph<apex_cell>;
using shell_graph = vv::graph<shell_cell>;
using koch_graph = vv::graph<module_props, reading_mark>;

// Every vertex of a closed line: two neighbours, as many edges as vertices.
template <class Mesh>
void expect_closed_lines(const Mesh& S, long lines) {
  EXPECT_NO_THROW(vv::check_invariants(S, {true, false}));
  for (auto v : vv::each(S)) EXPECT_EQ(vv::valence(v), 2u);
  EXPECT_EQ(vv::edge_count(S), S.size());
  EXPECT_EQ(vv::euler_characteristic(S), 2 * lines);  // each line: an inside and an outside
}

// The value printed after `label` on its line of `out`.
double number_after(const std::string& out, const std::string& label) {
  std::size_t at = out.find(label);
  if (at == std::string::npos) return -1;
  return std::strtod(out.c_str() + at + label.size(), nullptr);
}

}  // namespace

// ---- examples/lsystem_koch.vvp ----

TEST(KochLSystem, ModuleCountsFollowTheProductionExactly) {
  // 3*4^k F, 2(4^k - 1) +, 2*4^k + 4 -; the curve grows by 4/3 a step.
  test_run::result two = batch("lsystem_koch", {"--steps", "2", "--end"});
  ASSERT_EQ(two.status, 0) << report(two);
  EXPECT_EQ(two.out, "derivations: 2\nmodules: 114 (F 48, + 30, - 36)\ncurve length: 5.333333\n");
  test_run::result four = batch("lsystem_koch", {"--steps", "4", "--end"});
  ASSERT_EQ(four.status, 0) << report(four);
  EXPECT_EQ(four.out, "derivations: 4\nmodules: 1794 (F 768, + 510, - 516)\ncurve length: 9.481481\n");
}

TEST(KochLSystem, TheStringIsOneClosedChainReadInOneDirection) {
  std::string out;
  test_run::result r = run_and_export("lsystem_koch", "3", "koch3", out);
  ASSERT_EQ(r.status, 0) << report(r);
  koch_graph::context ctx;
  koch_graph::mesh S(ctx);
  S.readXMLFile(out);
  ASSERT_EQ(S.size(), 7u * 64 + 2);
  expect_closed_lines(S, 1);
  // Each half-edge reads on where its twin reads back; every module has
  // one of each, and following the READS_ON marks visits all modules.
  std::size_t F = 0;
  for (auto v : vv::each(S)) {
    F += v->symbol == 'F';
    int on = 0;
    for (auto w : vv::each(v)) {
      int there = vv::edge(v, w).reads, back = vv::edge(w, v).reads;
      EXPECT_TRUE((there == 1 && back == 2) || (there == 2 && back == 1));
      on += there == 1;
    }
    EXPECT_EQ(on, 1);
  }
  EXPECT_EQ(F, 3u * 64);
}

TEST(KochLSystem, ASecondRunExportsTheSameBytes) {
  expect_runs_export_the_same_bytes("lsystem_koch", "4");
}

// ---- examples/phyllotaxis.vvp ----

TEST(Phyllotaxis, PrimordiaFormAtTheGoldenAngle) {
  std::string out;
  test_run::result r = run_and_export("phyllotaxis", "500", "phyllotaxis", out);
  ASSERT_EQ(r.status, 0) << report(r);
  EXPECT_NE(r.out.find("primordia: 35\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("rings in the model: 6, cells: 607\n"), std::string::npos) << r.out;
  double angle = number_after(r.out, "mean divergence angle: ");
  EXPECT_NEAR(angle, 137.5, 2.5) << r.out;
  EXPECT_NE(r.out.find(" degrees\n"), std::string::npos) << r.out;
  apex_graph::context ctx;
  apex_graph::mesh S(ctx);
  S.readXMLFile(out);
  EXPECT_EQ(S.size(), 607u);
  expect_closed_lines(S, 6);
  // The five grown rings each carry their primordium; the active ring none.
  std::size_t primordia = 0;
  for (auto v : vv::each(S)) primordia += v->primordium;
  EXPECT_EQ(primordia, 5u);
}

TEST(Phyllotaxis, TheAngleStaysGoldenInALongRun) {
  // By 1500 steps the divergence alternates between 135.7 and 142.9
  // degrees; the mean over 103 angles stays within the bounds.
  test_run::result r = batch("phyllotaxis", {"--steps", "1500", "--end"});
  ASSERT_EQ(r.status, 0) << report(r);
  EXPECT_NE(r.out.find("primordia: 104\n"), std::string::npos) << r.out;
  EXPECT_NEAR(number_after(r.out, "mean divergence angle: "), 137.5, 2.5) << r.out;
}

TEST(Phyllotaxis, PlotsOneDivergenceAnglePerPrimordium) {
  const std::string csv = test_files::scratch_dir() + "phyllotaxis.csv";
  test_run::result r = batch("phyllotaxis", {"--steps", "500", "--plots", csv});
  ASSERT_EQ(r.status, 0) << report(r);
  std::istringstream lines(test_files::slurp(csv));
  std::string line;
  std::getline(lines, line);
  ASSERT_EQ(line, "step,divergence angle,primordia");
  std::size_t angles = 0;
  while (std::getline(lines, line)) {
    std::size_t comma = line.find(',');
    std::string value = line.substr(comma + 1, line.find(',', comma + 1) - comma - 1);
    if (value.empty()) continue;
    double d = std::strtod(value.c_str(), nullptr);
    EXPECT_GT(d, 0);
    EXPECT_LE(d, 180);
    ++angles;
  }
  EXPECT_EQ(angles, 34u);  // every primordium after the first
}

TEST(Phyllotaxis, ASecondRunExportsTheSameBytes) {
  expect_runs_export_the_same_bytes("phyllotaxis", "300");
}

// ---- examples/sea_shell.vvp ----

TEST(SeaShell, LaysARingEveryStepAndRefinesTheMargin) {
  std::string out;
  test_run::result r = run_and_export("sea_shell", "90", "shell", out);
  ASSERT_EQ(r.status, 0) << report(r);
  // Every cell laid behind the margin (all but the apex and the margin's
  // 64) reaches the margin through its flags, from the first ring in 90.
  EXPECT_EQ(r.out,
            "rings: 90, margin cells: 64, cells: 2017\n"
            "flag paths to the margin: 1952, longest 90\n"
            "whorls: 3.000, aperture width: 9.228856\n");
  shell_graph::context ctx;
  shell_graph::mesh S(ctx);
  S.readXMLFile(out);
  EXPECT_NO_THROW(vv::check_invariants(S, {true, true}));  // symmetric, manifold faces
  EXPECT_EQ(S.size(), 2017u);
  EXPECT_EQ(vv::edge_count(S), 4032u);
  // A disc: its cells' faces and the aperture's one long orbit.
  EXPECT_EQ(vv::face_orbits(S, 4).size(), 2016u);
  EXPECT_EQ(vv::euler_characteristic(S), 2);
}

TEST(SeaShell, WithoutRefinementEveryRingHasTheFirstMarginsCells) {
  test_run::result r = batch("sea_shell", {"--steps", "60", "--end", "--set", "chaikin_every=1000"});
  ASSERT_EQ(r.status, 0) << report(r);
  // The apex, 60 rings of 8 and the margin's 8.
  EXPECT_EQ(r.out,
            "rings: 60, margin cells: 8, cells: 489\n"
            "flag paths to the margin: 480, longest 60\n"
            "whorls: 2.000, aperture width: 4.399790\n");
}

TEST(SeaShell, ASecondRunExportsTheSameBytes) {
  expect_runs_export_the_same_bytes("sea_shell", "90");
}
