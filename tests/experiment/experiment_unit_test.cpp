// The parts of a sweep that need no model: reading --sweep, the plan's
// order, numbering and shards, the CSV dialect, a failed run's reason and
// line, the progress line.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <stdexcept>

#include "experiment/csv.hpp"
#include "experiment/run_record.hpp"
#include "experiment/slurm.hpp"
#include "experiment/sweep_identity.hpp"
#include "experiment/sweep_plan.hpp"
#include "experiment/sweep_progress.hpp"

namespace {

using vvi::parse_sweep;
using strings = std::vector<std::string>;

std::string refusal(const std::string& typed) {
  try {
    parse_sweep(typed);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(taken)";
}

TEST(SweepValues, AListKeepsTheValuesAsTyped) {
  vvi::swept_parameter p = parse_sweep("rate=0.10,2,-1e3");
  EXPECT_EQ(p.name, "rate");
  EXPECT_EQ(p.values, (strings{"0.10", "2", "-1e3"}));
}

TEST(SweepValues, ARangeHasCountEvenlySpacedValuesWrittenExactly) {
  EXPECT_EQ(parse_sweep("a=0:1:5").values, (strings{"0", "0.25", "0.5", "0.75", "1"}));
  EXPECT_EQ(parse_sweep("a=1:10:4").values, (strings{"1", "4", "7", "10"}));
  EXPECT_EQ(parse_sweep("a=0:0.3:4").values, (strings{"0", "0.1", "0.2", "0.3"}));
  EXPECT_EQ(parse_sweep("a=-1:1:3").values, (strings{"-1", "0", "1"}));
  EXPECT_EQ(parse_sweep("a=2:2:1").values, (strings{"2"}));
}

TEST(SweepValues, BadSweepsAreRefusedNamingTheOption) {
  EXPECT_EQ(refusal("rate="), "--sweep rate=: no values: the sweep would have no runs");
  EXPECT_EQ(refusal("rate=0:1:0"), "--sweep rate=0:1:0: COUNT is 0: the range has no values (COUNT must be 1 or more)");
  EXPECT_EQ(refusal("rate=1:0:3"), "--sweep rate=1:0:3: the range is empty: HI (0) is below LO (1)");
  EXPECT_EQ(refusal("rate=1,,2"), "--sweep rate=1,,2: an empty value (two commas, or one at an end)");
  EXPECT_EQ(refusal("rate=1,2,1"), "--sweep rate=1,2,1: the value 1 is listed twice");
  EXPECT_EQ(refusal("rate=0:1:2.5"), "--sweep rate=0:1:2.5: COUNT must be a whole number of values from 1 to 1000000, not 2.5");
  EXPECT_EQ(refusal("rate=0:x:2"), "--sweep rate=0:x:2: a range needs LO:HI:COUNT, three numbers, e.g. 0:1:5");
  EXPECT_EQ(refusal("rate=2:2:3"), "--sweep rate=2:2:3: LO and HI are equal, so its 3 values would all be 2");
  EXPECT_EQ(refusal("2x=1"), "--sweep 2x=1: \"2x\" is no parameter name; it needs NAME=V1,V2,... or NAME=LO:HI:COUNT, "
                             "e.g. --sweep rate=0.1,0.2 or --sweep rate=0:1:5");
  EXPECT_EQ(refusal("rate"), "--sweep rate: it needs NAME=V1,V2,... or NAME=LO:HI:COUNT, e.g. --sweep rate=0.1,0.2 or "
                             "--sweep rate=0:1:5");
}

TEST(SweepPlan, TheFirstParameterVariesSlowestAndTheSeedFastest) {
  vvi::sweep_plan plan({parse_sweep("a=1,2"), parse_sweep("b=x,y,z")}, 2, 0);
  ASSERT_EQ(plan.size(), 12u);
  EXPECT_EQ(plan.describe(plan.run(1)), "a=1 b=x seed=1");
  EXPECT_EQ(plan.describe(plan.run(2)), "a=1 b=x seed=2");
  EXPECT_EQ(plan.describe(plan.run(3)), "a=1 b=y seed=1");
  EXPECT_EQ(plan.describe(plan.run(7)), "a=2 b=x seed=1");
  EXPECT_EQ(plan.describe(plan.run(12)), "a=2 b=z seed=2");
}

TEST(SweepPlan, WithoutSeedsEveryRunUsesTheGivenSeed) {
  vvi::sweep_plan plan({parse_sweep("a=1,2")}, 0, 7);
  ASSERT_EQ(plan.size(), 2u);
  EXPECT_EQ(plan.run(2).seed, 7u);
}

TEST(SweepPlan, ShardsTakeEveryNthRunAndTogetherAllOnce) {
  vvi::sweep_plan plan({parse_sweep("a=1:7:7")}, 0, 0);
  EXPECT_EQ(plan.shard(1, 3), (std::vector<unsigned>{1, 4, 7}));
  EXPECT_EQ(plan.shard(2, 3), (std::vector<unsigned>{2, 5}));
  EXPECT_EQ(plan.shard(3, 3), (std::vector<unsigned>{3, 6}));
  EXPECT_EQ(plan.shard(1, 1).size(), 7u);
}

TEST(SweepPlan, RunFoldersAreNumberedWideEnoughForEveryRun) {
  EXPECT_EQ(vvi::sweep_plan({parse_sweep("a=1,2")}, 0, 0).folder(2), "run-0002");
  EXPECT_EQ(vvi::sweep_plan({parse_sweep("a=1:12000:12000")}, 0, 0).folder(7), "run-00007");
}

TEST(SweepPlan, AParameterSweptTwiceIsRefused) {
  try {
    vvi::sweep_plan({parse_sweep("a=1"), parse_sweep("a=2")}, 0, 0);
    FAIL() << "taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "--sweep a=2: parameter a is already swept (--sweep a=1)");
  }
}

TEST(SweepCsv, QuotedCellsReadBackAsWritten) {
  std::string text = vvi::csv::row({"step", "growth, %", "say \"hi\""}) + "1,2,\n";
  EXPECT_EQ(text, "step,\"growth, %\",\"say \"\"hi\"\"\"\n1,2,\n");
  auto rows = vvi::csv::read(text);
  ASSERT_TRUE(rows);
  ASSERT_EQ(rows->size(), 2u);
  EXPECT_EQ((*rows)[0], (strings{"step", "growth, %", "say \"hi\""}));
  EXPECT_EQ((*rows)[1], (strings{"1", "2", ""}));
  EXPECT_FALSE(vvi::csv::read("a,\"open\n"));
}

TEST(SweepFailedRun, ReasonAndLineComeFromTheLastMessageOfTheRun) {
  std::string err = "vvinterpreter: /abs/m.vvp:9: step 1 has been running for 10 s\n"
                    "vvinterpreter: /abs/m.vvp:12: crashed with SIGABRT in step 2\n  /abs/m.vvp:12 in the step block\n";
  vvi::run_failure f = vvi::failure_from_output(err, "exited with status 1", "/abs/m.vvp", "m.vvp");
  EXPECT_EQ(f.line, "m.vvp:12");
  EXPECT_EQ(f.reason, "crashed with SIGABRT in step 2");
  f = vvi::failure_from_output("vvinterpreter: out.png: cannot write file: No space left on device\n", "x", "", "");
  EXPECT_EQ(f.line, "");
  EXPECT_EQ(f.reason, "out.png: cannot write file: No space left on device");
  f = vvi::failure_from_output("", "killed by SIGKILL", "", "");
  EXPECT_EQ(f.reason, "killed by SIGKILL");
}

TEST(SweepProgress, TimeLeftIsSaidInUnitsPeopleRead) {
  EXPECT_EQ(vvi::time_left_text(0.2), "about 1 s");
  EXPECT_EQ(vvi::time_left_text(42), "about 42 s");
  EXPECT_EQ(vvi::time_left_text(185), "about 3 min");
  EXPECT_EQ(vvi::time_left_text(3900), "about 1 h 5 min");
}

std::string written(const std::function<void(vvi::sweep_progress&)>& use, bool rewrite) {
  std::FILE* f = std::tmpfile();
  {
    vvi::sweep_progress p(3, f, rewrite);
    use(p);
  }
  std::rewind(f);
  std::string text;
  for (int c; (c = std::fgetc(f)) != EOF;) text += static_cast<char>(c);
  std::fclose(f);
  return text;
}

TEST(SweepProgress, OnATerminalOneLineIsRewrittenInPlace) {
  std::string text = written(
      [](vvi::sweep_progress& p) {
        p.ended(false, "run 1");
        p.ended(true, "run 2");
        p.ended(false, "run 3");
        p.finish();
      },
      true);
  EXPECT_EQ(text.find('\n'), text.size() - 1) << text;
  EXPECT_NE(text.find("\rruns: 1 done, 0 failed, 2 remaining, about "), std::string::npos) << text;
  EXPECT_NE(text.find("\rruns: 1 done, 1 failed, 1 remaining, about "), std::string::npos) << text;
  EXPECT_NE(text.find("\rruns: 2 done, 1 failed, 0 remaining\033[K\n"), std::string::npos) << text;
}

TEST(SweepProgress, ElsewhereEachRunThatEndsIsALine) {
  std::string text = written(
      [](vvi::sweep_progress& p) {
        p.ended(false, "run 1 (a=1 seed=1)");
        p.ended(true, "run 2 (a=2 seed=1)");
        p.finish();
      },
      false);
  EXPECT_EQ(text.find('\r'), std::string::npos);
  EXPECT_EQ(text.rfind("run 1 (a=1 seed=1) finished: 1 done, 0 failed, 2 remaining, about ", 0), 0u) << text;
  EXPECT_NE(text.find("\nrun 2 (a=2 seed=1) failed: 1 done, 1 failed, 1 remaining, about "), std::string::npos) << text;
}

TEST(SweepIdentity, ItsTextReadsBackToTheSamePlan) {
  vvi::sweep_identity id{"abc", "plots.csv", {parse_sweep("rate=0:1:3"), parse_sweep("n=1,2")}, 2, 0, {"--steps", "3"}};
  EXPECT_EQ(id.text(),
            "vv sweep 1\nprogram abc\nplots plots.csv\nparameter rate 0,0.5,1\nparameter n 1,2\nseeds 2\noption --steps\n"
            "option 3\n");
  std::string why;
  auto back = vvi::parse_identity(id.text(), why);
  ASSERT_TRUE(back) << why;
  EXPECT_EQ(back->text(), id.text());
  EXPECT_EQ(back->plan().size(), 12u);
  EXPECT_EQ(vvi::first_difference("a\nb 1\n", "a\nb 2\n"), "\"b 1\" there, \"b 2\" here");
}

TEST(SweepSlurm, ShellWordsStayOneWordAsTheyAre) {
  EXPECT_EQ(vvi::shell_word("rate=0.5"), "rate=0.5");
  EXPECT_EQ(vvi::shell_word("a b"), "'a b'");
  EXPECT_EQ(vvi::shell_word("it's $HOME"), "'it'\\''s $HOME'");
  EXPECT_EQ(vvi::shell_word(""), "''");
}

}  // namespace
