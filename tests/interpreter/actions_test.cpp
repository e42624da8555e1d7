// The host's actions and pick block, in-process (runner/session.hpp,
// runner/model_runner.hpp): a real model (models/actions.vvp), built once
// for the whole executable, run through model_runner as the viewer and
// batch run it; a crash runs in a supervised child, as it does there. Then
// the example that has them (examples/cell_system.vvp): a picked corner's
// cell divides, "Relax" settles the tissue under new parameters.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "runner/crash_report.hpp"
#include "runner/model_runner.hpp"
#include "runner/supervisor.hpp"
#include "in_process_options.hpp"

namespace {

const std::string model_file = std::string(VV_TESTS_DIR) + "/models/actions.vvp";
const std::string cell_system_file = std::string(VV_SOURCE_DIR) + "/examples/cell_system.vvp";

vvi::options model_options(const std::string& file = model_file) { return in_process_options(file); }

class Actions : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    vvi::model_runner builder(model_options());
    vvi::build_result b = builder.build(false);
    ASSERT_TRUE(b.ok) << b.error << "\n" << b.details;
    plugin = b.plugin;
  }

  void SetUp() override {
    ASSERT_FALSE(plugin.empty()) << "the model did not build";
    ASSERT_TRUE(runner.load(plugin)) << runner.error();
  }

  //! The `size` of the vertex with this label, as the Inspect section shows it.
  std::string size_of(unsigned label) {
    std::string text;
    std::string e = runner.describe_vertex(label, text);
    if (!e.empty()) return e;
    std::size_t at = text.find("size = ");
    return at == std::string::npos ? text : text.substr(at + 7, text.find('\n', at) - at - 7);
  }

  static std::string plugin;
  vvi::model_runner runner{model_options()};
};

std::string Actions::plugin;

TEST_F(Actions, AnActionChangesTheModelAndCountsNoStep) {
  ASSERT_TRUE(runner.step()) << runner.error();
  ASSERT_TRUE(runner.run_action("Grow")) << runner.error();
  EXPECT_EQ(runner.model()->steps_done(), 1u);
  EXPECT_EQ(size_of(1), "11");
  EXPECT_EQ(size_of(2), "11");
  ASSERT_TRUE(runner.step()) << runner.error();
  EXPECT_EQ(size_of(1), "21");
  EXPECT_EQ(runner.model()->steps_done(), 2u);
}

TEST_F(Actions, TheActionsAreListedWithKeysAndLines) {
  std::vector<const vv_action_entry*> actions = runner.model()->actions();
  ASSERT_EQ(actions.size(), 3u);
  EXPECT_STREQ(actions[0]->name, "Grow");
  EXPECT_EQ(actions[0]->key, 'g');
  EXPECT_EQ(actions[0]->line, 21);
  EXPECT_STREQ(actions[1]->name, "Fail");
  EXPECT_EQ(actions[1]->key, 0);
  EXPECT_STREQ(actions[2]->name, "Crash");
  EXPECT_EQ(runner.model()->model().pick_line, 37);
}

TEST_F(Actions, AnActionRecordsItsPlotsAgainstTheLastStep) {
  ASSERT_TRUE(runner.step()) << runner.error();
  ASSERT_TRUE(runner.step()) << runner.error();
  ASSERT_TRUE(runner.run_action("Grow")) << runner.error();
  std::vector<vv_plot_series> plots = runner.model()->plots();
  ASSERT_EQ(plots.size(), 1u);
  EXPECT_STREQ(plots[0].name, "grown");
  ASSERT_EQ(plots[0].count, 1u);
  EXPECT_EQ(plots[0].steps[0], 2u);
  EXPECT_EQ(plots[0].values[0], 1.0);
}

TEST_F(Actions, TheRunSettingsAreWhatTheProgramSet) {
  vv_run_settings s = runner.model()->run_settings();
  EXPECT_EQ(s.steps, 7u);
  EXPECT_EQ(s.has_view_volume, 0);
}

TEST_F(Actions, AnUnknownActionIsAnErrorNamingTheModelAndItsActions) {
  EXPECT_FALSE(runner.run_action("Shrink"));
  EXPECT_EQ(runner.error(), model_file + ": the model has no action \"Shrink\" (it has \"Grow\", \"Fail\", \"Crash\")");
  EXPECT_EQ(size_of(1), "0");
}

TEST_F(Actions, AnErrorInAnActionNamesItsLineAndTheAction) {
  EXPECT_FALSE(runner.run_action("Fail"));
  EXPECT_EQ(runner.error(), model_file + ":29: $: property access on the null vertex (in action \"Fail\")");
  EXPECT_EQ(runner.model()->steps_done(), 0u);
}

TEST_F(Actions, PickRunsOnTheVertexOfTheLabel) {
  ASSERT_TRUE(runner.step()) << runner.error();
  ASSERT_TRUE(runner.run_pick(2)) << runner.error();
  EXPECT_EQ(size_of(1), "10");
  EXPECT_EQ(size_of(2), "100");
  EXPECT_EQ(runner.model()->steps_done(), 1u);
}

TEST_F(Actions, PickOfALabelNoMeshHoldsNamesTheLabel) {
  EXPECT_FALSE(runner.run_pick(99));
  EXPECT_EQ(runner.error(), "no global mesh holds a vertex 99 (in pick of vertex 99)");
}

// As in batch and the viewer: the model runs in a child; its crash is the
// supervisor's to report, with the line and the action.
TEST_F(Actions, ACrashInAnActionIsReportedWithItsLineAndTheAction) {
  vvi::child_end end = vvi::run_supervised(
      [] {
        vvi::model_runner child(model_options());
        if (!child.load(plugin)) return 2;
        child.run_action("Crash");
        return 0;
      },
      vvi::supervision{});
  ASSERT_EQ(end.kind, vvi::child_end::crashed);
  vvi::crash_text report = vvi::describe_crash(end, model_file);
  vvi::remove_module_copies(end);
  EXPECT_EQ(report.line, model_file + ":34: crashed with SIGSEGV in action \"Crash\"");
  EXPECT_NE(report.stack.find(model_file + ":34 in an action's block"), std::string::npos) << report.stack;
}

class CellSystemExample : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    vvi::model_runner builder(model_options(cell_system_file));
    vvi::build_result b = builder.build(false);
    ASSERT_TRUE(b.ok) << b.error << "\n" << b.details;
    plugin = b.plugin;
  }

  void SetUp() override {
    ASSERT_FALSE(plugin.empty()) << "the model did not build";
    ASSERT_TRUE(runner.load(plugin, 2)) << runner.error();  // 4 cells
  }

  //! The last value of a plot series, and the step it was recorded at.
  std::pair<unsigned, double> last_of(const std::string& series) {
    for (const vv_plot_series& p : runner.model()->plots())
      if (series == p.name && p.count) return {p.steps[p.count - 1], p.values[p.count - 1]};
    ADD_FAILURE() << "no series " << series;
    return {0, 0};
  }

  std::size_t vertices() { return runner.model()->mesh("S")->vertex_count(); }

  static std::string plugin;
  vvi::model_runner runner{model_options(cell_system_file)};
};

std::string CellSystemExample::plugin;

TEST_F(CellSystemExample, HasTheActionRelaxOnXAndAPickBlock) {
  std::vector<const vv_action_entry*> actions = runner.model()->actions();
  ASSERT_EQ(actions.size(), 1u);
  EXPECT_STREQ(actions[0]->name, "Relax");
  EXPECT_EQ(actions[0]->key, 'x');
  EXPECT_NE(runner.model()->model().pick, nullptr);
}

// Vertex 1 is a corner of the first hexagon, on the tissue's outline: one
// cell has it. Dividing a cell adds two wall vertices and one cell.
TEST_F(CellSystemExample, PickingACornerDividesItsCell) {
  EXPECT_EQ(last_of("cells"), std::make_pair(2u, 4.0));
  const std::size_t before = vertices();
  ASSERT_TRUE(runner.run_pick(1)) << runner.error();
  EXPECT_EQ(last_of("cells"), std::make_pair(2u, 5.0));
  EXPECT_EQ(vertices(), before + 2);
  EXPECT_EQ(runner.model()->steps_done(), 2u);
  // The daughters wait a generation: the next step divides the other 3 cells only.
  ASSERT_TRUE(runner.step()) << runner.error();
  EXPECT_EQ(last_of("cells"), std::make_pair(3u, 8.0));
}

TEST_F(CellSystemExample, RelaxSettlesTheTissueUnderANewPressure) {
  const double settled = last_of("mean cell area").second;
  ASSERT_EQ(runner.set_parameter("pressure", "2"), "");
  ASSERT_TRUE(runner.run_action("Relax")) << runner.error();
  EXPECT_GT(last_of("mean cell area").second, settled * 1.1);  // the walls stretched
  EXPECT_EQ(last_of("cells"), std::make_pair(2u, 4.0));        // and no cell divided
  EXPECT_EQ(runner.model()->steps_done(), 2u);
}

}  // namespace
