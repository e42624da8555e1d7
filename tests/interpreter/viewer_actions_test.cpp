// The program's actions and pick block in the viewer: the panel's Actions
// section has a button per action with its key; the script's `action` and
// `pick-action` run them as the buttons, the keys and Shift+click do (one
// command each); a reload replays them, and one that crashes the model
// runs once. The model, state_models/lifts.vvp, says what each does.
#include "text_in_image.hpp"
#include "viewer_harness.hpp"

namespace {

const std::string lifts = VV_TESTS_DIR "/state_models/lifts.vvp";

TEST(ViewerActions, ThePanelHasAButtonPerActionAndTheScriptRunsThemAndAReloadReplaysThem) {
  std::string d = fresh_dir("actions_panel");
  const std::string shot = d + "window.png";
  write_text(d + "s.txt", script({"step 1", "action Lift", "pick-action 2", "window-screenshot " + shot,
                                  "export S " + d + "before.vvm", "recompile", "export S " + d + "after.vvm",
                                  "quit"}));
  test_run::result r = viewer({"--script", d + "s.txt", lifts});
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);
  EXPECT_TRUE(viewer_errors(r.err).empty()) << report(r);
  // Start's vertex and step 1's, both lifted; step 1's (label 2) picked.
  EXPECT_EQ(slurp(d + "before.vvm"), "<mesh>\n  <v pos=\"0 1 0\" nb=\"\" />\n  <v pos=\"1 1 5\" nb=\"\" />\n</mesh>\n")
      << report(r);
  EXPECT_EQ(slurp(d + "after.vvm"), slurp(d + "before.vvm")) << report(r);
  image window = load_png(shot);
  ASSERT_TRUE(window.ok()) << report(r);
  for (const char* text : {"Actions", "Lift (l)", "Lift and fail", "Crash"})
    EXPECT_TRUE(find_text(window, text, is_light, 0, 0, panel_right_limit).found()) << "no \"" << text << "\"";
}

// The window that comes back after the crash has the model as it was before
// the action, and the script goes on after it.
TEST(ViewerActions, AnActionThatCrashesTheModelRunsOnce) {
  std::string d = fresh_dir("action_crash");
  write_text(d + "s.txt", script({"step 1", "action Lift", "action Crash", "export S " + d + "S.vvm", "quit"}));
  test_run::result r = viewer({"--script", d + "s.txt", lifts});
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);
  const std::string line = std::to_string(line_of(slurp(lifts), "*nowhere() = 3;"));
  EXPECT_EQ(count_of(r.err, "lifts.vvp:" + line + ": crashed with SIGSEGV in action \"Crash\""), 1) << report(r);
  EXPECT_EQ(count_of(r.err, "crashed"), 1) << report(r);
  EXPECT_EQ(slurp(d + "S.vvm"), "<mesh>\n  <v pos=\"0 1 0\" nb=\"\" />\n  <v pos=\"1 1 0\" nb=\"\" />\n</mesh>\n")
      << report(r);
}

}  // namespace
