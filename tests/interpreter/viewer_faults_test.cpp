// The viewer's modelling loop, as a modeller must be able to trust it
// (issue 8): a reload starts from freshly initialised globals even when the
// build is the same file; a header edit with Recompile really rebuilds; a
// save during a build is not lost; a crash or an endless step never takes
// the window down: it shows the .vvp line, the model comes back at its last
// good step, and the script goes on.
#include "viewer_harness.hpp"

namespace {

const std::string fault_models = VV_TESTS_DIR "/fault_models/";

// Regression (defect 2): a comment-only edit gives the same plugin file;
// it was dlopen()ed while the old model was still loaded, so the handle
// was shared and the globals were not initialised again (the counter went
// on from 2), and the old model's close block ran on the new one.
TEST(ViewerReload, ACommentOnlyEditStartsFromFreshGlobalsAndRunsBackToTheStep) {
  std::string d = fresh_dir("comment_reload");
  std::string model = d + "counter.vvp";
  std::string original = slurp(fault_models + "counter.vvp");
  write_text(model, original);
  write_text(d + "s.txt", script({"step 2", "wait 3000", "step 1", "export S " + d + "S.vvm", "quit"}));
  live_viewer v({"--script", d + "s.txt", model});
  ASSERT_TRUE(v.started());
  ASSERT_TRUE(v.wait_for_out("step: count 2\n", viewer_timeout)) << v.out << v.err;
  replace_file(model, original + "// a comment, and nothing else changed\n");
  test_run::result r = v.finish();
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);
  EXPECT_TRUE(has(r.out, "reloaded " + model)) << report(r);
  // Fresh globals, then run again to step 2, then the script's step 3.
  std::string reload = r.out.substr(r.out.find("reloaded"));
  std::size_t begin = r.out.find("start: count 0\n", r.out.find("step: count 2\n"));
  ASSERT_NE(begin, std::string::npos) << "the reloaded model did not start from 0\n" << report(r);
  EXPECT_EQ(r.out.substr(begin, r.out.find("reloaded", begin) - begin),
            "start: count 0\nstep: count 1\nstep: count 2\n")
      << report(r);
  EXPECT_TRUE(has(reload, "step: count 3\n")) << report(r);
  EXPECT_EQ(count_of(r.out, "step: count 3\n"), 1) << report(r);
  EXPECT_TRUE(viewer_errors(r.err).empty()) << report(r);
}

// Regression (defect 1): Recompile of a model whose header changed ran the
// old code (the rebuilt cache entry lost the rename to the old one).
TEST(ViewerReload, RecompileAfterAHeaderEditRunsTheNewCode) {
  std::string d = fresh_dir("recompile_header");
  fs::copy_file(fault_models + "with_header.vvp", d + "model.vvp");
  write_text(d + "rate.h", "const int rate = 1;\n");
  write_text(d + "s.txt", script({"wait 2500", "recompile", "quit"}));
  live_viewer v({"--script", d + "s.txt", d + "model.vvp"});
  ASSERT_TRUE(v.started());
  ASSERT_TRUE(v.wait_for_out("rate 1\n", viewer_timeout)) << v.out << v.err;
  write_text(d + "rate.h", "const int rate = 333;\n");
  test_run::result r = v.finish();
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);
  EXPECT_TRUE(has(r.out, "rate 333\n")) << "the edited header did not run\n" << report(r);
}

// Regression (defect 3): the files' times were taken after a build, so a
// save made while it ran was never built. The model's header makes the
// build slow enough to save during it.
TEST(ViewerReload, ASaveDuringABuildIsBuiltAfterIt) {
  std::string d = fresh_dir("save_during_build");
  std::string model = d + "slow.vvp";
  // Constant evaluation the compiler needs a few seconds for.
  std::string slow =
      "#include <cstdio>\n"
      "constexpr long spin(long n, long k) { long s = 0; for (long i = 0; i < n; ++i) "
      "for (long j = 0; j < 3000; ++j) s += (i ^ j ^ k) & 7; return s; }\n"
      "constexpr long a = spin(250, 1), b = spin(250, 2), c = spin(250, 3);\n"
      "mesh S;\n"
      "start { std::printf(\"version %d (%ld)\\n\", VERSION, a + b + c); }\n";
  auto version = [&](int n) { return "#define VERSION " + std::to_string(n) + "\n" + slow; };
  write_text(model, version(1));
  // After the first load the rebuild is under way within a second; the
  // script then waits for it (a command waits for a build) before quitting.
  write_text(d + "s.txt", script({"wait 1000", "quit"}));
  live_viewer v({"--script", d + "s.txt", model});
  ASSERT_TRUE(v.started());
  // The viewer says when it has read the sources and starts compiling; the
  // save lands during the compile.
  ASSERT_TRUE(v.wait_for_out("compiling " + model, 60)) << v.out << v.err;
  replace_file(model, version(2) + "// saved while the first build ran\n");
  ASSERT_TRUE(v.wait_for_out("version 1", viewer_timeout)) << v.out << v.err;
  bool rebuilt = v.wait_for_out("version 2", viewer_timeout);
  EXPECT_TRUE(rebuilt) << "the save during the build was lost\n" << v.out << v.err;
}

// Regression (defect 5): a crash in the model's code killed the viewer. It
// now stays: the crash is shown with its line and step, the model comes
// back at step 1 (its last good state), and the script goes on.
TEST(ViewerFaults, ACrashInStepTwoLeavesTheViewerRunningAtStepOne) {
  std::string d = fresh_dir("viewer_crash");
  std::string model = fault_models + "crash_in_step2.vvp";
  std::string shot = d + "after.png";
  write_text(d + "s.txt", script({"step 1", "step 1", "export S " + d + "S.vvm", "window-screenshot " + shot,
                                  "quit"}));
  test_run::result r = viewer({"--script", d + "s.txt", model});
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);
  EXPECT_TRUE(has(r.err, "vvinterpreter: " + model + ":23: crashed with SIGSEGV in step 2\n")) << report(r);
  // The model was run again to step 1 and answered the script's export.
  EXPECT_TRUE(has(r.out, "wrote " + d + "S.vvm")) << report(r);
  EXPECT_EQ(vvm_vertex_count(d + "S.vvm"), 3);
  EXPECT_EQ(count_of(r.out, "partial line of step 1\n"), 2) << "step 1 before the crash and again after it\n"
                                                             << report(r);
  // Printed before the crash, although stdout is a pipe.
  EXPECT_TRUE(has(r.out, "partial line of step 2")) << report(r);
  EXPECT_TRUE(has(r.out, "wrote " + shot)) << report(r);
}

// Regression (defect 4): an endless step froze the window. It stays
// responsive (the script's window screenshot is taken while the step
// runs); `stop` ends the step, and the model comes back at step 1.
TEST(ViewerFaults, StopEndsAnEndlessStepAndTheModelComesBackAtItsLastGoodStep) {
  std::string d = fresh_dir("viewer_stop");
  std::string model = fault_models + "endless_step2.vvp";
  write_text(d + "s.txt", script({"step 1", "step 1", "wait 1000", "window-screenshot " + d + "running.png", "stop",
                                  "export S " + d + "S.vvm", "quit"}));
  test_run::result r = viewer({"--script", d + "s.txt", model});
  ASSERT_FALSE(r.timed_out) << "the endless step was not stopped\n" << report(r);
  EXPECT_EQ(r.status, 0) << report(r);
  EXPECT_TRUE(has(r.out, "wrote " + d + "running.png")) << "the window did not answer during the step\n" << report(r);
  // Issue 23, item 5: the message names the line the step was stopped at.
  EXPECT_TRUE(has(r.err, "vvinterpreter: " + model + ":22: step 2 was stopped after ")) << report(r);
  EXPECT_TRUE(has(r.err, "the model was run again to step 1, its last good state")) << report(r);
  EXPECT_TRUE(has(r.out, "wrote " + d + "S.vvm")) << report(r);
  EXPECT_EQ(vvm_vertex_count(d + "S.vvm"), 3);
}

// Regression: a model that called exit() inside a step ended the viewer,
// silently. It is a fault like a crash: the window stays, the message
// names the call's line and the step, and the model comes back at step 1.
TEST(ViewerFaults, ExitInAStepLeavesTheViewerRunningAtStepOne) {
  std::string d = fresh_dir("viewer_exit");
  std::string model = VV_TESTS_DIR "/supervision_models/misbehaves.vvp";
  write_text(d + "s.txt", script({"step 1", "step 1", "export S " + d + "S.vvm", "quit"}));
  test_run::result r = viewer({"--set", "fault=3", "--set", "in_step=2", "--script", d + "s.txt", model});
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);
  const int exit_line = line_of(slurp(model), "std::exit(3);");
  EXPECT_TRUE(has(r.err, "vvinterpreter: " + model + ":" + std::to_string(exit_line) +
                             ": the model called exit(3) in step 2, before the run was done\n"))
      << report(r);
  EXPECT_TRUE(has(r.out, "wrote " + d + "S.vvm")) << report(r);
  EXPECT_EQ(vvm_vertex_count(d + "S.vvm"), 3);
  EXPECT_EQ(count_of(r.out, "step 1\n"), 2) << "step 1 before the exit and again after it\n" << report(r);
}

}  // namespace
