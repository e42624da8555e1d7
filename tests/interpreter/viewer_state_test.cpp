// What the viewer shows is the model's state, and what was done to the
// model stays done: a script command runs once even when it crashes the
// model; the panel shows the model's step while a step runs; after an
// error the model, its panel and its drawing agree; a reload brings back
// everything done between the steps, not only their number. Models live in
// state_models/.
#include "text_in_image.hpp"
#include "viewer_harness.hpp"

namespace {

const std::string state_models = VV_TESTS_DIR "/state_models/";
const std::string fault_models = VV_TESTS_DIR "/fault_models/";

// The panel's orange "running for" line.
bool is_orange(const unsigned char* p) { return p[0] > 150 && p[1] > 70 && p[2] < 60; }

// A step that crashed the model was run again by the restarted window when
// the script gave it in the frame its job started (after a wait): two
// crash reports, two restarts. It runs once; the model comes back at
// step 1 and the script goes on.
TEST(ViewerState, AScriptCommandThatCrashesTheModelRunsOnce) {
  std::string d = fresh_dir("crash_runs_once");
  const std::string model = fault_models + "crash_in_step2.vvp";
  write_text(d + "s.txt", script({"step 1", "wait 300", "step 1", "export S " + d + "S.vvm", "quit"}));
  test_run::result r = viewer({"--script", d + "s.txt", model});
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);
  EXPECT_EQ(count_of(r.err, "crashed with SIGSEGV in step 2"), 1) << report(r);
  EXPECT_EQ(count_of(r.out, "step 2\n"), 1) << report(r);
  EXPECT_TRUE(has(r.out, "wrote " + d + "S.vvm")) << report(r);
  EXPECT_EQ(vvm_vertex_count(d + "S.vvm"), 3);
}

// While step 2 runs (for ever), the panel showed "step 0" and "Run 0"
// beside "step 2 running for ...": the model's state was read only while
// it was idle. It shows the state step 1 left.
TEST(ViewerState, WhileAStepRunsThePanelShowsTheStepBefore) {
  std::string d = fresh_dir("panel_while_running");
  const std::string shot = d + "running.png";
  write_text(d + "s.txt", script({"step 1", "step 1", "wait 1200", "window-screenshot " + shot, "stop", "quit"}));
  test_run::result r = viewer({"--script", d + "s.txt", state_models + "hangs_in_step2.vvp"});
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);
  ASSERT_TRUE(has(r.out, "wrote " + shot)) << report(r);
  image window = load_png(shot);
  ASSERT_TRUE(window.ok());
  EXPECT_TRUE(find_text(window, "step 2 running for", is_orange, 0, 0, panel_right_limit).found())
      << "the running step is not shown";
  EXPECT_TRUE(find_text(window, "step 1", is_white, 0, 0, panel_right_limit).found()) << "no \"step 1\"";
  EXPECT_FALSE(find_text(window, "step 0", is_light, 0, 0, panel_right_limit).found()) << "\"step 0\" shown";
  EXPECT_TRUE(find_text(window, "Run 7", is_light, 0, 0, panel_right_limit).found()) << "no \"Run 7\"";
  EXPECT_TRUE(find_text(window, "mesh S: 3 vertices", is_white, 0, 0, panel_right_limit).found())
      << "the mesh's size is not shown";
}

// Step 3 fails after adding its vertex. The panel said step 2 and the
// plots ended at step 2, but the model (its render block, an export) held
// the half-done step 3. The model comes back to the state step 2 left: its
// export, its plots, its drawing and the panel agree.
TEST(ViewerState, AfterAnErrorTheModelThePanelAndTheDrawingAgree) {
  std::string d = fresh_dir("error_agrees");
  const std::string model = state_models + "half_done_step.vvp";
  write_text(d + "s.txt", script({"step 3", "screenshot " + d + "after_error.png", "export M " + d + "M.vvm",
                                  "plots " + d + "plots.csv", "window-screenshot " + d + "window.png", "rewind",
                                  "step 2", "screenshot " + d + "step2.png", "quit"}));
  test_run::result r = viewer({"--script", d + "s.txt", model});
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);
  EXPECT_TRUE(error_names(r.err, model + ":" + std::to_string(line_of(slurp(model), "make {a, b, a}"))))
      << report(r);
  EXPECT_EQ(vvm_vertex_count(d + "M.vvm"), 2) << report(r);
  EXPECT_EQ(slurp(d + "plots.csv"), "step,vertices\n0,0\n1,1\n2,2\n") << report(r);
  ASSERT_TRUE(fs::exists(d + "after_error.png") && fs::exists(d + "step2.png")) << report(r);
  EXPECT_TRUE(slurp(d + "after_error.png") == slurp(d + "step2.png"))
      << "the drawing after the error is not the model after step 2";
  image window = load_png(d + "window.png");
  ASSERT_TRUE(window.ok());
  EXPECT_TRUE(find_text(window, "step 2", is_white, 0, 0, panel_right_limit).found()) << "no \"step 2\"";
}

// The vertices of an exported .vvm, as "x y z" lines in the file's order.
std::vector<std::string> positions_in(const std::string& vvm) {
  std::vector<std::string> out;
  std::string text = slurp(vvm);
  for (std::size_t at = text.find("pos=\""); at != std::string::npos; at = text.find("pos=\"", at + 1))
    out.push_back(text.substr(at + 5, text.find('"', at + 5) - at - 5));
  return out;
}

// A reload ran the new model to the step count only: a parameter set
// between the steps was set before start, and a reread and the end block
// were lost. Everything done is replayed in order, so the reloaded model
// exports the same bytes.
TEST(ViewerState, AReloadReplaysParameterChangesRereadsAndTheEndBlock) {
  std::string d = fresh_dir("reload_replays");
  fs::copy_file(state_models + "history.vvp", d + "history.vvp");
  fs::copy_file(state_models + "shape.func", d + "shape.func");
  write_text(d + "s.txt", script({"step 1", "set spacing=3", "reread", "step 1", "end", "export S " + d + "before.vvm",
                                  "recompile", "export S " + d + "after.vvm", "quit"}));
  test_run::result r = viewer({"--script", d + "s.txt", d + "history.vvp"});
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);
  EXPECT_TRUE(viewer_errors(r.err).empty()) << report(r);
  EXPECT_TRUE(has(r.out, "reloaded " + d + "history.vvp")) << report(r);
  // Start's vertex; step 1 at x = 1 on f = x; step 2 3 further, on f = x
  // again (the reread undid step 1's tripling); the end block's vertex.
  EXPECT_EQ(positions_in(d + "before.vvm"), (std::vector<std::string>{"0 0 0", "1 0.5 0", "4 0.5 0", "0 -1 0"}))
      << report(r);
  EXPECT_EQ(slurp(d + "after.vvm"), slurp(d + "before.vvm")) << report(r);
}

}  // namespace
