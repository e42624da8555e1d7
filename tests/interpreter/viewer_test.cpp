// The interactive viewer (vvinterpreter without --batch), driven through
// --script inside a virtual X display: scripted sessions (steps, rewind,
// screenshots, export, camera), continuous modelling (editing the model
// while the window is open), errors that must leave the window running,
// proxy.record_frame, and the message when there is no display at all.
//
// Small models live in viewer_models/; files the viewer writes go to the
// scratch folder of this test process.
#include "viewer_harness.hpp"

namespace {

// ---- 1. a scripted session ----

TEST(ViewerScript, StepsRewindScreenshotsExportCameraAndQuit) {
  std::string d = fresh_dir("session");
  std::string a = d + "a.png", b = d + "b.png", rotated = d + "rotated.png", zoomed = d + "zoomed.png";
  std::string exported = d + "S.vvm";
  write_text(d + "session.txt", script({"step 2", "screenshot " + a, "rewind", "step 2", "screenshot " + b,
                                        "export S " + exported, "rotate 30 20", "screenshot " + rotated,
                                        "zoom 2", "screenshot " + zoomed, "quit"}));
  test_run::result r = viewer({"--script", d + "session.txt", loop_model});
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);
  EXPECT_TRUE(viewer_errors(r.err).empty()) << report(r);
  EXPECT_TRUE(has(r.out, "loaded " + loop_model)) << report(r);
  EXPECT_TRUE(has(r.out, "rewound " + loop_model)) << report(r);
  for (const std::string& f : {a, b, exported, rotated, zoomed})
    EXPECT_TRUE(has(r.out, "wrote " + f)) << report(r);

  // Two steps after a rewind draw exactly what two steps after loading drew.
  ASSERT_TRUE(fs::exists(a) && fs::exists(b)) << report(r);
  EXPECT_TRUE(slurp(a) == slurp(b)) << "the screenshots after rewind and the same steps differ";
  expect_scene_shot(a);
  expect_scene_shot(b);

  // The mesh after two Loop steps of the double pyramid.
  EXPECT_EQ(vvm_vertex_count(exported), 66);

  // Turning the camera changes the picture.
  ASSERT_TRUE(fs::exists(rotated)) << report(r);
  EXPECT_FALSE(slurp(rotated) == slurp(b)) << "rotate 30 20 did not change the screenshot";
  expect_scene_shot(rotated);

  // Zooming in by 2 makes the object larger in the picture.
  ASSERT_TRUE(fs::exists(zoomed)) << report(r);
  image before = load_png(rotated), after = load_png(zoomed);
  ASSERT_TRUE(before.ok() && after.ok());
  box small = object_box(before), large = object_box(after);
  ASSERT_FALSE(small.empty() || large.empty());
  EXPECT_GT(large.width(), small.width() * 3 / 2) << describe(small) << " -> " << describe(large);
  EXPECT_GT(large.height(), small.height() * 3 / 2) << describe(small) << " -> " << describe(large);
  EXPECT_GT(large.pixels, small.pixels * 2) << describe(small) << " -> " << describe(large);
}

// Issue 9, item 25: a comment after a command, as docs/interpreter.md
// shows them, was rejected.
TEST(ViewerScript, CommentsAfterCommandsAreComments) {
  std::string d = fresh_dir("script_comments");
  write_text(d + "s.txt", script({"# a whole-line comment", "step 2   # two steps", "export S " + d + "S#1.vvm  # a '#' inside a word is not one",
                                  "quit # done"}));
  test_run::result r = viewer({"--script", d + "s.txt", loop_model});
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);
  EXPECT_TRUE(viewer_errors(r.err).empty()) << report(r);
  // Loop of the double pyramid, two steps: 6 + 12 + 48 vertices.
  EXPECT_EQ(vvm_vertex_count(d + "S#1.vvm"), 66) << report(r);
}

// ---- 2. continuous modelling ----

TEST(ViewerHotReload, EditedModelReloadsAndABrokenEditKeepsTheLastGoodModel) {
  std::string d = fresh_dir("hot");
  std::string model = d + "grow.vvp";
  const std::string original = slurp(models_dir + "grow.vvp");
  write_text(model, original);
  const std::string before = d + "before.vvm", after = d + "after.vvm", last = d + "last.vvm";
  const std::string shot = d + "after_error.png";
  // Each wait leaves time for the file watch to notice an edit; the viewer
  // holds the script while it recompiles.
  write_text(d + "hot.txt", script({"step 2", "export M " + before, "wait 6000", "step 2", "export M " + after,
                                    "wait 6000", "step 1", "export M " + last, "screenshot " + shot, "quit"}));
  live_viewer v({"--script", d + "hot.txt", model});
  ASSERT_TRUE(v.started());

  // First edit, once the original model has run: 3 triangles a step, not 1.
  ASSERT_TRUE(v.wait_for_out("wrote " + before, viewer_timeout)) << v.out << v.err;
  EXPECT_TRUE(has(v.out, "loaded " + model)) << v.out;
  // (The new text is longer too, so a coarse file clock cannot hide the edit.)
  replace_file(model, edited(original, "const int per_step = 1;", "const int per_step = 3;  // was 1"));
  bool reloaded = v.wait_for_out("reloaded " + model, 120);
  EXPECT_TRUE(reloaded) << v.out << v.err;

  // Second edit, after the reloaded model has run: a syntax error.
  bool exported_after = v.wait_for_out("wrote " + after, 120);
  EXPECT_TRUE(exported_after) << v.out << v.err;
  std::string good = slurp(model);
  std::string broken = edited(good, "make {a, b} nb_of c;", "make {a, b} c;");
  int broken_line = line_of(broken, "make {a, b} c;");
  replace_file(model, broken);

  test_run::result r = v.finish();
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);

  // The original behaviour: a triangle from start and one a step.
  EXPECT_EQ(vvm_vertex_count(before), 3 + 2 * 3) << report(r);
  // Reloaded before the next steps ran: the reload starts the new model
  // afresh and runs it again to step 2, then two more steps: three
  // triangles a step, four steps.
  std::size_t reload_at = r.out.find("reloaded " + model), after_at = r.out.find("wrote " + after);
  EXPECT_TRUE(reload_at != std::string::npos && after_at != std::string::npos && reload_at < after_at)
      << report(r);
  EXPECT_EQ(vvm_vertex_count(after), 3 + 4 * 9) << report(r);
  EXPECT_EQ(r.out.find("reloaded " + model, reload_at + 1), std::string::npos)
      << "the broken edit was loaded\n" << report(r);

  // The syntax error is shown with its line; the last good model keeps
  // running: one more step of it adds three triangles.
  EXPECT_TRUE(error_names(r.err, "grow.vvp:" + std::to_string(broken_line))) << report(r);
  EXPECT_TRUE(has(r.out, "wrote " + last)) << report(r);
  EXPECT_EQ(vvm_vertex_count(last), 3 + 5 * 9) << report(r);
  EXPECT_TRUE(has(r.out, "wrote " + shot)) << report(r);
  if (fs::exists(shot)) {
    image im = load_png(shot);
    ASSERT_TRUE(im.ok());
    EXPECT_FALSE(object_box(im).empty()) << "the last good model is not drawn";
  }
}

// ---- 3. errors leave the window running ----

struct error_run {
  test_run::result result;
  std::string dir;
};

//! Runs `model` in the viewer with the script lines `before`, then an
//! export of M, a screenshot and quit; checks that the viewer went on
//! after the error (the screenshot was written) and quit normally.
error_run run_with_error(const std::string& name, const std::string& model, const std::vector<std::string>& before) {
  error_run e;
  e.dir = fresh_dir(name);
  std::vector<std::string> lines = before;
  lines.push_back("export M " + e.dir + "M.vvm");
  lines.push_back("screenshot " + e.dir + "after.png");
  lines.push_back("quit");
  write_text(e.dir + "script.txt", script(lines));
  e.result = viewer({"--script", e.dir + "script.txt", model});
  const test_run::result& r = e.result;
  EXPECT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);
  EXPECT_FALSE(viewer_errors(r.err).empty()) << "no error message\n" << report(r);
  EXPECT_TRUE(has(r.out, "wrote " + e.dir + "after.png")) << "the viewer stopped working after the error\n"
                                                           << report(r);
  return e;
}

TEST(ViewerErrors, SyntaxErrorNamesTheLine) {
  std::string model = models_dir + "syntax_error.vvp";
  int line = line_of(slurp(model), "forall in M");
  error_run e = run_with_error("syntax", model, {"step 1"});
  EXPECT_TRUE(error_names(e.result.err, "syntax_error.vvp:" + std::to_string(line))) << report(e.result);
  EXPECT_FALSE(has(e.result.out, "loaded")) << report(e.result);
}

TEST(ViewerErrors, CompileErrorNamesTheLine) {
  std::string model = models_dir + "compile_error.vvp";
  int line = line_of(slurp(model), "no_such_variable");
  error_run e = run_with_error("compile", model, {"step 1"});
  EXPECT_TRUE(error_names(e.result.err, "compile_error.vvp:" + std::to_string(line))) << report(e.result);
  EXPECT_TRUE(has(e.result.err, "no_such_variable")) << report(e.result);
  EXPECT_FALSE(has(e.result.out, "loaded")) << report(e.result);
}

TEST(ViewerErrors, RunTimeErrorInStepTwoKeepsTheStateAfterStepOne) {
  std::string model = models_dir + "runtime_error.vvp";
  int line = line_of(slurp(model), "make {a, b, a} nb_of c;");
  error_run e = run_with_error("runtime", model, {"step 3"});
  EXPECT_TRUE(has(e.result.out, "loaded " + model)) << report(e.result);
  EXPECT_TRUE(error_names(e.result.err, "runtime_error.vvp:" + std::to_string(line))) << report(e.result);
  // Step 1 added one vertex; step 2 failed before changing anything and
  // step 3 did not run.
  EXPECT_TRUE(has(e.result.out, "wrote " + e.dir + "M.vvm")) << report(e.result);
  EXPECT_EQ(vvm_vertex_count(e.dir + "M.vvm"), 1) << report(e.result);
}

TEST(ViewerErrors, MissingInputFileInStartNamesTheLine) {
  std::string model = models_dir + "missing_input.vvp";
  int line = line_of(slurp(model), "no_such_input.vvm");
  error_run e = run_with_error("missing_input", model, {"step 1"});
  EXPECT_TRUE(error_names(e.result.err, "missing_input.vvp:" + std::to_string(line))) << report(e.result);
  EXPECT_TRUE(has(e.result.err, "no_such_input.vvm")) << report(e.result);
}

TEST(ViewerErrors, MissingModelFileIsReported) {
  std::string d = fresh_dir("missing_model_file");
  std::string model = d + "no_such_model.vvp";
  error_run e = run_with_error("missing_model", model, {"step 1"});
  bool named = false;
  for (const std::string& l : viewer_errors(e.result.err)) named = named || has(l, model);
  EXPECT_TRUE(named) << report(e.result);
  EXPECT_FALSE(has(e.result.out, "loaded")) << report(e.result);
}

// ---- 4. proxy.record_frame ----

TEST(ViewerRecordFrame, WritesOneNumberedFramePerStep) {
  std::string d = fresh_dir("record");
  std::string frames = d + "frames";  // the viewer creates it
  write_text(d + "record.txt", script({"step 3", "quit"}));
  test_run::result r = viewer({"--frames", frames, "--script", d + "record.txt", models_dir + "record_frame.vvp"});
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);
  EXPECT_TRUE(viewer_errors(r.err).empty()) << report(r);
  std::vector<std::string> names;
  if (fs::is_directory(frames))
    for (const auto& entry : fs::directory_iterator(frames)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"frame_00001.png", "frame_00002.png", "frame_00003.png"}))
      << report(r);
  std::vector<std::string> pngs;
  for (const std::string& n : names) {
    image im = load_png(frames + "/" + n);
    EXPECT_EQ(im.width, window_width) << n;
    EXPECT_EQ(im.height, window_height) << n;
    EXPECT_FALSE(object_box(im).empty()) << n << " is blank";
    pngs.push_back(slurp(frames + "/" + n));
  }
  // Each step adds a triangle in view: every frame shows a new state.
  for (std::size_t i = 0; i < pngs.size(); ++i)
    for (std::size_t j = i + 1; j < pngs.size(); ++j)
      EXPECT_FALSE(pngs[i] == pngs[j]) << names[i] << " and " << names[j] << " are the same picture";
}

// ---- 5. no display ----

TEST(ViewerWithoutDisplay, ExitsWithOneLineSuggestingBatch) {
  std::string d = fresh_dir("no_display");
  write_text(d + "quit.txt", script({"quit"}));
  test_run::result r = test_run::run(
      {"env", "-u", "DISPLAY", "-u", "WAYLAND_DISPLAY", VV_INTERPRETER, "--cache", VV_TEST_CACHE, "--script",
       d + "quit.txt", models_dir + "grow.vvp"},
      viewer_timeout);
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_NE(r.status, 0) << report(r);
  EXPECT_NE(r.status, -1) << "killed by a signal\n" << report(r);
  ASSERT_FALSE(r.err.empty()) << report(r);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "not one line\n" << report(r);
  EXPECT_EQ(r.err.back(), '\n') << report(r);
  EXPECT_TRUE(has(r.err, "--batch")) << report(r);
  EXPECT_FALSE(has(r.out, "loaded")) << report(r);
}

}  // namespace
