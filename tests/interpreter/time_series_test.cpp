// Time series as users make them: `--every K` with {step} in --export and
// --screenshot names (exact file lists, the zero padding of the last step's
// width), the .pvd collection read back by VTK (python3-vtk9) with its
// timesteps and each file's point count, one framing for a series'
// screenshots (a growing model's picture grows), movies read back by
// ffprobe (frame count, size) and never left half written, series in a
// sweep's run folders, the viewer's `record` command, and every refusal
// with its text.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "run_interpreter.hpp"
#include "test_files.hpp"
#include "viewer_harness.hpp"
#include "vtk_read_back.hpp"

namespace fs = std::filesystem;
using test_files::slurp;
using viewer_harness::fresh_dir;
using viewer_harness::load_png;
using viewer_harness::object_box;
using vtk_read_back::read_with_vtk;

namespace {

const std::string loop_vvp = VV_SOURCE_DIR "/examples/loop.vvp";
// A ring of 12 cells that grows outward every step and divides its long
// walls: it only grows (its bounds at a step hold those of every step before).
const std::string ring_vvp = VV_SOURCE_DIR "/examples/growing_ring.vvp";

test_run::result vvi(const std::vector<std::string>& args, int timeout = 280) {
  return test_run::run(test_run::interpreter(args), timeout);
}

void batch_ok(std::vector<std::string> args) {
  args.insert(args.begin(), "--batch");
  test_run::result r = vvi(args);
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.status, 0) << "stderr: " << r.err << "\nstdout: " << r.out;
}

//! The names in a folder, sorted.
std::set<std::string> names_in(const std::string& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.insert(e.path().filename().string());
  return names;
}

//! What one of the ring's plotted series was at a step (its plots CSV: a
//! header, then step,cells,perimeter rows).
std::string cells_at(const std::string& plots_csv, unsigned step) {
  std::string text = slurp(plots_csv);
  std::string row = "\n" + std::to_string(step) + ",";
  std::size_t at = text.find(row);
  if (at == std::string::npos) return "";
  at += row.size();
  return text.substr(at, text.find(',', at) - at);
}

// ---- batch series ----

TEST(TimeSeries, ExportsAreNamedByTheStepPaddedToTheLastStepAndListedInAPvd) {
  const std::string dir = fresh_dir("series_vtp");
  ASSERT_NO_FATAL_FAILURE(batch_ok({"--steps", "12", "--every", "5", "--export", dir + "ring-{step}.vtp", "--plots",
                                    dir + "plots.csv", ring_vvp}));
  // After start, at 5 and 10, and the last step; two digits, as 12 has.
  EXPECT_EQ(names_in(dir), (std::set<std::string>{"ring-00.vtp", "ring-05.vtp", "ring-10.vtp", "ring-12.vtp",
                                                   "ring.pvd", "plots.csv"}));
  // VTK reads every file the collection lists; each has the vertices the
  // model counted at that step.
  vtk_read_back::read_back pvd = read_with_vtk(dir + "ring.pvd");
  std::vector<std::string> expected;
  for (unsigned step : {0u, 5u, 10u, 12u}) {
    char name[16];
    std::snprintf(name, sizeof name, "ring-%02u.vtp", step);
    expected.push_back(std::to_string(step) + " " + name + " " + cells_at(dir + "plots.csv", step));
  }
  EXPECT_EQ(pvd.datasets, expected);
  EXPECT_EQ(cells_at(dir + "plots.csv", 0), "12");  // control: the table has the counts
}

TEST(TimeSeries, LoopSeriesHasTheVertexCountsOfLoopSubdivision) {
  const std::string dir = fresh_dir("series_loop");
  ASSERT_NO_FATAL_FAILURE(batch_ok({"--steps", "3", "--every", "1", "--export", dir + "loop_{step}.vtp", loop_vvp}));
  EXPECT_EQ(names_in(dir),
            (std::set<std::string>{"loop_0.vtp", "loop_1.vtp", "loop_2.vtp", "loop_3.vtp", "loop.pvd"}));
  // The double pyramid (V 6, E 12, F 8); each Loop step adds a vertex per
  // edge and makes four triangles of one: V 6, 18, 66, 258.
  EXPECT_EQ(read_with_vtk(dir + "loop.pvd").datasets,
            (std::vector<std::string>{"0 loop_0.vtp 6", "1 loop_1.vtp 18", "2 loop_2.vtp 66", "3 loop_3.vtp 258"}));
  EXPECT_EQ(read_with_vtk(dir + "loop_3.vtp").cells["polys"].size(), 512u);
}

TEST(TimeSeries, StepInANameWithoutEveryIsTheLastStep) {
  const std::string dir = fresh_dir("series_one_file");
  ASSERT_NO_FATAL_FAILURE(batch_ok({"--steps", "2", "--export", dir + "loop-{step}.obj", loop_vvp}));
  EXPECT_EQ(names_in(dir), (std::set<std::string>{"loop-2.obj"}));
}

TEST(TimeSeries, ScreenshotsOfASeriesKeepOneFramingSoGrowthShows) {
  const std::string dir = fresh_dir("series_framing");
  ASSERT_NO_FATAL_FAILURE(batch_ok({"--steps", "20", "--every", "10", "--screenshot", dir + "f-{step}.png", "--size",
                                    "160x120", ring_vvp}));
  EXPECT_EQ(names_in(dir), (std::set<std::string>{"f-00.png", "f-10.png", "f-20.png"}));
  viewer_harness::box b0 = object_box(load_png(dir + "f-00.png")), b10 = object_box(load_png(dir + "f-10.png")),
                      b20 = object_box(load_png(dir + "f-20.png"));
  ASSERT_FALSE(b0.empty());
  // The ring grows by about 4% a step: in one framing its picture grows.
  EXPECT_LT(b0.width() + 8, b10.width());
  EXPECT_LT(b10.width() + 8, b20.width());
  EXPECT_LT(b0.height() + 8, b20.height());
  // The framing is the box that holds every frame's ring: the last one's,
  // as a single screenshot of step 20 has it.
  ASSERT_NO_FATAL_FAILURE(
      batch_ok({"--steps", "20", "--screenshot", dir + "single.png", "--size", "160x120", ring_vvp}));
  EXPECT_EQ(slurp(dir + "f-20.png"), slurp(dir + "single.png"));
  // --frame gives the box: the same ring in a box twice as large is half as wide.
  ASSERT_NO_FATAL_FAILURE(batch_ok({"--steps", "0", "--every", "1", "--screenshot", dir + "framed-{step}.png",
                                    "--size", "160x120", "--frame", "-2", "-2", "0", "2", "2", "0", ring_vvp}));
  ASSERT_NO_FATAL_FAILURE(batch_ok({"--steps", "0", "--every", "1", "--screenshot", dir + "half-{step}.png", "--size",
                                    "160x120", "--frame", "-1", "-1", "0", "1", "1", "0", ring_vvp}));
  int framed = object_box(load_png(dir + "framed-0.png")).width(), half = object_box(load_png(dir + "half-0.png")).width();
  EXPECT_NEAR(2.0 * framed, half, 3.0);
}

// ---- movies ----

//! ffprobe's "frames,width,height" of a video file's first stream.
std::string probe(const std::string& movie) {
  test_run::result r = test_run::run({"ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0",
                                      "-show_entries", "stream=nb_read_frames,width,height,codec_name", "-of",
                                      "csv=p=0", movie});
  EXPECT_EQ(r.status, 0) << r.err;
  while (!r.out.empty() && r.out.back() == '\n') r.out.pop_back();
  return r.out;
}

TEST(TimeSeries, MovieHasAFrameForEveryFileOfTheSeries) {
  const std::string dir = fresh_dir("series_movie");
  ASSERT_NO_FATAL_FAILURE(batch_ok({"--steps", "12", "--every", "5", "--screenshot", dir + "ring.mp4", "--size",
                                    "160x120", ring_vvp}));
  EXPECT_EQ(names_in(dir), (std::set<std::string>{"ring.mp4"}));  // no temporary, no frame left
  // Steps 0, 5, 10 and 12.
  EXPECT_EQ(probe(dir + "ring.mp4"), "h264,160,120,4");
}

TEST(TimeSeries, MovieOfARunThatCrashesIsNotWritten) {
  const std::string dir = fresh_dir("series_movie_crash");
  test_run::result r = vvi({"--batch", "--steps", "4", "--every", "1", "--screenshot", dir + "crash.mp4",
                            VV_TESTS_DIR "/fault_models/crash_in_step2.vvp"});
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("crashed with SIGSEGV in step 2"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(dir)) << "left: " << *names_in(dir).begin();
}

TEST(TimeSeries, MovieIntoAMissingFolderFailsNamingItAndLeavesNothing) {
  const std::string dir = fresh_dir("series_movie_missing_folder");
  test_run::result r =
      vvi({"--batch", "--steps", "2", "--every", "1", "--screenshot", dir + "no/m.mp4", "--size", "64x48", ring_vvp});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "vvinterpreter: " + dir + "no/m.mp4: cannot write file: No such file or directory\n");
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(TimeSeries, MovieWithoutFfmpegIsRefusedBeforeTheRun) {
  const std::string dir = fresh_dir("series_no_ffmpeg");
  test_run::result r = test_run::run({"env", "PATH=" + dir, VV_INTERPRETER, "--cache", VV_TEST_CACHE, "--batch",
                                      "--every", "2", "--screenshot", dir + "m.mp4", ring_vvp});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "vvinterpreter: " + dir + "m.mp4: a movie is made by ffmpeg, which is not installed (no ffmpeg on "
                   "the PATH); install it (Debian package ffmpeg), or write the frames as pictures: --screenshot " +
                       dir + "m-{step}.png\n");
  EXPECT_TRUE(fs::is_empty(dir));
}

// ---- sweeps ----

TEST(TimeSeries, EachRunOfASweepWritesItsSeriesInItsFolder) {
  const std::string dir = fresh_dir("series_sweep");
  test_run::result r = vvi({"--sweep", "rate=0.02,0.04", "--steps", "4", "--every", "2", "--export",
                            "ring-{step}.vtp", "--jobs", "2", "--out", dir + "sweep", ring_vvp});
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* run : {"run-0001", "run-0002"}) {
    std::string folder = dir + "sweep/" + run + "/";
    std::set<std::string> names = names_in(folder);
    for (const char* file : {"ring-0.vtp", "ring-2.vtp", "ring-4.vtp", "ring.pvd"})
      EXPECT_EQ(names.count(file), 1u) << folder << file;
    std::vector<std::string> expected;
    for (unsigned step : {0u, 2u, 4u})
      expected.push_back(std::to_string(step) + " ring-" + std::to_string(step) + ".vtp " +
                         cells_at(folder + "plots.csv", step));
    EXPECT_EQ(read_with_vtk(folder + "ring.pvd").datasets, expected);
  }
}

// ---- the viewer ----

TEST(TimeSeries, ViewerRecordsTheSameSeriesWhileItSteps) {
  const std::string dir = fresh_dir("series_viewer");
  viewer_harness::write_text(dir + "s.txt", viewer_harness::script({
                                                "record 5 " + dir + "ring-{step}.vtp",
                                                "record 5 " + dir + "f-{step}.png 2",
                                                "record 5 " + dir + "ring.mp4",
                                                "step 12",
                                                "record off",
                                                "plots " + dir + "plots.csv",
                                                "record 5 " + dir + "bad.vtp",
                                                "quit",
                                            }));
  test_run::result r = test_run::run(
      test_run::in_virtual_display(test_run::interpreter({"--script", dir + "s.txt", ring_vvp})),
      viewer_harness::viewer_timeout);
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.status, 0) << r.err;
  // Now, at 5 and 10, and at 12 where the recording stopped; {step} five
  // digits wide (the viewer cannot know the last step), or as the command says.
  EXPECT_EQ(names_in(dir), (std::set<std::string>{"s.txt", "plots.csv", "ring-00000.vtp", "ring-00005.vtp",
                                                   "ring-00010.vtp", "ring-00012.vtp", "ring.pvd", "f-00.png",
                                                   "f-05.png", "f-10.png", "f-12.png", "ring.mp4"}));
  std::vector<std::string> expected;
  for (unsigned step : {0u, 5u, 10u, 12u}) {
    char name[24];
    std::snprintf(name, sizeof name, "ring-%05u.vtp", step);
    expected.push_back(std::to_string(step) + " " + name + " " + cells_at(dir + "plots.csv", step));
  }
  EXPECT_EQ(read_with_vtk(dir + "ring.pvd").datasets, expected);
  // The view does not follow the ring while it records: its picture grows.
  EXPECT_LT(object_box(load_png(dir + "f-00.png")).width() + 40, object_box(load_png(dir + "f-12.png")).width());
  // The movie's frames are the scene's pictures (the window without the panel).
  EXPECT_EQ(probe(dir + "ring.mp4"), "h264," + std::to_string(viewer_harness::window_width) + "," +
                                         std::to_string(viewer_harness::window_height) + ",4");
  EXPECT_NE(r.err.find("vvinterpreter: record " + dir +
                       "bad.vtp: the name has no {step}, so each file would replace the one before; write it as " +
                       dir + "bad-{step}.vtp"),
            std::string::npos)
      << r.err;
}

// ---- refusals ----

struct refusal {
  std::vector<std::string> args;
  std::string message;
};

TEST(TimeSeries, BadSeriesOptionsAreRefusedSayingWhatToDo) {
  const std::string m = ring_vvp;
  const refusal cases[] = {
      {{"--every", "0", "--export", "a-{step}.vtp"}, "--every needs a number of steps (1 or more)"},
      {{"--every", "3", "--export", "a.vtp"},
       "--every 3: --export a.vtp has no {step} in its name, so each file would replace the one before; write it "
       "as a-{step}.vtp"},
      {{"--every", "3", "--export", "a-{step}.vtp", "--screenshot", "out/b.png"},
       "--every 3: --screenshot out/b.png has no {step} in its name, so each file would replace the one before; "
       "write it as out/b-{step}.png"},
      {{"--every", "3"},
       "--every 3 writes the files of --export and --screenshot every 3 steps; give one of them, with {step} in "
       "its name (e.g. --export mesh-{step}.vtp)"},
      {{"--screenshot", "m.mp4"}, "--screenshot m.mp4: a movie needs --every K (a frame after start and every K steps)"},
      {{"--every", "2", "--screenshot", "m-{step}.mp4"},
       "--screenshot m-{step}.mp4: a movie is one file; leave {step} out of its name"},
      {{"--frame", "0", "0", "0", "1", "1"}, "--frame needs six numbers: XMIN YMIN ZMIN XMAX YMAX ZMAX"},
      {{"--frame", "0", "2", "0", "1", "1", "1"}, "--frame: YMAX is below YMIN"},
      {{"--fps", "0"}, "--fps needs a number of frames a second (1 to 240)"},
  };
  for (const refusal& c : cases) {
    std::vector<std::string> args = {"--batch"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    args.push_back(m);
    test_run::result r = vvi(args);
    EXPECT_EQ(r.status, 2) << c.message;
    EXPECT_EQ(r.err.substr(0, r.err.find('\n')), "vvinterpreter: " + c.message);
  }
  // The viewer records with its Record section, not with --every.
  test_run::result r = vvi({"--every", "2", "--export", "a-{step}.vtp", m});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.substr(0, r.err.find('\n')),
            "vvinterpreter: --every 2 is for --batch; the viewer records series with its Record section or the "
            "script command record");
}

}  // namespace
