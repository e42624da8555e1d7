// Looking into a model and steering it (issue 10): plots recorded with
// proxy.plot (batch --plots, script `plots`), a vertex described by label
// (--pick, script `pick`), colour by a numeric property (--color-by),
// parameters set and saved from the viewer, file objects reread when their
// file is saved, and --help listing every script command; and how the
// viewer shows it all: the panel within the window, the pick in view and
// highlighted, slider values readable, the colour bar labelled and clear
// of the model.
#include "text_in_image.hpp"
#include "viewer_harness.hpp"

namespace {

const std::string inspect_model = VV_TESTS_DIR "/models/inspect.vvp";

test_run::result batch(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {"--batch"};
  argv.insert(argv.end(), args.begin(), args.end());
  return test_run::run(test_run::interpreter(argv), 280);
}

// The apex of the double pyramid after one step: its properties, its four
// neighbours in the file's rotation order (labels 4 3 2 1) with 3 flagged,
// and the records step 1 wrote (mark = the neighbour's label).
const std::string apex_after_one_step =
    "vertex 5\n"
    "  in meshes: S\n"
    "  properties:\n"
    "    pos = 0 1.4142 0\n"
    "    height = 1.4142\n"
    "    visits = 1\n"
    "  neighbourhood (4, rotation order, [flagged]): 4 [3] 2 1\n"
    "  half-edge records:\n"
    "    5 -> 4:\n      mark = 4\n"
    "    5 -> 3:\n      mark = 3\n"
    "    5 -> 2:\n      mark = 2\n"
    "    5 -> 1:\n      mark = 1\n";

TEST(Plots, BatchWritesOneColumnPerSeriesAndOneRowPerStep) {
  std::string d = fresh_dir("plots_batch");
  test_run::result r = batch({"--quiet", "--steps", "3", "--plots", d + "plots.csv", inspect_model});
  ASSERT_EQ(r.status, 0) << report(r);
  // Start records only "vertices" (step 0); "even" only at even steps; a
  // name with a comma is quoted; 100/3 reads back exactly.
  EXPECT_EQ(slurp(d + "plots.csv"),
            "step,vertices,\"growth, %\",even\n"
            "0,6,,\n"
            "1,6,100,\n"
            "2,6,50,2\n"
            "3,6,33.333333333333336,\n");
}

TEST(Plots, AModelWithoutPlotsWritesTheHeaderOnly) {
  std::string d = fresh_dir("plots_none");
  test_run::result r = batch({"--quiet", "--plots", d + "plots.csv", loop_model});
  ASSERT_EQ(r.status, 0) << report(r);
  EXPECT_EQ(slurp(d + "plots.csv"), "step\n");
}

TEST(Pick, BatchDescribesAVertexItsNeighbourhoodFlagAndRecords) {
  test_run::result r = batch({"--quiet", "--steps", "1", "--pick", "5", inspect_model});
  ASSERT_EQ(r.status, 0) << report(r);
  EXPECT_EQ(r.out, apex_after_one_step) << report(r);
}

TEST(Pick, AnUnknownLabelIsOneLineAndFails) {
  test_run::result r = batch({"--quiet", "--pick", "99", inspect_model});
  EXPECT_EQ(r.status, 1) << report(r);
  EXPECT_EQ(viewer_errors(r.err),
            std::vector<std::string>{"vvinterpreter: " + inspect_model + ": pick 99: no global mesh holds a vertex 99"})
      << report(r);
}

// The colour bar's columns: where its middle row has the ramp's middle
// colour (teal), searching from the right edge. Empty when there is none.
struct bar_columns {
  int x0 = -1, x1 = -1;  // inclusive
  bool found() const { return x0 >= 0; }
};
bar_columns find_colour_bar(const image& im) {
  bar_columns b;
  auto teal = [](const unsigned char* p) { return p[0] < 60 && p[1] > 120 && p[2] > 110; };
  int y = im.height / 2;
  for (int x = im.width - 1; x >= 0; --x) {
    if (teal(im.at(x, y))) {
      if (b.x1 < 0) b.x1 = x;
      b.x0 = x;
    } else if (b.x1 >= 0) {
      break;
    }
  }
  return b;
}

TEST(ColourBy, TheScreenshotIsColouredByThePropertyAndTheBarLabelled) {
  std::string d = fresh_dir("colour_by");
  ASSERT_EQ(batch({"--quiet", "--screenshot", d + "plain.png", inspect_model}).status, 0);
  test_run::result r = batch({"--quiet", "--color-by", "height", "--screenshot", d + "height.png", inspect_model});
  ASSERT_EQ(r.status, 0) << report(r);
  image plain = load_png(d + "plain.png"), coloured = load_png(d + "height.png");
  ASSERT_EQ(plain.width, coloured.width);
  ASSERT_EQ(plain.height, coloured.height);
  // A face above the front edge (the model) changes colour; the colour
  // bar at the right runs from dark violet (bottom) to yellow (top).
  auto at = [](const image& im, int x, int y) { return im.at(x, y); };
  int cx = plain.width / 2, cy = plain.height / 2 - plain.height / 8;
  EXPECT_FALSE(near_colour(at(plain, cx, cy), at(coloured, cx, cy))) << "the model is not coloured";
  bar_columns bar = find_colour_bar(coloured);
  ASSERT_TRUE(bar.found()) << "no colour bar";
  EXPECT_GT(bar.x0, coloured.width * 3 / 4) << "the colour bar is not at the right";
  int bx = (bar.x0 + bar.x1) / 2, h = coloured.height;
  const unsigned char* top = at(coloured, bx, h * 3 / 10);
  const unsigned char* bottom = at(coloured, bx, h * 7 / 10);
  EXPECT_GT(top[0] + top[1], 300) << "the top of the colour bar is not light (yellow)";
  EXPECT_LT(bottom[0] + bottom[1], 200) << "the bottom of the colour bar is not dark";
  EXPECT_GT(top[1], top[2]) << "the top of the colour bar is not yellow";
  // The labels, as the viewer shows them: the heights of the double
  // pyramid run from -1.4142 to 1.4142; the bar's ends and its middle
  // carry their values (four digits) to the bar's right, and the
  // property's name stands above the bar. The bar spans the middle half of
  // the picture's height.
  auto label = [&](const std::string& text) { return find_text(coloured, text, is_dark, bar.x1 + 1, 0); };
  text_place high = label("1.414"), middle = label("0"), low = label("-1.414");
  text_place name = find_text(coloured, "height", is_dark, bar.x0 - 4, 0);
  ASSERT_TRUE(high.found()) << "no label 1.414 beside the bar";
  ASSERT_TRUE(middle.found()) << "no label 0 beside the bar";
  ASSERT_TRUE(low.found()) << "no label -1.414 beside the bar";
  ASSERT_TRUE(name.found()) << "no name (height) at the bar";
  EXPECT_NEAR(high.centre_y(), h / 4, 3);
  EXPECT_NEAR(middle.centre_y(), h / 2, 3);
  EXPECT_NEAR(low.centre_y(), h * 3 / 4, 3);
  for (const text_place& t : {high, middle, low}) EXPECT_LT(t.x - bar.x1, 16) << "a label far from the bar";
  EXPECT_LT(name.y + name.height, h / 4 - high.height / 2) << "the name is not above the bar";
  EXPECT_NEAR(name.x, bar.x0, 2) << "the name is not over the bar";
  // Nothing else is written there: the name of another property, or the
  // top label's value, are not.
  EXPECT_FALSE(find_text(coloured, "visits", is_dark, bar.x0 - 4, 0).found());
  EXPECT_FALSE(label("1.4142").found());
}

TEST(ColourBy, AMissingPropertyNamesTheNumericOnes) {
  std::string d = fresh_dir("colour_by_missing");
  test_run::result r = batch({"--quiet", "--color-by", "pos", "--screenshot", d + "x.png", inspect_model});
  EXPECT_EQ(r.status, 1) << report(r);
  EXPECT_EQ(viewer_errors(r.err),
            std::vector<std::string>{"vvinterpreter: " + inspect_model +
                                     ": --color-by pos: the vertices have no numeric property pos (they have "
                                     "height, visits)"})
      << report(r);
  EXPECT_FALSE(fs::exists(d + "x.png"));
}

TEST(Help, ListsEveryScriptCommand) {
  test_run::result r = test_run::run(test_run::interpreter({"--help"}), 30);
  ASSERT_EQ(r.status, 0) << report(r);
  for (const char* command : {"step", "run", "rewind", "end", "reread", "recompile", "fit", "screenshot",
                              "window-screenshot", "export", "rotate", "zoom", "wait", "stop", "pick", "set",
                              "save-params", "color-by", "show", "plots", "quit"})
    EXPECT_TRUE(has(r.out, std::string("\n  ") + command + " ")) << command << " is not listed\n" << r.out;
}

// The viewer: `pick` prints what the panel shows; `set` changes what the
// next step computes; `save-params` writes the values into the .vvp.
TEST(ViewerInteraction, PickSetAndSaveParameters) {
  std::string d = fresh_dir("viewer_params");
  const std::string model = d + "parameters.vvp";
  std::string source = slurp(VV_TESTS_DIR "/models/parameters.vvp");
  write_text(model, source);
  write_text(d + "script.txt",
             script({"set rate=0.25", "set grow=false", "rewind", "recompile", "save-params", "quit"}));
  test_run::result r = viewer({"--script", d + "script.txt", model});
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);
  EXPECT_TRUE(viewer_errors(r.err).empty()) << report(r);
  // Start printed the file's values, and after the rewind the set ones.
  EXPECT_TRUE(has(r.out, "rate 0.5 cells 3 grow 1 seeds 7 scale 0.1\n")) << report(r);
  // After the rewind and after the reload Recompile makes: the values set
  // are kept (names and types unchanged).
  const std::string set = "rate 0.25 cells 3 grow 0 seeds 7 scale 0.1\n";
  std::size_t first = r.out.find(set);
  ASSERT_NE(first, std::string::npos) << report(r);
  EXPECT_NE(r.out.find(set, first + 1), std::string::npos) << "a reload lost the values set\n" << report(r);
  std::string saved = edited(edited(source, "param double rate = 0.5 in [0, 1];", "param double rate = 0.25 in [0, 1];"),
                             "param bool grow = true;", "param bool grow = false;");
  EXPECT_EQ(slurp(model), saved);
}

// The last row of the panel: its left padding column is the panel's dark
// background from the title bar down to its bottom edge.
int panel_bottom(const image& im) {
  auto dark = [](const unsigned char* p) { return p[0] < 60 && p[1] < 60 && p[2] < 60; };
  int bottom = -1;
  for (int y = 30; y < im.height; ++y)
    if (dark(im.at(12, y))) bottom = y;
    else if (bottom >= 0) break;
  return bottom;
}

// The column where the panel ends: at the row of the model's name, the
// first dark pixel from the right (the scene is light there).
int panel_right(const image& im) {
  auto dark = [](const unsigned char* p) { return p[0] < 60 && p[1] < 60 && p[2] < 60; };
  for (int x = im.width - 1; x >= 0; --x)
    if (dark(im.at(x, 40))) return x;
  return -1;
}

const unsigned char picked_red[3] = {217, 13, 13}, neighbour_orange[3] = {255, 140, 0};

TEST(ViewerInteraction, PickColourByDisplayAndPlots) {
  std::string d = fresh_dir("viewer_pick");
  const std::string shaded = d + "flat.png", coloured = d + "coloured.png", zoomed = d + "zoomed.png";
  const std::string picked_window = d + "picked_window.png";
  write_text(d + "script.txt",
             script({"step", "pick 5", "window-screenshot " + picked_window, "show flat on", "show points on",
                     "screenshot " + shaded, "color-by height", "screenshot " + coloured, "zoom 4",
                     "screenshot " + zoomed, "plots " + d + "plots.csv", "quit"}));
  test_run::result r = viewer({"--script", d + "script.txt", inspect_model});
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);
  EXPECT_TRUE(viewer_errors(r.err).empty()) << report(r);
  EXPECT_TRUE(has(r.out, apex_after_one_step)) << report(r);
  expect_scene_shot(shaded);
  ASSERT_TRUE(fs::exists(coloured)) << report(r);
  EXPECT_FALSE(slurp(shaded) == slurp(coloured)) << "color-by height did not change the picture";
  // Step 1 is odd: "even" has no value yet.
  EXPECT_EQ(slurp(d + "plots.csv"), "step,vertices,\"growth, %\"\n0,6,\n1,6,100\n");

  // On the very frame of the pick, the panel shows the picked vertex and
  // is sized for it: its last line is not cut off (Dear ImGui sizes a
  // window from the frame before's content).
  image window = load_png(picked_window);
  ASSERT_TRUE(window.ok());
  EXPECT_TRUE(find_text(window, "vertex 5", is_white, 0, 0, panel_right_limit).found()) << "the pick is not shown";
  text_place last_line =
      find_text(window, "ctrl+click: pick a vertex  esc: stop  ctrl+q: quit", is_light, 0, 0, panel_right_limit);
  EXPECT_TRUE(last_line.found()) << "the panel's last line is cut off on the frame of the pick";
  int bottom = panel_bottom(window);
  EXPECT_GT(bottom, last_line.y + last_line.height) << "the panel ends above its last line";
  EXPECT_LT(bottom, window.height - 1) << "the panel runs off the window";
  // The model is drawn beside the panel as it is on that frame, not under
  // it: the apex (red) and its four neighbours (orange) all show right of
  // the panel.
  int right = panel_right(window);
  ASSERT_GT(right, 300) << "no panel";
  EXPECT_GT(count_colour(window, picked_red, 12, right + 1, 0), 100) << "the picked vertex is not in view";
  EXPECT_GT(count_colour(window, neighbour_orange, 12, right + 1, 0), 4 * 50) << "a neighbour is under the panel";

  // Zoomed in, the model fills the picture but stays left of the colour
  // bar's strip: the bar never covers it.
  image close = load_png(zoomed);
  ASSERT_TRUE(close.ok());
  bar_columns bar = find_colour_bar(close);
  ASSERT_TRUE(bar.found()) << "no colour bar";
  const unsigned char* background = close.at(close.width - 1, 0);
  EXPECT_FALSE(near_colour(close.at(bar.x0 - 40, close.height / 2), background)) << "the model does not fill the view";
  long covered = 0;
  for (int y = 0; y < close.height; ++y)
    for (int x = bar.x0 - 10; x < bar.x0; ++x) covered += !near_colour(close.at(x, y), background);
  EXPECT_EQ(covered, 0) << "the model reaches into the colour bar's strip";
  EXPECT_TRUE(find_text(close, "height", is_dark, bar.x0 - 4, 0).found()) << "the bar's name is covered";
}

// Korn-Spalding draws itself (a render block) and has seven parameters and
// three plots: the panel stays within the window, the picked vertex is
// shown near the top of the panel on the frame of the pick and drawn over
// the model's own drawing, and each slider's value is readable beside the
// slider, not under its grab.
TEST(ViewerInteraction, PanelFitsThePickIsInViewAndHighlightedAndSliderValuesReadable) {
  std::string d = fresh_dir("viewer_panel");
  const std::string window_shot = d + "window.png", scene_shot = d + "scene.png";
  // time_step in [0.001, 0.05]: 0.025 puts the grab in the slider's middle,
  // where a value written on the slider would be.
  write_text(d + "script.txt", script({"step 2", "set time_step=0.025", "pick 10", "window-screenshot " + window_shot,
                                       "screenshot " + scene_shot, "quit"}));
  test_run::result r = viewer({"--script", d + "script.txt", VV_SOURCE_DIR "/examples/korn_spalding.vvp"});
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 0) << report(r);
  EXPECT_TRUE(viewer_errors(r.err).empty()) << report(r);
  EXPECT_TRUE(has(r.out, "vertex 10\n  in meshes: S\n")) << report(r);

  // The picked vertex (red) and its neighbours (orange), over the green
  // walls the model draws.
  image scene = load_png(scene_shot);
  ASSERT_TRUE(scene.ok());
  EXPECT_GT(count_colour(scene, picked_red, 12), 100) << "the picked vertex is not highlighted";
  EXPECT_GT(count_colour(scene, neighbour_orange, 12), 100) << "its neighbours are not highlighted";

  image window = load_png(window_shot);
  ASSERT_TRUE(window.ok());
  int bottom = panel_bottom(window);
  EXPECT_GT(bottom, window.height / 2) << "no panel";
  EXPECT_LT(bottom, window.height - 1) << "the panel runs off the window";
  text_place picked = find_text(window, "vertex 10", is_white, 0, 0, panel_right_limit);
  EXPECT_TRUE(picked.found()) << "the pick is not in view";
  text_place value = find_text(window, "0.025", is_white, 0, 0, panel_right_limit);
  ASSERT_TRUE(value.found()) << "the value of time_step is not readable";
  const unsigned char grab[3] = {61, 133, 224};
  EXPECT_EQ(count_colour(window, grab, 20, value.x - 3, value.y - 3, value.x + value.width + 3,
                         value.y + value.height + 3),
            0)
      << "a slider's grab is on its value";
}

// A function file: control points on the line y = slope x.
std::string function_on(double slope) {
  std::string points;
  for (double x : {0.0, 1.0 / 3, 2.0 / 3, 1.0}) points += std::to_string(x) + " " + std::to_string(slope * x) + "\n";
  return "fver 1 1\nname: growth\nsamples: 100\nflip: off\npoints: 4\n" + points;
}

// Saving a file a file object reads rereads it at once, keeping the step;
// a broken save names its line and the model keeps the last good values.
TEST(ViewerInteraction, SavingAFunctionFileRereadsIt) {
  std::string d = fresh_dir("viewer_reread");
  fs::copy_file(VV_TESTS_DIR "/models/function_file.vvp", d + "model.vvp");
  write_text(d + "growth.func", function_on(1));
  write_text(d + "script.txt", script({"step", "wait 3000", "step", "wait 3000", "step", "quit"}));
  live_viewer v({"--script", d + "script.txt", d + "model.vvp"});
  ASSERT_TRUE(v.wait_for_out("step f(0.5) = 0.5\n", viewer_timeout)) << v.out << v.err;
  replace_file(d + "growth.func", function_on(2));
  ASSERT_TRUE(v.wait_for_out("step f(0.5) = 1\n", 10)) << v.out << v.err;
  replace_file(d + "growth.func", "fver 1 1\nname: growth\nsamples: 100\nflip: off\npoints: 4\n0 0\n1 x\n");
  test_run::result r = v.finish();
  EXPECT_EQ(r.status, 0) << report(r);
  // Three steps: the file's values, the edited ones, and again the edited
  // ones after the broken save; the start block did not run again after the
  // reread (no rewind). (It may have run twice before it: a first build
  // that was quick, as a cached declarations' part makes it, replays start
  // on the optimised build swapped in.)
  ASSERT_NE(r.out.find("reread "), std::string::npos) << report(r);
  EXPECT_LT(r.out.rfind("start f(0.5)"), r.out.find("reread ")) << report(r);
  EXPECT_TRUE(has(r.out, "step f(0.5) = 0.5\nreread " + d + "growth.func\nstep f(0.5) = 1\n")) << report(r);
  std::size_t second = r.out.find("step f(0.5) = 1\n");
  ASSERT_NE(second, std::string::npos) << report(r);
  EXPECT_NE(r.out.find("step f(0.5) = 1\n", second + 1), std::string::npos) << "the broken save changed f\n"
                                                                              << report(r);
  EXPECT_TRUE(error_names(r.err, d + "growth.func:7")) << report(r);
}

}  // namespace
