// Batch mode's events: --action NAME@STEP and --pick-action LABEL@STEP run
// the program's actions and pick block after the steps they name, and
// --replay FILE runs a session the viewer saved; both routes come to the
// same state. A failing or crashing event ends the run naming it, once.
// The model, state_models/lifts.vvp, says what each event does.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "run_interpreter.hpp"
#include "test_files.hpp"

namespace {

const std::string lifts = VV_TESTS_DIR "/state_models/lifts.vvp";

test_run::result batch(std::vector<std::string> args) {
  args.insert(args.begin(), "--batch");
  args.push_back(lifts);
  return test_run::run(test_run::interpreter(args), 280);
}

std::string report(const test_run::result& r) { return "status " + std::to_string(r.status) + "\n" + r.out + r.err; }

// "lifts.vvp:N", N the line of the model that holds `needle`.
std::string model_line(const std::string& needle) {
  std::string text = test_files::slurp(lifts);
  std::size_t at = text.find(needle);
  return "lifts.vvp:" + std::to_string(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n') + 1);
}

int count_of(const std::string& text, const std::string& part) {
  int n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

// Step 1, Lift, step 2, vertex 2 picked, Lift again (by hand: start's vertex
// at 0, step 1's at x = 1, step 2's at x = 2).
const char* const lifted_and_picked = "<mesh>\n  <v pos=\"0 2 0\" nb=\"\" />\n  <v pos=\"1 2 5\" nb=\"\" />\n"
                                      "  <v pos=\"2 1 0\" nb=\"\" />\n</mesh>\n";

TEST(BatchEvents, ActionsAndPicksRunAfterTheStepsTheyName) {
  std::string out = test_files::scratch_dir() + "events.vvm";
  test_run::result r = batch({"--steps", "2", "--action", "Lift@1", "--pick-action", "2@2", "--action", "Lift@2",
                              "--export", out});
  ASSERT_EQ(r.status, 0) << report(r);
  EXPECT_EQ(test_files::slurp(out), lifted_and_picked);
  EXPECT_TRUE(r.out.find("2 steps in") != std::string::npos) << report(r);
}

TEST(BatchEvents, AReplayedSessionComesToTheSameState) {
  std::string session = test_files::write_scratch("lifts.vvs", "# a session\nstep 1\naction Lift\nstep 1\n"
                                                            "pick-action 2\naction \"Lift\"\n");
  std::string out = test_files::scratch_dir() + "replayed.vvm";
  test_run::result r = batch({"--replay", session, "--export", out});
  ASSERT_EQ(r.status, 0) << report(r);
  EXPECT_EQ(test_files::slurp(out), lifted_and_picked);
  // --steps go on from where the session ended.
  out = test_files::scratch_dir() + "replayed_and_stepped.vvm";
  r = batch({"--replay", session, "--steps", "1", "--export", out});
  ASSERT_EQ(r.status, 0) << report(r);
  EXPECT_EQ(test_files::slurp(out), "<mesh>\n  <v pos=\"0 2 0\" nb=\"\" />\n  <v pos=\"1 2 5\" nb=\"\" />\n"
                                    "  <v pos=\"2 1 0\" nb=\"\" />\n  <v pos=\"3 0 0\" nb=\"\" />\n</mesh>\n");
}

TEST(BatchEvents, AnEventThatFailsEndsTheRunNamingIt) {
  test_run::result r = batch({"--steps", "1", "--action", "Lift and fail@1"});
  EXPECT_EQ(r.status, 1) << report(r);
  EXPECT_NE(r.err.find(model_line("none$pos =") + ": $: property access on the null vertex (in action \"Lift and fail\")"),
            std::string::npos)
      << report(r);
  r = batch({"--action", "Nope@0"});
  EXPECT_EQ(r.status, 1) << report(r);
  EXPECT_NE(r.err.find("the model has no action \"Nope\" (it has \"Lift\", \"Lift and fail\", \"Crash\")"),
            std::string::npos)
      << report(r);
  r = batch({"--steps", "1", "--pick-action", "2@3"});
  EXPECT_EQ(r.status, 1) << report(r);
  EXPECT_EQ(r.err, "vvinterpreter: --pick-action 2@3: the run goes from step 0 to step 1\n");
}

// A crash while a session is replayed names the event, once: no second run.
TEST(BatchEvents, ACrashDuringAReplayStopsAtThatEvent) {
  std::string session = test_files::write_scratch("crash.vvs", "step 1\naction Lift\naction Crash\nstep 2\n");
  test_run::result r = batch({"--replay", session});
  EXPECT_EQ(r.status, 1) << report(r);
  EXPECT_EQ(count_of(r.err, "crashed with SIGSEGV"), 1) << report(r);
  EXPECT_NE(r.err.find(model_line("*nowhere() = 3;") + ": crashed with SIGSEGV in action \"Crash\" (replaying event 3 of 4 of " +
                       session + ": action Crash)"),
            std::string::npos)
      << report(r);
}

TEST(BatchEvents, ASessionLineThatIsNoEventIsAnErrorNamingIt) {
  std::string session = test_files::write_scratch("bad.vvs", "step 1\nscreenshot x.png\n");
  test_run::result r = batch({"--replay", session});
  EXPECT_EQ(r.status, 1) << report(r);
  EXPECT_EQ(r.err, "vvinterpreter: " + session +
                       ":2: 'screenshot' is not one of the model's events (step, end, reread, set, action, "
                       "pick-action), rewind or resume\n");
}

}  // namespace
