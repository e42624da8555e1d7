// The host's commands as text, in-process (vvinterpreter/control): the
// command language read and written back, the event log and its session
// text, the state record's line, and what a viewer that died comes back
// with (restart_after).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "control/command_text.hpp"
#include "control/event_log.hpp"
#include "control/restart.hpp"
#include "control/state_record.hpp"

namespace {

using vvi::command;

std::vector<command> parsed(const std::string& text) {
  std::string error;
  std::vector<command> out = vvi::parse_commands(text, "s.txt", error);
  EXPECT_EQ(error, "");
  return out;
}

std::string parse_error(const std::string& text) {
  std::string error;
  vvi::parse_commands(text, "s.txt", error);
  return error;
}

// One command of every kind, each with arguments that are not defaults.
std::vector<command> one_of_each() {
  std::vector<command> all;
  auto add = [&](command c) { all.push_back(c); };
  add(command::steps(3));
  add(command::of(command::run));
  add(command::of(command::animate));
  add(command::of(command::stop));
  add(command::of(command::rewind));
  add(command::of(command::end));
  add(command::of(command::reread));
  add(command::of(command::reload));
  add(command::of(command::recompile));
  add(command::named(command::set, "rate", "0.25"));
  add(command::named(command::action, "Divide all"));
  add(command::labelled(command::pick_action, 17));
  add(command::labelled(command::inspect, 5));
  add(command::labelled(command::inspect, 0));
  command e = command::with_path(command::export_mesh, "out dir/S#1.vvm");
  e.name = "S";
  add(e);
  add(command::with_path(command::plots, "p.csv"));
  add(command::of(command::save_params));
  add(command::with_path(command::save_session, "a \"quoted\" \\ name.vvs"));
  add(command::recording(5, "out dir/mesh-{step}.vtp", 3));
  add(command::recording(2, "m.mp4"));
  add(command::record_off());
  add(command::with_path(command::screenshot, "a.png"));
  add(command::with_path(command::window_screenshot, "w.png"));
  add(command::of(command::fit));
  command r = command::of(command::rotate);
  r.x = 30, r.y = -0.1;
  add(r);
  command z = command::of(command::zoom);
  z.x = 1 / 1.15;
  add(z);
  add(command::of(command::reset_view));
  add(command::switched(command::show, "back-faces", false));
  add(command::named(command::color_by, "height"));
  add(command::named(command::color_by, ""));
  add(command::switched(command::replay, "", false));
  add(command::switched(command::rewind_on_change, "", true));
  add(command::labelled(command::wait, 250));
  add(command::of(command::quit));
  return all;
}

TEST(CommandLanguage, EveryCommandReadsBackAsItWasWritten) {
  for (const command& c : one_of_each()) {
    std::string line = vvi::command_text(c);
    std::vector<command> again = parsed(line + "\n");
    ASSERT_EQ(again.size(), 1u) << line;
    EXPECT_TRUE(again[0] == c) << line << " reads back as " << vvi::command_text(again[0]);
  }
}

TEST(CommandLanguage, TheHelpListsEveryCommandsWord) {
  std::string help = "\n" + vvi::command_help();
  for (const command& c : one_of_each())
    EXPECT_NE(help.find(std::string("\n  ") + vvi::command_word(c.kind) + " "), std::string::npos)
        << vvi::command_word(c.kind);
}

TEST(CommandLanguage, TodaysScriptsRead) {
  std::vector<command> c = parsed(
      "# a comment\n\nstep\nstep 3   # three\nset rate=0.5\npick 5\nexport S s#1.vvm\ncolor-by none\n"
      "show edges off\nrotate 30 -10\nzoom 1.5\nwait 2000\n");
  ASSERT_EQ(c.size(), 10u);
  EXPECT_EQ(c[0].kind, command::step);
  EXPECT_EQ(c[0].number, 1u);
  EXPECT_EQ(c[1].number, 3u);
  EXPECT_EQ(c[1].line, 4);
  EXPECT_EQ(c[2].name + "=" + c[2].value, "rate=0.5");
  EXPECT_EQ(c[3].kind, command::inspect);
  EXPECT_EQ(c[4].path, "s#1.vvm");
  EXPECT_EQ(c[5].name, "");
  EXPECT_FALSE(c[6].on);
  EXPECT_EQ(c[7].y, -10);
  EXPECT_EQ(c[9].kind, command::wait);
}

TEST(CommandLanguage, ABadLineNamesItsFileLineAndWhatIsWrong) {
  EXPECT_EQ(parse_error("step\nfly 3\n"), "s.txt:2: unknown command 'fly'");
  EXPECT_EQ(parse_error("step 0\n"), "s.txt:1: bad arguments for 'step' (it takes: step [N])");
  EXPECT_EQ(parse_error("show edges maybe\n"), "s.txt:1: bad arguments for 'show' (it takes: show WHAT on|off)");
  EXPECT_EQ(parse_error("action \"Divide\n"), "s.txt:1: a quoted word is not closed");
  EXPECT_EQ(parse_error("record 0 m-{step}.vtp\n"),
            "s.txt:1: bad arguments for 'record' (it takes: record K FILE [DIGITS])");
  EXPECT_EQ(parse_error("record on\n"), "s.txt:1: bad arguments for 'record' (it takes: record K FILE [DIGITS])");
  EXPECT_EQ(parse_error("action Divide all\n"),
            "s.txt:1: bad arguments for 'action' (it takes: action NAME); a name with spaces is quoted: "
            "action \"Divide all\"");
}

vvi::event_log log_of(const std::string& text) {
  vvi::event_log log;
  std::string error;
  EXPECT_TRUE(vvi::event_log::parse(text, "log", log, error)) << error;
  return log;
}

TEST(EventLog, StepsRightAfterStepsAreOneEvent) {
  vvi::event_log log;
  log.append(command::steps(1));
  log.append(command::steps(2));
  log.append(command::of(command::end));
  log.append(command::steps(1));
  EXPECT_EQ(log.text(), "step 3\nend\nstep 1\n");
  EXPECT_EQ(log.steps(), 4u);
  EXPECT_EQ(log.steps_before(2), 3u);
}

TEST(EventLog, ItsTextHoldsTheStartingValuesBeforeARewind) {
  vvi::event_log log;
  log.initial = {{"rate", "double", "0.25"}};
  log.append(command::steps(2));
  log.append(command::named(command::set, "rate", "0.5"));
  log.append(command::named(command::action, "Divide all"));
  log.append(command::labelled(command::pick_action, 17));
  log.append(command::of(command::reread));
  std::string text = "set rate=0.25\nrewind\nstep 2\nset rate=0.5\naction \"Divide all\"\npick-action 17\nreread\n";
  EXPECT_EQ(log.text(), text);
  EXPECT_TRUE(log_of(text) == log);
  EXPECT_EQ(log.settings_after()[0].text, "0.5");
}

TEST(EventLog, ARewindStartsItAgainWithTheValuesSetSoFar) {
  vvi::event_log log = log_of("set a=1\nstep 4\nset b=2\nrewind\nstep 1\n");
  EXPECT_EQ(log.text(), "set a=1\nset b=2\nrewind\nstep 1\n");
}

TEST(EventLog, OnlyTheModelsEventsAreInASession) {
  vvi::event_log log;
  std::string error;
  EXPECT_FALSE(vvi::event_log::parse("step 2\nscreenshot a.png\n", "s.vvs", log, error));
  EXPECT_EQ(error,
            "s.vvs:2: 'screenshot' is not one of the model's events (step, end, reread, set, action, pick-action), "
            "rewind or resume");
}

TEST(EventLog, AResumeStartsItAgainFromTheCheckpointWithTheValuesSetSoFar) {
  vvi::event_log log = log_of("step 3\nset a=1\nresume \"my state.ckpt\"\nstep 2\n");
  EXPECT_EQ(log.resumed_from, "my state.ckpt");
  EXPECT_EQ(log.steps(), 2u);
  EXPECT_EQ(log.text(), "set a=1\nresume \"my state.ckpt\"\nstep 2\n");
  // Read back, the same log; a rewind after it starts from start again.
  EXPECT_EQ(log_of(log.text()), log);
  EXPECT_EQ(log_of(log.text() + "rewind\n").resumed_from, "");
}

TEST(EventLog, UpToKeepsTheEventsBeforeAndTheStepsDoneOfTheOneAt) {
  vvi::event_log log = log_of("step 2\nend\nstep 10\nend\n");
  EXPECT_EQ(log.up_to(2, 4).text(), "step 2\nend\nstep 4\n");
  EXPECT_EQ(log.up_to(1).text(), "step 2\n");
}

TEST(StateRecord, ItsLineReadsBackWithEveryField) {
  vvi::state_record r;
  r.plugin = "/cache/a b/model.so";
  r.log = log_of("set rate=0.25\nrewind\nstep 3\naction \"Divide all\"\n");
  r.trying = "/cache/new.so";
  r.replaying = 1;
  r.bad_plugin = "bad%=.so";
  r.no_render_plugin = "x.so";
  r.replay = false;
  r.rewind_on_change = true;
  r.view.camera = "1 2 3\n4";
  int window[4] = {10, 20, 1100, 800};
  for (int i = 0; i < 4; ++i) r.view.window[i] = window[i];
  r.view.edges = false;
  r.view.flat = true;
  r.view.color_by = "height";
  r.view.picked = 5;
  r.view.screenshots = 2;
  r.script_pos = 7;
  r.up = true;
  r.stopped = "step 2 was stopped after 1.0 s";
  r.stopped_activity = "step";
  r.restarted = true;
  r.error = "m.vvp:3: crashed\n  m.vvp:3 in the step block";
  r.note = "restarted";
  std::string line = vvi::record_line(r);
  EXPECT_EQ(line.find('\n'), std::string::npos) << "not one line";
  vvi::state_record back;
  ASSERT_TRUE(vvi::read_record_line(line, back));
  EXPECT_EQ(vvi::record_line(back), line);
  EXPECT_TRUE(back.log == r.log);
  EXPECT_EQ(back.view.camera, r.view.camera);
  EXPECT_EQ(back.error, r.error);
  EXPECT_EQ(back.replaying, 1);
  EXPECT_FALSE(vvi::read_record_line("begin step 3", back));
}

// ---- restart_after ----

vvi::child_end crash_in(const std::string& what, unsigned step) {
  vvi::child_end end;
  end.kind = vvi::child_end::crashed;
  end.signal = 11;
  end.crash.signal = "SIGSEGV";
  end.activity.what = what;
  end.activity.step = step;
  return end;
}

vvi::state_record running(const std::string& log) {
  vvi::state_record r;
  r.plugin = "good.so";
  r.log = log_of(log);
  r.up = true;
  return r;
}

TEST(Restart, ACrashInAStepComesBackWithTheLogWithoutIt) {
  vvi::options o;
  o.model = "m.vvp";
  vvi::restart r = vvi::restart_after(o, running("step 3\nend\n"), crash_in("step", 4));
  EXPECT_EQ(r.record.log.text(), "step 3\nend\n");
  EXPECT_EQ(r.record.plugin, "good.so");
  EXPECT_TRUE(r.record.restarted);
  EXPECT_FALSE(r.record.up);
  EXPECT_EQ(r.record.note, "restarted; the model was run again to step 3, its last good state");
  EXPECT_EQ(r.report.rfind("vvinterpreter: m.vvp: crashed with SIGSEGV in step 4", 0), 0u) << r.report;
}

TEST(Restart, ACrashWhileTheLogIsReplayedStopsTheReplayThere) {
  vvi::options o;
  o.model = "m.vvp";
  vvi::state_record last = running("step 2\nend\nstep 10\nend\n");
  last.replaying = 2;
  vvi::restart r = vvi::restart_after(o, last, crash_in("step", 7));  // steps 3 to 6 of the event were done
  EXPECT_EQ(r.record.log.text(), "step 2\nend\nstep 4\n");
  EXPECT_EQ(r.record.replaying, -1);
  EXPECT_NE(r.report.find("; the replay stopped at event 3 of 4 (step 10)"), std::string::npos) << r.report;
}

TEST(Restart, ANewBuildThatCrashesOnItsWayInIsNotLoadedAgain) {
  vvi::options o;
  o.model = "m.vvp";
  vvi::state_record last = running("step 2\n");
  last.trying = "new.so";
  for (const char* what : {"loading", "start", "step"}) {
    vvi::restart r = vvi::restart_after(o, last, crash_in(what, 1));
    EXPECT_EQ(r.record.bad_plugin, "new.so") << what;
    EXPECT_EQ(r.record.plugin, "good.so") << what;
    EXPECT_EQ(r.record.log.text(), "step 2\n") << what;
    EXPECT_EQ(r.record.trying, "") << what;
  }
}

// The pipe names an action and a pick by what they are (`action "Lift"`,
// `pick of vertex 3`): a new build that crashes in one while its log is
// replayed is not loaded again either; a crash in one while the good
// model's log is replayed stops the replay there.
TEST(Restart, ACrashInAReplayedActionOrPickStopsTheReplayThere) {
  vvi::options o;
  o.model = "m.vvp";
  vvi::state_record last = running("step 2\naction Lift\npick-action 3\n");
  last.trying = "new.so";
  for (const char* what : {"action \"Lift\"", "pick of vertex 3"}) {
    vvi::restart r = vvi::restart_after(o, last, crash_in(what, 0));
    EXPECT_EQ(r.record.bad_plugin, "new.so") << what;
    EXPECT_EQ(r.record.log.text(), "step 2\naction Lift\npick-action 3\n") << what;
  }
  last.trying.clear();
  last.replaying = 2;
  vvi::restart r = vvi::restart_after(o, last, crash_in("pick of vertex 3", 0));
  EXPECT_EQ(r.record.bad_plugin, "");
  EXPECT_EQ(r.record.log.text(), "step 2\naction Lift\n");
  EXPECT_NE(r.report.find("crashed with SIGSEGV in pick of vertex 3; the replay stopped at event 3 of 3 (pick-action 3)"),
            std::string::npos)
      << r.report;
}

TEST(Restart, AModelThatCrashesInStartIsNotStartedAgain) {
  vvi::options o;
  o.model = "m.vvp";
  vvi::restart r = vvi::restart_after(o, running(""), crash_in("start", 0));
  EXPECT_EQ(r.record.bad_plugin, "good.so");
  EXPECT_EQ(r.record.note, "restarted; no model had loaded yet");
}

TEST(Restart, WithoutReplayItComesBackAtStepZeroWithTheValuesSet) {
  vvi::options o;
  o.model = "m.vvp";
  vvi::state_record last = running("step 2\nset rate=0.5\nstep 1\n");
  last.replay = false;
  vvi::restart r = vvi::restart_after(o, last, crash_in("step", 4));
  EXPECT_EQ(r.record.log.text(), "set rate=0.5\nrewind\n");
  EXPECT_EQ(r.record.note, "restarted at step 0 (running again to the last step is off)");
}

TEST(Restart, AStopSaysWhatWasStoppedAndACrashInARenderBlockTurnsThemOff) {
  vvi::options o;
  o.model = "m.vvp";
  vvi::state_record last = running("step 1\n");
  last.stopped = "step 2 was stopped after 3.0 s";
  last.stopped_activity = "step";
  vvi::child_end stop;
  stop.kind = vvi::child_end::exited;
  stop.exit_code = vvi::viewer_restart_code;
  vvi::restart r = vvi::restart_after(o, last, stop);
  EXPECT_EQ(r.record.error,
            "m.vvp: step 2 was stopped after 3.0 s; restarted; the model was run again to step 1, its last good state");
  EXPECT_EQ(r.record.stopped, "");
  vvi::restart drawn = vvi::restart_after(o, running("step 1\n"), crash_in("render", 0));
  EXPECT_EQ(drawn.record.no_render_plugin, "good.so");
  EXPECT_EQ(drawn.record.bad_plugin, "");
}

}  // namespace
