// Checkpoints as users make them (docs/interpreter.md, "Checkpoints"): K
// steps and --checkpoint, then --resume for the rest, against the run that
// was never interrupted, byte for byte; what a checkpoint cannot hold; and
// the checkpoints a run must refuse: of another program, of an edited one,
// cut short or damaged, each with its message and nothing written.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <vv/io/vtk_files.hpp>

#include "run_interpreter.hpp"
#include "test_files.hpp"

namespace {

const std::string examples = VV_SOURCE_DIR "/examples/";
const std::string test_models = VV_TESTS_DIR "/models/";
const std::string checkpoint_models = VV_TESTS_DIR "/checkpoint_models/";

bool exists(const std::string& path) { return std::filesystem::exists(path); }

test_run::result batch(const std::vector<std::string>& options, const std::string& model) {
  std::vector<std::string> args = {"--batch", "--quiet"};
  args.insert(args.end(), options.begin(), options.end());
  args.push_back(model);
  return test_run::run(test_run::interpreter(args), 300);
}

std::string report(const test_run::result& r) { return "stdout:\n" + r.out + "stderr:\n" + r.err; }

// A run of `steps` steps, straight and in two: `split` steps and a
// checkpoint, then the rest resumed from it.
struct resumed_run {
  std::string name;
  std::string model;
  std::vector<std::string> options;  // the same for every part (--seed, --set)
  unsigned steps = 0, split = 0;
  bool end = false;  // the end block prints: its output is compared too
};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// The straight run's export, plots and (with the end block) output are
// those of the resumed run, byte for byte; returns the straight export.
std::string expect_resuming_changes_nothing(const resumed_run& c) {
  const std::string dir = test_files::scratch_dir() + c.name + "_";
  const std::vector<std::string> end = c.end ? std::vector<std::string>{"--end"} : std::vector<std::string>{};
  test_run::result straight =
      batch(with(with(c.options, {"--steps", std::to_string(c.steps), "--export", dir + "straight.vvm", "--plots",
                                  dir + "straight.csv"}),
                 end),
            c.model);
  EXPECT_EQ(straight.status, 0) << report(straight);
  test_run::result first =
      batch(with(c.options, {"--steps", std::to_string(c.split), "--checkpoint", dir + "part.ckpt"}), c.model);
  EXPECT_EQ(first.status, 0) << report(first);
  test_run::result rest =
      batch(with(with(c.options, {"--resume", dir + "part.ckpt", "--steps", std::to_string(c.steps - c.split),
                                  "--export", dir + "resumed.vvm", "--plots", dir + "resumed.csv"}),
                 end),
            c.model);
  EXPECT_EQ(rest.status, 0) << report(rest);
  const std::string exported = test_files::slurp(dir + "straight.vvm");
  EXPECT_FALSE(exported.empty());
  EXPECT_EQ(exported, test_files::slurp(dir + "resumed.vvm")) << c.name;
  EXPECT_EQ(test_files::slurp(dir + "straight.csv"), test_files::slurp(dir + "resumed.csv")) << c.name;
  if (c.end) {
    EXPECT_EQ(straight.out, rest.out) << c.name;
  }
  return exported;
}

// Every example that draws random numbers (from vv_random(); phyllotaxis
// only with noise): the resumed run draws what the straight one would
// have. Another seed gives another export, so the numbers drawn matter.
TEST(Checkpoint, ResumedExamplesThatDrawRandomNumbersExportAndPlotWhatTheUninterruptedRunDoes) {
  const std::vector<resumed_run> runs = {
      {"terrain", examples + "terrain.vvp", {"--seed", "3"}, 4, 1},
      {"phyllotaxis", examples + "phyllotaxis.vvp", {"--seed", "5", "--set", "noise=0.3"}, 24, 9},
  };
  for (const resumed_run& c : runs) {
    const std::string exported = expect_resuming_changes_nothing(c);
    const std::string other = test_files::scratch_dir() + c.name + "_other_seed.vvm";
    std::vector<std::string> options = c.options;
    options[1] = "4";  // --seed
    test_run::result r = batch(with(options, {"--steps", std::to_string(c.steps), "--export", other}), c.model);
    ASSERT_EQ(r.status, 0) << report(r);
    EXPECT_NE(test_files::slurp(other), exported) << c.name << " does not depend on its seed";
  }
}

// The C library's generators (rand, drand48: vv 1.1 programs) and the
// model's own, drawn from in every step.
TEST(Checkpoint, ResumedRunsDrawFromTheCLibrarysGeneratorsAndTheModelsWhereTheyLeftOff) {
  expect_resuming_changes_nothing({"c_random", test_models + "c_random.vvp", {"--seed", "11"}, 5, 2});
  expect_resuming_changes_nothing({"random_walk", test_models + "random_walk.vvp", {"--seed", "11"}, 5, 2});
}

// Handles in globals, containers and properties, half-edge records, flags,
// old state, mesh properties, labels, a file object changed in memory, an
// engine and a distribution of <random>, plots: the end block prints them
// all, and draws once more from every generator.
TEST(Checkpoint, EveryKindOfStateAModelKeepsComesBackFromACheckpoint) {
  expect_resuming_changes_nothing(
      {"everything", checkpoint_models + "everything_kept.vvp", {"--seed", "4"}, 5, 2, true});
}

// A resumed run saves a checkpoint of its own that resumes as well.
TEST(Checkpoint, ACheckpointOfAResumedRunResumesToo) {
  const std::string model = checkpoint_models + "everything_kept.vvp";
  const std::string dir = test_files::scratch_dir() + "chain_";
  test_run::result straight = batch({"--seed", "9", "--steps", "5", "--end"}, model);
  ASSERT_EQ(straight.status, 0) << report(straight);
  for (const std::vector<std::string>& part :
       {std::vector<std::string>{"--steps", "2", "--checkpoint", dir + "2.ckpt"},
        std::vector<std::string>{"--resume", dir + "2.ckpt", "--steps", "2", "--checkpoint", dir + "4.ckpt"}}) {
    test_run::result r = batch(with({"--seed", "9"}, part), model);
    ASSERT_EQ(r.status, 0) << report(r);
  }
  test_run::result last = batch({"--seed", "9", "--resume", dir + "4.ckpt", "--steps", "1", "--end"}, model);
  ASSERT_EQ(last.status, 0) << report(last);
  EXPECT_EQ(last.out, straight.out);
}

// A time series goes on from a checkpoint: the resumed run's files from
// the checkpoint's step on are the uninterrupted run's, byte for byte (the
// one at the checkpoint's step is the first part's last), and its .pvd
// lists the files it wrote.
TEST(Checkpoint, AResumedTimeSeriesWritesTheFilesOfTheUninterruptedOne) {
  const std::string model = examples + "phyllotaxis.vvp";
  const std::string dir = test_files::scratch_dir() + "series_";
  for (const char* part : {"straight", "first", "resumed"}) std::filesystem::create_directories(dir + part);
  const std::vector<std::string> random = {"--seed", "5", "--set", "noise=0.3", "--every", "5"};
  test_run::result straight =
      batch(with(random, {"--steps", "24", "--export", dir + "straight/p-{step}.vtp"}), model);
  ASSERT_EQ(straight.status, 0) << report(straight);
  test_run::result first = batch(
      with(random, {"--steps", "9", "--export", dir + "first/p-{step}.vtp", "--checkpoint", dir + "9.ckpt"}), model);
  ASSERT_EQ(first.status, 0) << report(first);
  test_run::result resumed = batch(
      with(random, {"--resume", dir + "9.ckpt", "--steps", "15", "--export", dir + "resumed/p-{step}.vtp"}), model);
  ASSERT_EQ(resumed.status, 0) << report(resumed);
  for (const char* step : {"10", "15", "20", "24"}) {
    const std::string expected = test_files::slurp(dir + "straight/p-" + step + ".vtp");
    EXPECT_FALSE(expected.empty()) << step;
    EXPECT_EQ(test_files::slurp(dir + "resumed/p-" + step + ".vtp"), expected) << "step " << step;
  }
  EXPECT_EQ(test_files::slurp(dir + "resumed/p-09.vtp"), test_files::slurp(dir + "first/p-9.vtp"));
  std::vector<std::uint64_t> listed;
  for (const vv::pvd_entry& e : vv::read_pvd(dir + "resumed/p.pvd")) listed.push_back(e.step);
  EXPECT_EQ(listed, (std::vector<std::uint64_t>{9, 10, 15, 20, 24}));
}

// Each global a checkpoint cannot hold is named with its .vvp line, its
// type and why; no checkpoint is written.
TEST(Checkpoint, AGlobalACheckpointCannotHoldIsNamedWithItsLine) {
  const std::string model = checkpoint_models + "cannot_save.vvp";
  const std::string saved = test_files::scratch_dir() + "cannot.ckpt";
  test_run::result r = batch({"--steps", "2", "--checkpoint", saved}, model);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "vvinterpreter: " + model +
                       ": a checkpoint cannot hold the model's whole state: these globals cannot be saved\n" +
                       model + ":8: log_file (FILE*): a pointer (what it points at cannot be saved)\n" + model +
                       ":9: shape (std::function<double(double)>): a function object (what it calls cannot be "
                       "saved)\n" +
                       model + ":10: seen (std::unordered_map<int, double>): an unordered container (a restore "
                               "cannot promise its order; use std::map or std::set)\n" +
                       model + ":14: made (int): a static variable inside a function, which the host cannot reach "
                               "(make it a global)\n");
  EXPECT_FALSE(exists(saved));
}

TEST(Checkpoint, ACheckpointOfAnotherProgramIsRefusedAndNothingIsWritten) {
  const std::string dir = test_files::scratch_dir() + "other_";
  test_run::result saved = batch({"--steps", "1", "--checkpoint", dir + "walk.ckpt"}, test_models + "random_walk.vvp");
  ASSERT_EQ(saved.status, 0) << report(saved);
  test_run::result r = batch({"--resume", dir + "walk.ckpt", "--steps", "1", "--export", dir + "out.vvm"},
                             test_models + "c_random.vvp");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "vvinterpreter: " + dir +
                       "walk.ckpt: a checkpoint of another program (random_walk.vvp), not of c_random.vvp: it "
                       "cannot be resumed by this one\n");
  EXPECT_FALSE(exists(dir + "out.vvm"));
}

// The program lives beside the test cache, at the same path every run, so
// that both its versions are compiled once.
TEST(Checkpoint, ACheckpointOfTheProgramBeforeAnEditIsRefused) {
  const std::string dir = VV_TEST_CACHE "/../checkpoint_edited/";
  std::filesystem::create_directories(dir);
  const std::string program =
      "vertex { double x; };\nmesh S;\n"
      "start { vertex a, b; make {b} nb_of a; make {a} nb_of b; add a to S; add b to S; }\n"
      "step { forall v in S v$x += 1; }\n";
  const std::string model = dir + "two.vvp";
  auto write = [&model](const std::string& text) { std::ofstream(model, std::ios::binary | std::ios::trunc) << text; };
  std::filesystem::remove(dir + "two.ckpt");
  std::filesystem::remove(dir + "out.vvm");
  write(program);
  test_run::result saved = batch({"--steps", "1", "--checkpoint", dir + "two.ckpt"}, model);
  ASSERT_EQ(saved.status, 0) << report(saved);
  write(program + "// edited\n");
  test_run::result r = batch({"--resume", dir + "two.ckpt", "--steps", "1", "--export", dir + "out.vvm"}, model);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "vvinterpreter: " + dir +
                       "two.ckpt: a checkpoint of two.vvp as it was before it was edited: the program has changed "
                       "since, and its state cannot be resumed by the new one (run it from its start)\n");
  EXPECT_FALSE(exists(dir + "out.vvm"));
}

// A checkpoint cut short, damaged, or no checkpoint at all: one line naming
// the file and what is wrong, status 1, and none of the run's files.
TEST(Checkpoint, ATruncatedOrDamagedCheckpointIsRefusedWithItsFileAndNothingIsWritten) {
  const std::string dir = test_files::scratch_dir() + "damaged_";
  const std::string model = test_models + "random_walk.vvp";
  test_run::result saved = batch({"--steps", "2", "--checkpoint", dir + "good.ckpt"}, model);
  ASSERT_EQ(saved.status, 0) << report(saved);
  const std::string good = test_files::slurp(dir + "good.ckpt");
  const std::size_t body = good.find("\n\n") + 2;
  const std::size_t state = good.size() - body;
  std::string flipped = good;
  flipped[body + state / 2] = static_cast<char>(flipped[body + state / 2] ^ 0x10);
  struct damage {
    std::string name, bytes, message;
  };
  const std::vector<damage> cases = {
      {"half", good.substr(0, body + state / 2),
       "the checkpoint is truncated: it holds " + std::to_string(state / 2) + " of the " + std::to_string(state) +
           " bytes of its state"},
      {"header", good.substr(0, 40), "the checkpoint is truncated: it ends in its header"},
      {"empty", "", "the checkpoint is truncated: the file is empty"},
      {"flipped", flipped, "the checkpoint is damaged: its state does not match its checksum"},
      {"longer", good + "x", "the checkpoint is damaged: 1 bytes follow its state"},
      {"mesh", test_files::slurp(VV_SOURCE_DIR "/models/pyramid.vvm"),
       "not a vv checkpoint (it does not begin with \"vv checkpoint\")"},
  };
  for (const damage& d : cases) {
    const std::string path = test_files::write_scratch("damaged_" + d.name + ".ckpt", d.bytes);
    const std::string out = dir + d.name + "_out";
    test_run::result r = batch({"--resume", path, "--steps", "1", "--export", out + ".vvm", "--plots", out + ".csv",
                                "--checkpoint", out + ".ckpt"},
                               model);
    EXPECT_EQ(r.status, 1) << d.name;
    EXPECT_EQ(r.err, "vvinterpreter: " + path + ": " + d.message + "\n") << d.name;
    for (const char* ext : {".vvm", ".csv", ".ckpt"}) EXPECT_FALSE(exists(out + ext)) << d.name << ext;
  }
}

// The viewer opens a checkpoint (--resume), saves one and resumes one with
// its commands (what its panel's buttons give), as batch does.
TEST(Checkpoint, TheViewerOpensSavesAndResumesCheckpointsAsBatchDoes) {
  const std::string model = test_models + "random_walk.vvp";
  const std::string dir = test_files::scratch_dir() + "viewer_";
  test_run::result straight = batch({"--seed", "2", "--steps", "3", "--export", dir + "straight.vvm"}, model);
  ASSERT_EQ(straight.status, 0) << report(straight);
  test_run::result first = batch({"--seed", "2", "--steps", "1", "--checkpoint", dir + "1.ckpt"}, model);
  ASSERT_EQ(first.status, 0) << report(first);
  const std::string script = test_files::write_scratch(
      "viewer.script", "step 2\nexport S " + dir + "opened.vvm\ncheckpoint " + dir + "3.ckpt\nresume " + dir +
                           "1.ckpt\nstep 2\nexport S " + dir + "resumed.vvm\nquit\n");
  test_run::result r = test_run::run(test_run::in_virtual_display(test_run::interpreter(
                                         {"--seed", "2", "--resume", dir + "1.ckpt", "--script", script, model})),
                                     120);
  ASSERT_EQ(r.status, 0) << report(r);
  const std::string expected = test_files::slurp(dir + "straight.vvm");
  EXPECT_EQ(test_files::slurp(dir + "opened.vvm"), expected);
  EXPECT_EQ(test_files::slurp(dir + "resumed.vvm"), expected);
  EXPECT_NE(r.out.find("resumed " + model + " from " + dir + "1.ckpt\n"), std::string::npos) << r.out;
  const std::string saved = test_files::slurp(dir + "3.ckpt");
  EXPECT_EQ(saved.substr(0, saved.find("program-hash")), "vv checkpoint 1\nprogram random_walk.vvp\n");
  EXPECT_NE(saved.find("\nstep 3\n"), std::string::npos);
}

TEST(Checkpoint, TheViewerSavesCheckpointsWithItsCommandNotWithTheOption) {
  test_run::result r = test_run::run(test_run::interpreter({"--checkpoint", "x.ckpt", test_models + "random_walk.vvp"}));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("vvinterpreter: --checkpoint is for --batch (the viewer saves checkpoints with its panel or "
                       "the command checkpoint FILE)\n"),
            std::string::npos)
      << r.err;
}

}  // namespace
