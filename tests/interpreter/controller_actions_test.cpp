// The model's actions and pick block through the model controller: they
// are events of the log, a replay repeats them in order and comes to the
// same state, one that fails brings the model back to the state before it,
// and the facts list the actions for the panel and the keys. The model,
// state_models/lifts.vvp, says what each does to its vertices.
#include "controller_harness.hpp"

namespace {

using namespace controller_harness;

// Lifts, steps and a pick, in an order whose result tells them apart.
const char* const history[] = {"step", "action Lift", "step", "pick-action 2", "action Lift"};

// By hand: start's vertex at 0, step 1's at x = 1, both lifted; step 2's at
// x = 2; vertex 2 (step 1's) picked: z = 5; all three lifted again.
const char* const after_history = "<mesh>\n  <v pos=\"0 2 0\" nb=\"\" />\n  <v pos=\"1 2 5\" nb=\"\" />\n"
                                  "  <v pos=\"2 1 0\" nb=\"\" />\n</mesh>\n";

TEST(ControllerActions, TheFactsListTheActionsWithTheirKeysAndThePickBlock) {
  controlled m("lifts.vvp");
  const std::vector<vvi::action_view>& a = m.c.facts().actions;
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a[0].name, "Lift");
  EXPECT_EQ(a[0].key, 'l');
  EXPECT_EQ(a[0].line, line_in_model("lifts.vvp", "action \"Lift\" key"));
  EXPECT_EQ(a[1].name, "Lift and fail");
  EXPECT_EQ(a[1].key, 0);
  EXPECT_EQ(a[2].name, "Crash");
  EXPECT_TRUE(m.c.facts().has_pick);
  controlled without("history.vvp");
  EXPECT_TRUE(without.c.facts().actions.empty());
  EXPECT_FALSE(without.c.facts().has_pick);
}

TEST(ControllerActions, ActionsAndPicksAreEventsOfTheLogAndNotSteps) {
  controlled m("lifts.vvp");
  for (const char* line : history) m.run(line);
  EXPECT_TRUE(m.view.errors.empty()) << m.view.errors[0];
  EXPECT_EQ(m.c.facts().steps, 2u);
  EXPECT_EQ(m.c.log().text(), "step 1\naction Lift\nstep 1\npick-action 2\naction Lift\n");
  EXPECT_EQ(m.c.record().log.text(), m.c.log().text());
  EXPECT_EQ(m.exported("lifted.vvm"), after_history);
}

TEST(ControllerActions, AReplayRunsThemAgainInOrderToTheSameState) {
  controlled first("lifts.vvp");
  for (const char* line : history) first.run(line);
  controlled again("lifts.vvp", first.c.log());
  EXPECT_TRUE(again.view.errors.empty());
  EXPECT_EQ(again.exported("replayed.vvm"), after_history);
  EXPECT_TRUE(again.c.log() == first.c.log());
  // A reload too.
  first.reload();
  EXPECT_EQ(first.view.said.back(), "reloaded " + first.o.model + " (cached)");
  EXPECT_EQ(first.exported("reloaded.vvm"), after_history);
}

// "Lift and fail" lifts every vertex, then fails: the model comes back to
// the state before it, not lifted, and the log does not hold it.
TEST(ControllerActions, AnActionThatFailsBringsTheModelBackToTheStateBeforeIt) {
  controlled m("lifts.vvp");
  m.run("step");
  m.run("action \"Lift and fail\"");
  ASSERT_EQ(m.view.errors.size(), 1u);
  const std::string line = std::to_string(line_in_model("lifts.vvp", "none$pos = "));
  EXPECT_NE(m.view.errors[0].find("lifts.vvp:" + line + ": $: property access on the null vertex (in action "
                                  "\"Lift and fail\")"),
            std::string::npos)
      << m.view.errors[0];
  EXPECT_EQ(m.c.log().text(), "step 1\n");
  EXPECT_EQ(m.exported("not_lifted.vvm"),
            "<mesh>\n  <v pos=\"0 0 0\" nb=\"\" />\n  <v pos=\"1 0 0\" nb=\"\" />\n</mesh>\n");
}

// An unknown action, or a pick of a model without a pick block, runs none
// of the model's code; an unknown label is the pick block's own error.
TEST(ControllerActions, AnUnknownActionOrLabelIsAnErrorNamingIt) {
  controlled m("lifts.vvp");
  m.run("action Nope");
  ASSERT_EQ(m.view.errors.size(), 1u);
  EXPECT_NE(m.view.errors[0].find("the model has no action \"Nope\" (it has \"Lift\", \"Lift and fail\", \"Crash\")"),
            std::string::npos)
      << m.view.errors[0];
  // Nothing ran: the model was not restored (run again) either.
  for (const std::string& said : m.view.said) EXPECT_EQ(said.find("restored"), std::string::npos) << said;
  m.run("pick-action 9");
  ASSERT_EQ(m.view.errors.size(), 2u);
  EXPECT_NE(m.view.errors[1].find("vertex 9"), std::string::npos) << m.view.errors[1];
  EXPECT_TRUE(m.c.log().events.empty());
  controlled without("history.vvp");
  without.run("step");
  without.run("pick-action 1");
  ASSERT_EQ(without.view.errors.size(), 1u);
  EXPECT_NE(without.view.errors[0].find("the model has no pick block (pick of vertex 1)"), std::string::npos)
      << without.view.errors[0];
  for (const std::string& said : without.view.said) EXPECT_EQ(said.find("restored"), std::string::npos) << said;
  EXPECT_EQ(without.c.log().text(), "step 1\n");
}

// A session saved with actions and picks reads back as the same log.
TEST(ControllerActions, ASavedSessionHoldsThemAsCommands) {
  controlled m("lifts.vvp");
  m.run("step");
  m.run("action \"Lift and fail\"");  // fails: not in the session
  m.run("action Lift");
  m.run("pick-action 1");
  std::string path = test_files::scratch_dir() + "lifts.vvs";
  m.run(command::with_path(command::save_session, path));
  std::string text = test_files::slurp(path);
  EXPECT_EQ(text.substr(text.find('\n') + 1), "step 1\naction Lift\npick-action 1\n");
  vvi::event_log read;
  std::string error;
  ASSERT_TRUE(vvi::event_log::parse(text, path, read, error)) << error;
  EXPECT_TRUE(read == m.c.log());
}

}  // namespace
