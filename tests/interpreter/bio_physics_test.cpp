// The cell division models (korn_spalding.vvp, cell_system.vvp) run as
// users run them (vvinterpreter --batch): the cells per generation (the
// plots' CSV and the end block's line), the tissue they leave (read back
// with vvlib: symmetric neighbourhoods, V - E + F of a disc, convex cells
// of positive area; Korn-Spalding's are hexagons with opposite walls
// marked alike, the cell system's carry their turned reference vector)
// and identical exports from two runs.
#include <vv/vv.hpp>

#include <algorithms/cell_geometry.hpp>
#include <util/point.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "example_runs.hpp"

namespace {

using namespace example_runs;

using Pt = util::Point<double>;

struct vertex_props {
  Pt pos, vel;
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos);
    f("vel", vel);
  }
};
// The fields of both models' edge blocks (a file's other fields are
// ignored).
struct edge_props {
  int mark, cell, born;
  double angle;
  template <class F>
  void vv_fields(F&& f) {
    f("mark", mark);
    f("cell", cell);
    f("born", born);
    f("angle", angle);
  }
};
using graph = vv::graph<vertex_props, edge_props>;

// A tissue exported by a model: its cells are the face orbits of at most
// 6 corners (the outline is longer).
struct tissue {
  graph::context ctx;
  graph::mesh S{ctx};
  std::vector<graph::vertex> at;  // by position in the mesh
  std::vector<std::vector<std::uint32_t>> cells;

  explicit tissue(const std::string& path, std::size_t max_face = 6) {
    S.readXMLFile(path);
    for (graph::vertex v : vv::each(S)) at.push_back(v);
    cells = vv::face_orbits(S, max_face);
  }
  std::vector<Pt> corners(const std::vector<std::uint32_t>& cell) const {
    std::vector<Pt> points;
    for (std::uint32_t i : cell) points.push_back(at[i]->pos);
    return points;
  }
};

// Checks what every exported tissue must satisfy; `cells` is exact.
void expect_hexagonal_tissue(const tissue& t, std::size_t cells) {
  EXPECT_NO_THROW(vv::check_invariants(t.S, {true, false}));  // symmetric
  ASSERT_EQ(t.cells.size(), cells);
  // A disc: V - E + cells = 1 (the outline is no face).
  EXPECT_EQ(long(t.S.size()) - long(vv::edge_count(t.S)) + long(cells), 1);
  for (const auto& cell : t.cells) {
    ASSERT_EQ(cell.size(), 6u);
    const std::vector<Pt> points = t.corners(cell);
    EXPECT_GT(algorithms::polygon_area(points), 0.1);
    EXPECT_TRUE(algorithms::polygon_is_convex(points));
    // Opposite walls carry the same mark, the three marks 1, 2, 3.
    int marks[6];
    for (int i = 0; i < 6; ++i) marks[i] = vv::edge(t.at[cell[i]], t.at[cell[(i + 1) % 6]]).mark;
    for (int i = 0; i < 3; ++i) EXPECT_EQ(marks[i], marks[i + 3]);
    EXPECT_EQ(marks[0] + marks[1] + marks[2], 6);
    EXPECT_EQ(marks[0] * marks[1] * marks[2], 6);
  }
}

const std::vector<std::string> doubling = {"1", "2", "4", "8", "16", "32", "64"};

}  // namespace

TEST(KornSpalding, CellsDoubleEveryGeneration) {
  const std::string plots = test_files::scratch_dir() + "korn_spalding.csv";
  test_run::result r = batch("korn_spalding", {"--steps", "6", "--end", "--plots", plots});
  ASSERT_EQ(r.status, 0) << report(r);
  EXPECT_EQ(csv_column(plots, "cells"), doubling);
  EXPECT_EQ(r.out.rfind("generation 6: 64 cells, mean area ", 0), 0u) << r.out;
  // Cells keep their size: walls of one rest length, slightly stretched.
  for (const std::string& area : csv_column(plots, "mean cell area")) {
    EXPECT_GT(std::stod(area), 2.5);
    EXPECT_LT(std::stod(area), 3.2);
  }
}

TEST(KornSpalding, EveryCellIsAConvexHexagonWithOppositeWallsMarkedAlike) {
  const std::string dir = test_files::scratch_dir();
  for (int steps : {1, 2, 5}) {
    const std::string out = dir + "korn_spalding_" + std::to_string(steps) + ".vvm";
    test_run::result r = batch("korn_spalding", {"--steps", std::to_string(steps), "--export", out});
    ASSERT_EQ(r.status, 0) << report(r);
    SCOPED_TRACE(steps);
    expect_hexagonal_tissue(tissue(out), std::size_t(1) << steps);
  }
}

TEST(KornSpalding, TwoRunsExportTheSameBytes) {
  expect_runs_export_the_same_bytes("korn_spalding", "4");
}

// ---- examples/cell_system.vvp ----

// The cells of a cell system's tissue: the orbits inside a cell (the
// outline's half-edges have cell = 0).
std::vector<std::vector<std::uint32_t>> inner_cells(const tissue& t) {
  std::vector<std::vector<std::uint32_t>> inside;
  for (const auto& cell : t.cells)
    if (vv::edge(t.at[cell[0]], t.at[cell[1]]).cell == 1) inside.push_back(cell);
  return inside;
}

TEST(CellSystem, CellsDoubleAtEverySettleEvent) {
  const std::string plots = test_files::scratch_dir() + "cell_system.csv";
  test_run::result r = batch("cell_system", {"--steps", "6", "--end", "--plots", plots});
  ASSERT_EQ(r.status, 0) << report(r);
  EXPECT_EQ(csv_column(plots, "cells"), doubling);
  EXPECT_EQ(r.out.rfind("generation 6: 64 cells, mean area ", 0), 0u) << r.out;
}

TEST(CellSystem, EveryCellIsConvexAndTurnedByTheSameAngle) {
  const std::string dir = test_files::scratch_dir();
  for (int steps : {1, 3, 5}) {
    const std::string out = dir + "cell_system_" + std::to_string(steps) + ".vvm";
    test_run::result r = batch("cell_system", {"--steps", std::to_string(steps), "--export", out});
    ASSERT_EQ(r.status, 0) << report(r);
    SCOPED_TRACE(steps);
    const tissue t(out, 1000);
    EXPECT_NO_THROW(vv::check_invariants(t.S, {true, false}));
    const auto cells = inner_cells(t);
    ASSERT_EQ(cells.size(), std::size_t(1) << steps);
    ASSERT_EQ(t.cells.size(), cells.size() + 1);  // and the outline
    // Every division adds 2 wall vertices and 3 walls: a disc.
    const long divisions = (1L << steps) - 1;
    EXPECT_EQ(long(t.S.size()), 6 + 2 * divisions);
    EXPECT_EQ(long(vv::edge_count(t.S)), 6 + 3 * divisions);
    for (const auto& cell : cells) {
      const std::vector<Pt> points = t.corners(cell);
      EXPECT_GT(algorithms::polygon_area(points), 0.1);
      EXPECT_TRUE(algorithms::polygon_is_convex(points));
      // The first reference vector (10 degrees) turned 90 degrees per
      // division, recorded in every half-edge inside the cell.
      for (std::size_t i = 0; i < cell.size(); ++i) {
        const edge_props& e = vv::edge(t.at[cell[i]], t.at[cell[(i + 1) % cell.size()]]);
        EXPECT_EQ(e.angle, 10 + 90 * steps);
        EXPECT_EQ(e.born, steps);
      }
    }
  }
}

TEST(CellSystem, TwoRunsExportTheSameBytes) {
  expect_runs_export_the_same_bytes("cell_system", "4");
}
