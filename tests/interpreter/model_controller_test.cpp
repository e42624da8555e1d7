// The model controller in-process (vvinterpreter/control), on real models
// compiled once per test executable (state_models/), its jobs run at once
// on the test's thread: the event log it keeps, replays that come back to
// the same state (the same exported bytes), the state record told before
// every job, an error that brings the model back to its last good state, a
// replay that stops at the event that fails, checkpoints resumed, and
// --script's order.
#include "controller_harness.hpp"

namespace {

using namespace controller_harness;

TEST(ModelController, StepsAreOneEventOfTheLogAndOfTheRecord) {
  controlled m("history.vvp");
  m.run("step");
  m.run("step 2");
  EXPECT_EQ(m.c.facts().steps, 3u);
  EXPECT_EQ(m.c.log().text(), "step 3\n");
  EXPECT_EQ(m.c.record().log.text(), "step 3\n");
  EXPECT_EQ(m.view.records.back().log.text(), "step 3\n");
  EXPECT_EQ(std::count(m.view.changes.begin(), m.view.changes.end(), vvi::model_change::stepped), 3);
  EXPECT_TRUE(m.view.errors.empty());
}

// A crash in a job must find the record without the job's event and with
// the script's position past the command that asked for it.
TEST(ModelController, TheRecordIsToldBeforeEachJobStarts) {
  controlled m("history.vvp");
  m.run("step");
  m.c.set_script_position(4);
  m.run("end");
  ASSERT_EQ(m.jobs.started.back(), "end");
  const vvi::state_record& told = m.jobs.told.back();
  EXPECT_EQ(told.script_pos, 4u);
  EXPECT_EQ(told.log.text(), "step 1\n");
  EXPECT_EQ(m.view.records.back().log.text(), "step 1\nend\n");
}

TEST(ModelController, AnErrorInAStepBringsTheModelBackToItsLastGoodState) {
  controlled m("half_done_step.vvp");
  m.run("step 3");
  ASSERT_EQ(m.view.errors.size(), 1u);
  EXPECT_NE(m.view.errors[0].find("make: vertex 4 is listed twice for vertex 6 (in step 3)"), std::string::npos)
      << m.view.errors[0];
  EXPECT_EQ(m.c.facts().steps, 2u);
  EXPECT_EQ(m.c.log().text(), "step 2\n");
  ASSERT_EQ(m.c.facts().meshes.size(), 1u);
  EXPECT_EQ(m.c.facts().meshes[0].second, 2u);
  ASSERT_EQ(m.c.facts().plots.size(), 1u);
  EXPECT_EQ(m.c.facts().plots[0].last, 2);
  command e = command::with_path(command::export_mesh, test_files::scratch_dir() + "restored.vvm");
  m.run(e);
  EXPECT_EQ(vertices_in(test_files::slurp(e.path)), 2);
  EXPECT_EQ(m.view.said.back(), "wrote " + e.path);
  EXPECT_NE(std::find(m.view.said.begin(), m.view.said.end(),
                      "restored " + m.o.model + " to step 2, its last good state"),
            m.view.said.end());
}

TEST(ModelController, AReplayStopsAtTheEventThatFails) {
  controlled m("half_done_step.vvp", log_of("step 5\nend\n"));
  ASSERT_EQ(m.view.errors.size(), 1u);
  EXPECT_NE(m.view.errors[0].find("; the replay stopped at event 1 of 2 (step 5)"), std::string::npos)
      << m.view.errors[0];
  EXPECT_EQ(m.c.facts().steps, 2u);
  EXPECT_EQ(m.c.log().text(), "step 2\n");
  // Not half done: replayed again to step 2.
  EXPECT_EQ(m.view.said.back(), "restored " + m.o.model + " to step 2, where the replay stopped");
  EXPECT_EQ(m.c.facts().meshes[0].second, 2u);
  // Step 3 fails again, and the model comes back to step 2 again.
  m.run("step");
  EXPECT_EQ(m.view.errors.size(), 2u);
  EXPECT_EQ(m.c.facts().steps, 2u);
}

// Everything done between the steps, replayed on a fresh instance: the
// same vertices at the same places.
TEST(ModelController, ReplayingTheLogGivesTheSameExport) {
  controlled first("history.vvp");
  for (const char* line : {"step", "set spacing=3", "reread", "step", "end"}) first.run(line);
  EXPECT_TRUE(first.view.errors.empty());
  std::string before = first.exported("before.vvm");
  EXPECT_EQ(before, "<mesh>\n  <v pos=\"0 0 0\" nb=\"\" />\n  <v pos=\"1 0.5 0\" nb=\"\" />\n"
                    "  <v pos=\"4 0.5 0\" nb=\"\" />\n  <v pos=\"0 -1 0\" nb=\"\" />\n</mesh>\n");
  EXPECT_EQ(first.c.log().text(), "step 1\nset spacing=3\nreread\nstep 1\nend\n");
  controlled again("history.vvp", first.c.log());
  EXPECT_EQ(again.exported("after.vvm"), before);
  EXPECT_TRUE(again.c.log() == first.c.log());
}

// Regression: the viewer's first load started from an empty log, so the
// values given with --set never reached the model.
TEST(ModelController, TheFirstLoadStartsWithTheCommandLinesValues) {
  vvi::options o = options_for("history.vvp");
  o.parameter_values = {{"spacing", "3"}};
  recording_view view;
  recording_jobs jobs{view};
  vvi::model_controller c(o, jobs, view, {}, {});
  c.submit(command::of(command::reload));  // the viewer's first build
  for (int i = 0; i < 6000 && (c.building() || !c.idle()); ++i) {
    c.poll(0);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  c.submit(command::of(command::step));
  c.poll(0);
  EXPECT_EQ(c.log().text(), "set spacing=3\nrewind\nstep 1\n");
  std::string path = test_files::scratch_dir() + "first_load_set.vvm";
  command e = command::with_path(command::export_mesh, path);
  e.name = "S";
  c.submit(e);
  c.poll(0);
  controlled given("history.vvp", log_of("set spacing=3\nrewind\nstep 1\n"));
  controlled plain("history.vvp", log_of("step 1\n"));
  EXPECT_EQ(test_files::slurp(path), given.exported("first_load_given.vvm"));
  EXPECT_NE(test_files::slurp(path), plain.exported("first_load_plain.vvm"));
}

TEST(ModelController, AReloadReplaysTheLog) {
  controlled m("history.vvp");
  for (const char* line : {"step", "set spacing=3", "reread", "step", "end"}) m.run(line);
  std::string before = m.exported("before_reload.vvm");
  m.reload();
  EXPECT_EQ(m.view.said.back(), "reloaded " + m.o.model + " (cached)");
  EXPECT_EQ(m.exported("after_reload.vvm"), before);
  EXPECT_EQ(m.c.facts().steps, 2u);
}

TEST(ModelController, RewindOnChangeRunsTheModelAgainWithTheNewValueFromStart) {
  controlled m("history.vvp");
  m.run("rewind-on-change on");
  m.run("step 2");
  m.run("set spacing=3");
  EXPECT_EQ(m.c.log().text(), "set spacing=3\nrewind\nstep 2\n");
  EXPECT_EQ(m.c.facts().steps, 2u);
  controlled fresh("history.vvp", log_of("set spacing=3\nrewind\nstep 2\n"));
  EXPECT_EQ(m.exported("changed.vvm"), fresh.exported("fresh.vvm"));
}

TEST(ModelController, ARewindStartsTheLogAgainWithTheValuesSet) {
  controlled m("history.vvp");
  m.run("step");
  m.run("set spacing=2");
  m.run("rewind");
  EXPECT_EQ(m.c.facts().steps, 0u);
  EXPECT_EQ(m.c.log().text(), "set spacing=2\nrewind\n");
  EXPECT_EQ(m.view.said.back(), "rewound " + m.o.model);
}

TEST(ModelController, ASavedSessionIsTheLogInTheCommandLanguage) {
  controlled m("history.vvp");
  for (const char* line : {"step 2", "set spacing=3", "end"}) m.run(line);
  std::string path = test_files::scratch_dir() + "saved.vvs";
  m.run(command::with_path(command::save_session, path));
  std::string text = test_files::slurp(path);
  EXPECT_EQ(text.substr(text.find('\n') + 1), "step 2\nset spacing=3\nend\n");
  vvi::event_log read;
  std::string error;
  ASSERT_TRUE(vvi::event_log::parse(text, path, read, error)) << error;
  EXPECT_TRUE(read == m.c.log());
}

TEST(ModelController, AfterARestartTheModelComesBackThroughItsLog) {
  controlled first("history.vvp");
  for (const char* line : {"step", "set spacing=3", "step", "end"}) first.run(line);
  vvi::state_record from = first.c.record();
  from.restarted = true;
  controlled again("history.vvp", {}, from);
  again.reload();
  EXPECT_EQ(again.c.facts().steps, 2u);
  EXPECT_EQ(again.exported("restarted.vvm"), first.exported("first.vvm"));
}

TEST(ModelController, ABuildThatCrashedOnItsWayInIsNotLoadedAgain) {
  vvi::state_record from;
  from.restarted = true;
  from.bad_plugin = built("history.vvp").plugin;
  controlled m("history.vvp", {}, from);
  m.reload();
  EXPECT_FALSE(m.c.facts().loaded);
  EXPECT_EQ(m.c.status(), "no model: it crashed while loading; edit it to try again");
}

// The viewer's checkpoint and resume commands (its panel gives them): the
// model resumed goes on as the one saved would have, also with the
// function its step 1 changed in memory, and its log starts at the
// checkpoint, so a replay of the log comes back to the same state.
TEST(ModelController, AResumedCheckpointGoesOnAsTheSavedModelWouldHave) {
  controlled m("history.vvp");
  m.run("step");
  const std::string path = test_files::scratch_dir() + "history.ckpt";
  m.run(command::with_path(command::checkpoint, path));
  EXPECT_EQ(m.view.errors, std::vector<std::string>{});
  m.run("step 2");
  const std::string straight = m.exported("straight.vvm");
  m.run(command::with_path(command::resume, path));
  EXPECT_EQ(m.c.facts().steps, 1u);
  EXPECT_EQ(m.view.said.back(), "resumed " + m.o.model + " from " + path);
  m.run("step 2");
  EXPECT_EQ(m.exported("resumed.vvm"), straight);
  EXPECT_EQ(m.c.log().text(), "resume " + path + "\nstep 2\n");
  controlled again("history.vvp", m.c.log());
  EXPECT_EQ(again.c.facts().steps, 3u);
  EXPECT_EQ(again.exported("replayed.vvm"), straight);
  EXPECT_EQ(m.view.errors, std::vector<std::string>{});
}

TEST(ModelController, ACheckpointThatCannotBeResumedLeavesTheModelAsItWas) {
  controlled m("history.vvp");
  m.run("step 2");
  const std::string path = test_files::write_scratch("not_a.ckpt", "step 3\n");
  m.run(command::with_path(command::resume, path));
  ASSERT_EQ(m.view.errors.size(), 1u);
  EXPECT_EQ(m.view.errors[0], path + ": not a vv checkpoint (it does not begin with \"vv checkpoint\")");
  EXPECT_EQ(m.c.facts().steps, 2u);
  EXPECT_EQ(m.c.log().text(), "step 2\n");
}

// Batch's policy: the first error ends the run, and the commands queued
// after the one that failed are dropped, not carried out.
TEST(ModelController, WithoutRestoringAnErrorEndsTheRunAndDropsWhatFollows) {
  controlled m("history.vvp", {}, {}, vvi::controller_policy{false});
  std::string bad = test_files::scratch_dir() + "out.xyz";
  m.c.submit(command::with_path(command::export_mesh, bad));
  m.c.submit(command::steps(1));
  m.c.poll(0);
  ASSERT_TRUE(m.c.failed());
  EXPECT_NE(m.c.failure().find("out.xyz"), std::string::npos) << m.c.failure();
  EXPECT_EQ(m.c.facts().steps, 0u);
  EXPECT_TRUE(m.c.log().events.empty());
  EXPECT_TRUE(m.c.idle());
}

// The window waits for events as long as nothing is due (a frame drawn in
// software takes a core from the model and the compiler): idle, at the
// file watch's pace; in a `wait`, until it ends, a step asked for meanwhile
// running then.
TEST(ModelController, TheWindowMaySleepUntilTheNextThingIsDue) {
  controlled m("history.vvp");
  EXPECT_DOUBLE_EQ(m.c.seconds_until_due(0), 0.25);
  m.c.poll(10.0);  // the time now
  command wait = command::of(command::wait);
  wait.number = 100;
  m.c.submit(wait);  // at once: it goes beside jobs
  EXPECT_FALSE(m.c.idle());
  EXPECT_NEAR(m.c.seconds_until_due(10.0), 0.1, 1e-9);
  m.c.submit(command::steps(1));
  m.c.poll(10.06);
  EXPECT_EQ(m.c.facts().steps, 0u);
  EXPECT_NEAR(m.c.seconds_until_due(10.06), 0.04, 1e-9);
  m.c.poll(10.1);
  EXPECT_EQ(m.c.facts().steps, 1u);
  EXPECT_TRUE(m.c.idle());
  EXPECT_DOUBLE_EQ(m.c.seconds_until_due(10.1), 0.25);
}

// The script's commands go one at a time, each once the one before has
// finished, and the record has the position before the command runs.
TEST(ScriptPlayer, GivesEachCommandOnceTheOneBeforeIsDoneAndTellsThePositionFirst) {
  controlled m("history.vvp");
  std::string error;
  vvi::script_player player(vvi::parse_commands("step 2\nfit\nend\nquit\n", "s.txt", error), 0);
  for (int frame = 0; frame < 10 && !player.done(); ++frame) {
    player.feed(m.c);
    m.c.poll(0);
  }
  EXPECT_TRUE(player.done());
  ASSERT_EQ(m.jobs.started.size(), 4u);  // the load, two steps, end
  EXPECT_EQ(m.jobs.told[1].script_pos, 1u);
  EXPECT_EQ(m.jobs.told[3].script_pos, 3u);
  ASSERT_EQ(m.view.viewed.size(), 2u);
  EXPECT_EQ(m.view.viewed[0].kind, command::fit);
  EXPECT_EQ(m.view.viewed[1].kind, command::quit);
  EXPECT_EQ(m.c.log().text(), "step 2\nend\n");
}

}  // namespace
