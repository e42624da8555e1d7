// Cells on a radial canvas (examples/radial_cells.vvp) run as users run it
// (vvinterpreter --batch): the cell count per step (the plots' CSV) and the
// end block's summary are exact; the tissue it exports, read back with
// vvlib, is a triangulated disc of cell fans (symmetric neighbourhoods,
// V - E + T = 1, every fan triangle counter-clockwise, so no cell has zero
// area and each is star-shaped about its centre); two runs export the same
// bytes.
#include <vv/vv.hpp>

#include <algorithms/cell_geometry.hpp>
#include <util/point.hpp>

#include <gtest/gtest.h>

#include <sstream>
#include <utility>
#include <string>
#include <vector>

#include "example_runs.hpp"

namespace {

using namespace example_runs;

using Pt = util::Point<double>;

struct vertex_props {
  Pt pos;
  int centre = 0;
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos);
    f("centre", centre);
  }
};
struct edge_props {
  template <class F>
  void vv_fields(F&&) {}
};
using graph = vv::graph<vertex_props, edge_props>;

double cross(const Pt& o, const Pt& a, const Pt& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

}  // namespace

TEST(RadialCells, SummaryAndCellCountsAreExact) {
  const std::string plots = test_files::scratch_dir() + "radial_cells.csv";
  test_run::result r = batch("radial_cells", {"--steps", "30", "--end", "--plots", plots});
  ASSERT_EQ(r.status, 0) << report(r);
  EXPECT_EQ(r.out, "53 cells, mean area 0.8782, 2 in the quiescent zone\n");
  EXPECT_EQ(csv_column(plots, "cells"), std::vector<std::string>({"7",  "7",  "7",  "7",  "7",  "7",  "7",  "7",  "7",  "7",  "7",
                                                                 "7",  "7",  "7",  "13", "25", "25", "25", "25", "25", "25", "25",
                                                                 "25", "35", "38", "39", "42", "43", "46", "50", "53"}));
}

TEST(RadialCells, TheQuiescentZoneDividesLess) {
  // Without a quiescent zone the centre divides as fast as its area allows.
  test_run::result r = batch("radial_cells", {"--steps", "30", "--end", "--set", "quiescent_factor=1"});
  ASSERT_EQ(r.status, 0) << report(r);
  EXPECT_EQ(r.out, "55 cells, mean area 0.8472, 6 in the quiescent zone\n");
}

TEST(RadialCells, TheTissueIsADiscOfCellFans) {
  const std::string dir = test_files::scratch_dir();
  const std::pair<int, long> runs[] = {{0, 7}, {15, 25}, {30, 53}};  // steps, cells
  for (auto [steps, expected_cells] : runs) {
    const std::string out = dir + "radial_cells_" + std::to_string(steps) + ".vvm";
    test_run::result r = batch("radial_cells", {"--steps", std::to_string(steps), "--export", out});
    ASSERT_EQ(r.status, 0) << report(r);
    SCOPED_TRACE(steps);
    graph::context ctx;
    graph::mesh S{ctx};
    S.readXMLFile(out);
    EXPECT_NO_THROW(vv::check_invariants(S, {true, false}));  // symmetric
    long triangles = 0, cells = 0;
    for (graph::vertex v : vv::each(S)) {
      std::vector<graph::vertex> nbs;
      for (graph::vertex n : vv::each(v)) nbs.push_back(n);
      if (!v->centre) {
        // A wall junction belongs to at least one cell.
        bool in_cell = false;
        for (graph::vertex n : nbs) in_cell = in_cell || n->centre;
        EXPECT_TRUE(in_cell);
        continue;
      }
      ++cells;
      triangles += long(nbs.size());
      ASSERT_GE(nbs.size(), 3u);
      std::vector<Pt> corners;
      for (graph::vertex n : nbs) {
        EXPECT_FALSE(n->centre);  // a cell's fan reaches walls only
        corners.push_back(n->pos);
      }
      EXPECT_GT(algorithms::polygon_area(corners), 0.05);
      for (std::size_t i = 0; i < corners.size(); ++i)
        EXPECT_GT(cross(v->pos, corners[i], corners[(i + 1) % corners.size()]), 0);
    }
    EXPECT_EQ(cells, expected_cells);
    // A disc triangulated by the fans: V - E + T = 1.
    EXPECT_EQ(long(S.size()) - long(vv::edge_count(S)) + triangles, 1);
  }
}

TEST(RadialCells, TwoRunsExportTheSameBytes) {
  expect_runs_export_the_same_bytes("radial_cells", "20");
}
