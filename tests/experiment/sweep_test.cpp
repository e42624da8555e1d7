// Sweeps as users run them (docs/experiments.md): the runs table and the
// failed runs, any number of jobs, resuming, kill -9, shards and merge,
// Slurm scripts, and every refusal with its message. The model
// (models/sweep_model.vvp) plots rate * step and its random generator's
// draws, so every cell is computed here independently.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

#include "run_interpreter.hpp"
#include "spawned_run.hpp"

namespace {

namespace fs = std::filesystem;
using strings = std::vector<std::string>;

const std::string model = VV_EXPERIMENT_TESTS_DIR "/models/sweep_model.vvp";

fs::path fresh(const std::string& name) {
  fs::path p = fs::path(VV_WORK_DIR) / name;
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

test_run::result vv(const strings& args) { return test_run::run(test_run::interpreter(args)); }

// A sweep of the test model into `out`; `more` are further options.
test_run::result sweep(const fs::path& out, const strings& more) {
  strings args = {"--steps", "3", "--out", out.string()};
  args.insert(args.end(), more.begin(), more.end());
  args.push_back(model);
  return vv(args);
}

// The line of the model that holds `text`.
int line_of(const std::string& text) {
  std::ifstream in(model);
  int n = 0;
  for (std::string line; std::getline(in, line);)
    if (++n, line.find(text) != std::string::npos) return n;
  return 0;
}

// The rows a run of the test model gives for 3 steps: value = rate *
// step (the texts given), draw = the seeded mt19937_64's numbers % 1000.
std::string rows(int run, int seed, const std::string& rate, const strings& values) {
  std::mt19937_64 random(static_cast<std::uint64_t>(seed));
  std::string lead = std::to_string(run) + "," + std::to_string(seed) + "," + rate + ",";
  std::string out = lead + "0,0,\n";
  for (int step = 1; step <= 3; ++step)
    out += lead + std::to_string(step) + "," + values[step - 1] + "," + std::to_string(random() % 1000) + "\n";
  return out;
}

const std::string header = "run,seed,rate,step,value,draw\n";
const strings half = {"0.5", "1", "1.5"}, two = {"2", "4", "6"}, one = {"1", "2", "3"};

TEST(Sweep, RunsTableHasARowPerRunAndStepWithItsParametersSeedAndPlots) {
  fs::path out = fresh("table") / "sweep";
  test_run::result r = sweep(out, {"--sweep", "rate=0.5,2", "--seeds", "2", "--jobs", "2"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read(out / "runs.csv"),
            header + rows(1, 1, "0.5", half) + rows(2, 2, "0.5", half) + rows(3, 1, "2", two) + rows(4, 2, "2", two));
  EXPECT_EQ(read(out / "failed.csv"), "run,seed,rate,line,reason\n");
  for (const char* run : {"run-0001", "run-0002", "run-0003", "run-0004"}) {
    EXPECT_TRUE(fs::exists(out / run / "finished")) << run;
    EXPECT_TRUE(fs::exists(out / run / "plots.csv")) << run;
  }
  // Progress: a line per run when the output is not a terminal.
  EXPECT_NE(r.out.find("4 runs: 0 finished before, 4 to run, 2 at a time\n"), std::string::npos) << r.out;
  for (const char* run : {"run 1 (rate=0.5 seed=1) finished: ", "run 4 (rate=2 seed=2) finished: "})
    EXPECT_NE(r.out.find(run), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" done, 0 failed, 0 remaining\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("wrote " + out.string() + "/runs.csv\n"), std::string::npos) << r.out;
}

TEST(Sweep, OnATerminalProgressIsOneLineRewrittenInPlace) {
  fs::path out = fresh("terminal") / "sweep";
  if (!fs::exists("/usr/bin/script")) GTEST_SKIP() << "no script(1) to give the sweep a terminal";
  // script(1) runs the sweep on a pseudo-terminal and copies what it shows.
  std::string command;
  for (const std::string& a : test_run::interpreter({"--sweep", "rate=0.5,2", "--steps", "3", "--jobs", "1", "--out",
                                                     out.string(), model}))
    command += "'" + a + "' ";
  test_run::result r = test_run::run({"/usr/bin/script", "-qec", command, "/dev/null"});
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("\rruns: 1 done, 0 failed, 1 remaining, about "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\rruns: 2 done, 0 failed, 0 remaining\033[K\r\n"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find(" finished: "), std::string::npos) << r.out;  // no line per run
}

TEST(Sweep, TheModelIsCompiledOnceAndEveryRunFindsItInTheCache) {
  fs::path out = fresh("compile_once") / "sweep";
  test_run::result r = sweep(out, {"--sweep", "rate=1,2,4", "--rebuild"});
  ASSERT_EQ(r.status, 0) << r.err;
  std::size_t compiled = r.out.find("sweep_model.vvp: translated in ");
  ASSERT_NE(compiled, std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("translated in ", r.out.find('\n', compiled)), std::string::npos) << r.out;
  for (const char* run : {"run-0001", "run-0002", "run-0003"})
    EXPECT_NE(read(out / run / "stdout.txt").find("sweep_model.vvp: compiled model found in the cache"),
              std::string::npos)
        << run << ": " << read(out / run / "stdout.txt");
}

TEST(Sweep, RangesSweepEvenlySpacedValuesAndEveryCombinationRuns) {
  fs::path out = fresh("range") / "sweep";
  test_run::result r = sweep(out, {"--sweep", "rate=0.5:2:2", "--sweep", "nap=0,1", "--jobs", "1"});
  ASSERT_EQ(r.status, 0) << r.err;
  std::string table = read(out / "runs.csv");
  EXPECT_EQ(table.substr(0, table.find('\n') + 1), "run,seed,rate,nap,step,value,draw\n");
  // rate 0.5 with nap 0 and 1, then rate 2: seed 0 throughout.
  for (const char* row : {"\n1,0,0.5,0,3,1.5,", "\n2,0,0.5,1,3,1.5,", "\n3,0,2,0,3,6,", "\n4,0,2,1,3,6,"})
    EXPECT_NE(table.find(row), std::string::npos) << row << " in\n" << table;
}

TEST(Sweep, TheTableIsByteIdenticalForOneAndTwoJobs) {
  fs::path dir = fresh("jobs");
  // Runs of different lengths, so with two jobs they end out of order.
  strings args = {"--sweep", "rate=0.5,1,2", "--seeds", "2", "--set", "nap=0"};
  strings one_job = args, two_jobs = args;
  one_job.insert(one_job.end(), {"--jobs", "1"});
  two_jobs.insert(two_jobs.end(), {"--jobs", "2"});
  ASSERT_EQ(sweep(dir / "one", one_job).status, 0);
  ASSERT_EQ(sweep(dir / "two", two_jobs).status, 0);
  std::string a = read(dir / "one" / "runs.csv"), b = read(dir / "two" / "runs.csv");
  EXPECT_EQ(a, b);
  EXPECT_EQ(a, header + rows(1, 1, "0.5", half) + rows(2, 2, "0.5", half) + rows(3, 1, "1", one) +
                   rows(4, 2, "1", one) + rows(5, 1, "2", two) + rows(6, 2, "2", two));
}

TEST(Sweep, ACrashingRunIsInFailedCsvWithReasonAndLineWhileTheOthersFinish) {
  fs::path out = fresh("crash") / "sweep";
  test_run::result r = sweep(out, {"--sweep", "rate=1,3,2", "--jobs", "2"});
  EXPECT_EQ(r.status, 1);
  std::string line = model + ":" + std::to_string(line_of("std::abort()"));
  EXPECT_EQ(read(out / "failed.csv"), "run,seed,rate,line,reason\n2,0,3," + line + ",crashed with SIGABRT in step 2\n");
  EXPECT_EQ(read(out / "runs.csv"), header + rows(1, 0, "1", one) + rows(3, 0, "2", two));
  EXPECT_TRUE(fs::exists(out / "run-0002" / "failed"));
  EXPECT_FALSE(fs::exists(out / "run-0002" / "finished"));
  EXPECT_NE(r.err.find("vvinterpreter: 1 of 3 runs failed: see " + out.string() + "/failed.csv\n"), std::string::npos)
      << r.err;
}

struct file_stamp {
  ino_t inode;
  std::int64_t mtime_ns;
  bool operator==(const file_stamp& o) const { return inode == o.inode && mtime_ns == o.mtime_ns; }
};
file_stamp stamp(const fs::path& p) {
  struct stat st {};
  stat(p.c_str(), &st);
  return {st.st_ino, std::int64_t(st.st_mtim.tv_sec) * 1000000000 + st.st_mtim.tv_nsec};
}

TEST(Sweep, RunningTheSameCommandAgainSkipsFinishedRunsAndRunsTheFailedOnesAgain) {
  fs::path out = fresh("rerun") / "sweep";
  strings args = {"--sweep", "rate=1,3", "--seeds", "2"};
  test_run::result first = sweep(out, args);
  ASSERT_EQ(first.status, 1) << first.err;
  std::string table = read(out / "runs.csv"), failed = read(out / "failed.csv");
  file_stamp run1 = stamp(out / "run-0001" / "stdout.txt"), run2 = stamp(out / "run-0002" / "plots.csv");
  file_stamp run3 = stamp(out / "run-0003" / "stdout.txt");

  test_run::result again = sweep(out, args);
  EXPECT_EQ(again.status, 1);
  EXPECT_NE(again.out.find("sweep_model.vvp: compiled model found in the cache\n"), std::string::npos) << again.out;
  EXPECT_NE(again.out.find("4 runs: 2 finished before, 2 to run"), std::string::npos) << again.out;
  EXPECT_TRUE(stamp(out / "run-0001" / "stdout.txt") == run1);  // not run again
  EXPECT_TRUE(stamp(out / "run-0002" / "plots.csv") == run2);
  EXPECT_FALSE(stamp(out / "run-0003" / "stdout.txt") == run3);  // failed: run again
  EXPECT_EQ(read(out / "runs.csv"), table);
  EXPECT_EQ(read(out / "failed.csv"), failed);
}

TEST(Sweep, AfterKillNineNoHalfWrittenRunCountsAndTheRerunGivesTheSameTable) {
  fs::path dir = fresh("kill");
  // Each run naps 100 ms a step: the sweep is killed while its second run runs.
  strings args = {"--sweep", "rate=0.5,2", "--seeds", "2", "--jobs", "1", "--set", "nap=100",
                  "--steps", "3", "--out"};
  strings whole = args, killed = args;
  whole.insert(whole.end(), {(dir / "whole").string(), model});
  killed.insert(killed.end(), {(dir / "killed").string(), model});
  ASSERT_EQ(vv(whole).status, 0);

  test_run::spawned s(test_run::interpreter(killed));
  ASSERT_TRUE(s.started());
  fs::path first_done = dir / "killed" / "run-0001" / "finished";
  auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(first_done) && std::chrono::steady_clock::now() < until)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_TRUE(fs::exists(first_done));
  kill(s.pid(), SIGKILL);  // the sweep alone: its runs end with it
  s.finish();
  EXPECT_FALSE(fs::exists(dir / "killed" / "runs.csv"));
  EXPECT_FALSE(fs::exists(dir / "killed" / "run-0002" / "finished"));
  EXPECT_FALSE(fs::exists(dir / "killed" / "run-0004" / "finished"));

  test_run::result rerun = vv(killed);
  ASSERT_EQ(rerun.status, 0) << rerun.err;
  EXPECT_EQ(rerun.out.find("0 finished before"), std::string::npos) << rerun.out;
  EXPECT_EQ(rerun.out.find("4 finished before"), std::string::npos) << rerun.out;
  EXPECT_EQ(read(dir / "killed" / "runs.csv"), read(dir / "whole" / "runs.csv"));
  EXPECT_EQ(read(dir / "killed" / "runs.csv"),
            header + rows(1, 1, "0.5", half) + rows(2, 2, "0.5", half) + rows(3, 1, "2", two) + rows(4, 2, "2", two));
}

TEST(Sweep, CtrlCEndsTheRunningRunsWritesTheTablesOfTheFinishedOnesAndTheRerunCompletes) {
  fs::path out = fresh("interrupt") / "sweep";
  strings args = {"--sweep", "rate=0.5,2", "--seeds", "2", "--jobs", "1", "--set", "nap=100", "--steps", "3",
                  "--out", out.string(), model};
  test_run::spawned s(test_run::interpreter(args));
  auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(out / "run-0001" / "finished") && std::chrono::steady_clock::now() < until)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  kill(s.pid(), SIGINT);
  test_run::result r = s.finish();
  EXPECT_EQ(r.status, 128 + SIGINT);
  EXPECT_NE(r.err.find("vvinterpreter: interrupted (SIGINT); the unfinished runs run when the same command is given "
                       "again\n"),
            std::string::npos)
      << r.err;
  // The tables hold what finished (run 1, perhaps run 2); the run it ended has no marker.
  std::string table = read(out / "runs.csv");
  EXPECT_EQ(table.rfind(header + rows(1, 1, "0.5", half), 0), 0u) << table;
  EXPECT_FALSE(fs::exists(out / "run-0004" / "finished"));
  EXPECT_EQ(read(out / "failed.csv"), "run,seed,rate,line,reason\n");  // an interrupted run is no failed run
  test_run::result again = vv(args);
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(read(out / "runs.csv"),
            header + rows(1, 1, "0.5", half) + rows(2, 2, "0.5", half) + rows(3, 1, "2", two) + rows(4, 2, "2", two));
}

TEST(Sweep, ASecondSweepInTheSameFolderIsRefusedWhileTheFirstRuns) {
  fs::path out = fresh("busy") / "sweep";
  strings args = {"--sweep", "rate=0.5,2", "--jobs", "1", "--set", "nap=100", "--steps", "3", "--out", out.string(),
                  model};
  test_run::spawned first(test_run::interpreter(args));
  auto until = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(out / "run-0001") && std::chrono::steady_clock::now() < until)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  test_run::result second = vv(args);
  EXPECT_EQ(second.status, 1);
  EXPECT_EQ(second.err, "vvinterpreter: " + out.string() +
                            ": another sweep or merge is working in this folder; wait for it to end\n");
  test_run::result done = first.finish();
  EXPECT_EQ(done.status, 0) << done.err;
  EXPECT_EQ(read(out / "runs.csv"), header + rows(1, 0, "0.5", half) + rows(2, 0, "2", two));
}

TEST(SweepShards, TwoShardsMergedEqualTheWholeSweepByteForByte) {
  fs::path dir = fresh("shards");
  strings args = {"--sweep", "rate=0.5,3,2", "--seeds", "2"};
  strings s1 = args, s2 = args;
  s1.insert(s1.end(), {"--shard", "1/2"});
  s2.insert(s2.end(), {"--shard", "2/2"});
  sweep(dir / "whole", args);
  test_run::result r1 = sweep(dir / "s1", s1);
  EXPECT_NE(r1.out.find("3 runs in shard 1/2 of 6: 0 finished before, 3 to run"), std::string::npos) << r1.out;
  sweep(dir / "s2", s2);
  EXPECT_TRUE(fs::exists(dir / "s1" / "run-0003" / "failed"));  // rate 3 crashes: in failed.csv
  EXPECT_FALSE(fs::exists(dir / "s1" / "run-0002"));
  test_run::result m = vv({"--merge", (dir / "s1").string(), (dir / "s2").string(), "--out", (dir / "merged").string()});
  ASSERT_EQ(m.status, 0) << m.err;
  EXPECT_NE(m.out.find("merged 6 runs from 2 folders into "), std::string::npos) << m.out;
  for (const char* table : {"runs.csv", "failed.csv", "sweep.txt"})
    EXPECT_EQ(read(dir / "merged" / table), read(dir / "whole" / table)) << table;
  EXPECT_EQ(read(dir / "merged" / "run-0005" / "plots.csv"), read(dir / "whole" / "run-0005" / "plots.csv"));
  EXPECT_TRUE(fs::exists(dir / "merged" / "run-0005" / "finished"));
  EXPECT_TRUE(fs::exists(dir / "merged" / "run-0004" / "failed"));
}

TEST(SweepShards, MergeRefusesFoldersOfDifferentSweeps) {
  fs::path dir = fresh("merge_different");
  sweep(dir / "a", {"--sweep", "rate=1,2", "--shard", "1/2"});
  sweep(dir / "b", {"--sweep", "rate=1,2,4", "--shard", "2/2"});
  test_run::result m = vv({"--merge", (dir / "a").string(), (dir / "b").string(), "--out", (dir / "m").string()});
  EXPECT_EQ(m.status, 1);
  EXPECT_EQ(m.err, "vvinterpreter: --merge: " + (dir / "b").string() + " holds another sweep than " +
                       (dir / "a").string() +
                       " (sweep.txt: \"parameter rate 1,2\" there, \"parameter rate 1,2,4\" here); only the shards of "
                       "one sweep can be merged\n");
  EXPECT_FALSE(fs::exists(dir / "m"));
}

TEST(SweepShards, MergeRefusesMissingAndDuplicateRuns) {
  fs::path dir = fresh("merge_runs");
  strings args = {"--sweep", "rate=1,2"};
  strings s1 = args;
  s1.insert(s1.end(), {"--shard", "1/2"});
  sweep(dir / "s1", s1);
  sweep(dir / "whole", args);
  test_run::result missing = vv({"--merge", (dir / "s1").string(), "--out", (dir / "m").string()});
  EXPECT_EQ(missing.status, 1);
  EXPECT_EQ(missing.err, "vvinterpreter: --merge: 1 of 2 runs are missing (run their shards again, or to the end):\n"
                         "  run 2 (rate=2 seed=0) is finished or failed in none of the folders\n");
  test_run::result twice =
      vv({"--merge", (dir / "s1").string(), (dir / "whole").string(), "--out", (dir / "m").string()});
  EXPECT_EQ(twice.status, 1);
  EXPECT_EQ(twice.err, "vvinterpreter: --merge: 1 runs are in more than one folder (merge each shard once):\n"
                       "  run 1 (rate=1 seed=0) is in " + (dir / "s1").string() + " and in " +
                       (dir / "whole").string() + "\n");
  EXPECT_FALSE(fs::exists(dir / "m"));
  test_run::result no_dirs = vv({"--merge", "--out", (dir / "m").string()});
  EXPECT_EQ(no_dirs.status, 2);
  EXPECT_EQ(no_dirs.err.substr(0, no_dirs.err.find('\n')),
            "vvinterpreter: --merge needs the folders of the shards to merge, e.g. --merge a b --out all");
  test_run::result no_out = vv({"--merge", (dir / "s1").string()});
  EXPECT_EQ(no_out.status, 2);
  EXPECT_EQ(no_out.err.substr(0, no_out.err.find('\n')),
            "vvinterpreter: --merge needs --out DIR, the folder to merge into");
}

// The PATH without any sbatch, with `first` in front. (Where sbatch is
// installed, that may leave `first` alone: the sweeps run below find
// their model in the cache and start their runs by absolute paths.)
std::string path_without_sbatch(const fs::path& first) {
  std::string path = first.string();
  std::stringstream dirs(std::getenv("PATH") ? std::getenv("PATH") : "");
  for (std::string d; std::getline(dirs, d, ':');)
    if (!d.empty() && !fs::exists(fs::path(d) / "sbatch")) path += ":" + d;
  return path;
}

TEST(SweepSlurm, TheWrittenScriptsRunTheShardsAndMergeToTheLocalSweepsTable) {
  fs::path dir = fresh("slurm_scripts");
  fs::create_directories(dir / "bin");
  strings args = {"--sweep", "rate=0.5,3,2", "--seeds", "2"};
  sweep(dir / "local", args);
  strings cmd = {"/usr/bin/env", "PATH=" + path_without_sbatch(dir / "bin"), VV_INTERPRETER, "--cache", VV_TEST_CACHE,
                 "--steps", "3", "--slurm", "2", "--out", (dir / "cluster").string()};
  cmd.insert(cmd.end(), args.begin(), args.end());
  cmd.push_back(model);
  test_run::result r = test_run::run(cmd);
  ASSERT_EQ(r.status, 0) << r.err;
  fs::path scripts = dir / "cluster" / "slurm";
  std::string array = read(scripts / "sweep.sbatch"), merge = read(scripts / "merge.sbatch");
  EXPECT_NE(r.out.find("sbatch was not found. The scripts are written; on the cluster, submit them with\n"
                       "  jobid=$(sbatch --parsable " + (scripts / "sweep.sbatch").string() + ")\n"
                       "  sbatch --dependency=afterany:$jobid " + (scripts / "merge.sbatch").string() + "\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find(array), std::string::npos);  // printed for the user
  EXPECT_EQ(array.rfind("#!/bin/sh\n", 0), 0u);
  for (const std::string& line : strings{"#SBATCH --job-name=vv-sweep-sweep_model\n", "#SBATCH --array=1-2\n",
                                  "#SBATCH --cpus-per-task=1\n",
                                  "#SBATCH --output=" + (dir / "cluster").string() + "/slurm/shard-%a.out\n",
                                  "  --shard \"$SLURM_ARRAY_TASK_ID/2\" --out " + (dir / "cluster").string() +
                                      "/shards/\"$SLURM_ARRAY_TASK_ID\" " + model + "\n"})
    EXPECT_NE(array.find(line), std::string::npos) << line << " in\n" << array;
  EXPECT_NE(array.find(" --sweep rate=0.5,3,2 --seeds 2 --jobs 1 --cache "), std::string::npos) << array;
  EXPECT_NE(merge.find("exec " + std::string(VV_INTERPRETER) + " --merge " + (dir / "cluster").string() +
                       "/shards/1 " + (dir / "cluster").string() + "/shards/2 --out " + (dir / "cluster").string() +
                       "\n"),
            std::string::npos)
      << merge;

  // What Slurm would do: each array task, then the merge.
  for (const char* task : {"1", "2"}) {
    test_run::result t =
        test_run::run({"/usr/bin/env", std::string("SLURM_ARRAY_TASK_ID=") + task, "/bin/sh", (scripts / "sweep.sbatch").string()});
    EXPECT_NE(t.out.find(std::string("runs in shard ") + task + "/2 of 6"), std::string::npos) << t.out << t.err;
  }
  test_run::result m = test_run::run({"/bin/sh", (scripts / "merge.sbatch").string()});
  ASSERT_EQ(m.status, 0) << m.err;
  EXPECT_EQ(read(dir / "cluster" / "runs.csv"), read(dir / "local" / "runs.csv"));
  EXPECT_EQ(read(dir / "cluster" / "failed.csv"), read(dir / "local" / "failed.csv"));
}

TEST(SweepSlurm, WithSbatchTheArrayIsSubmittedAndTheMergeWaitsForIt) {
  fs::path dir = fresh("slurm_submit");
  fs::create_directories(dir / "bin");
  // A stand-in for sbatch: logs its arguments, answers job ids 4242, 4243
  // (shell built-ins only: the PATH may hold nothing else).
  const std::string calls = (dir / "calls").string();
  write(dir / "bin" / "sbatch", "#!/bin/sh\necho \"$*\" >> " + calls + "\nn=4241\nwhile read -r line; do n=$((n + 1)); done < " +
                                    calls + "\necho $n\n");
  ASSERT_EQ(vv({"--compile-only", model}).status, 0);  // in the cache: no compiler is needed below
  fs::permissions(dir / "bin" / "sbatch", fs::perms::owner_all);
  strings cmd = {"/usr/bin/env", "PATH=" + path_without_sbatch(dir / "bin"), VV_INTERPRETER, "--cache", VV_TEST_CACHE,
                 "--sweep", "rate=1,2", "--slurm", "3", "--jobs", "2", "--out", (dir / "cluster").string(), model};
  test_run::result r = test_run::run(cmd);
  ASSERT_EQ(r.status, 0) << r.err;
  fs::path scripts = dir / "cluster" / "slurm";
  EXPECT_EQ(read(dir / "calls"), "--parsable " + (scripts / "sweep.sbatch").string() +
                                     "\n--parsable --dependency=afterany:4242 " + (scripts / "merge.sbatch").string() +
                                     "\n");
  EXPECT_NE(r.out.find("submitted job array 4242 (3 shards) and merge job 4243; the tables will be in " +
                       (dir / "cluster").string() + "\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(read(scripts / "sweep.sbatch").find("#SBATCH --cpus-per-task=2\n"), std::string::npos);
}

// The first line of standard error.
std::string first_error(const test_run::result& r) { return r.err.substr(0, r.err.find('\n')); }

TEST(SweepBadInput, AnUnknownParameterIsNamedWithTheModelsParameters) {
  fs::path out = fresh("bad_name") / "sweep";
  test_run::result r = sweep(out, {"--sweep", "speed=1,2"});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "vvinterpreter: --sweep speed=1,2: the model " + model +
                       " has no parameter speed (its parameters: rate, nap)\n");
  EXPECT_FALSE(fs::exists(out));
}

TEST(SweepBadInput, AValueOutsideTheParametersRangeIsNamedWithTheOption) {
  fs::path out = fresh("bad_value") / "sweep";
  test_run::result r = sweep(out, {"--sweep", "rate=0:20:3"});
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "vvinterpreter: --sweep rate=0:20:3: " + model + ":" + std::to_string(line_of("param double rate")) +
                       ": --set rate=20: 20 is outside the range [0, 10] of parameter rate\n");
  EXPECT_FALSE(fs::exists(out));
}

TEST(SweepBadInput, EmptyRangesAndCountZeroAreRefused) {
  fs::path out = fresh("bad_range") / "sweep";
  test_run::result empty = sweep(out, {"--sweep", "rate=2:1:3"});
  EXPECT_EQ(empty.status, 2);
  EXPECT_EQ(empty.err, "vvinterpreter: --sweep rate=2:1:3: the range is empty: HI (1) is below LO (2)\n");
  test_run::result none = sweep(out, {"--sweep", "rate="});
  EXPECT_EQ(none.err, "vvinterpreter: --sweep rate=: no values: the sweep would have no runs\n");
  test_run::result zero = sweep(out, {"--sweep", "rate=0:1:0"});
  EXPECT_EQ(zero.status, 2);
  EXPECT_EQ(zero.err, "vvinterpreter: --sweep rate=0:1:0: COUNT is 0: the range has no values (COUNT must be 1 or more)\n");
  EXPECT_FALSE(fs::exists(out));
}

TEST(SweepBadInput, AShardOutOfRangeIsRefused) {
  fs::path out = fresh("bad_shard") / "sweep";
  test_run::result r = sweep(out, {"--sweep", "rate=1,2", "--shard", "3/2"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(first_error(r), "vvinterpreter: --shard 3/2: shard 3 is out of range: shards are numbered 1 to 2");
  r = sweep(out, {"--sweep", "rate=1,2", "--shard", "1/0"});
  EXPECT_EQ(first_error(r), "vvinterpreter: --shard 1/0: the number of shards must be 1 or more");
  r = sweep(out, {"--sweep", "rate=1,2", "--shard", "2"});
  EXPECT_EQ(first_error(r), "vvinterpreter: --shard needs I/N, e.g. --shard 2/8 (the second of 8 shards); \"2\" is not");
  EXPECT_FALSE(fs::exists(out));
}

TEST(SweepBadInput, ASweepWithoutOutIsRefused) {
  test_run::result r = vv({"--sweep", "rate=1,2", "--steps", "3", model});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(first_error(r), "vvinterpreter: a sweep needs --out DIR, the folder for its runs and tables");
}

TEST(SweepBadInput, AFolderOfAnotherSweepOrOtherFilesIsLeftAsItWas) {
  fs::path dir = fresh("bad_out");
  ASSERT_EQ(sweep(dir / "sweep", {"--sweep", "rate=1,2"}).status, 0);
  std::string table = read(dir / "sweep" / "runs.csv");
  test_run::result other = sweep(dir / "sweep", {"--sweep", "rate=1,2,4"});
  EXPECT_EQ(other.status, 1);
  EXPECT_EQ(other.err, "vvinterpreter: " + (dir / "sweep").string() +
                           " holds another sweep (sweep.txt: \"parameter rate 1,2\" there, \"parameter rate 1,2,4\" "
                           "here); give another --out folder, or remove this one\n");
  EXPECT_EQ(read(dir / "sweep" / "runs.csv"), table);
  EXPECT_FALSE(fs::exists(dir / "sweep" / "run-0003"));

  fs::create_directories(dir / "papers");
  write(dir / "papers" / "draft.txt", "mine");
  test_run::result full = sweep(dir / "papers", {"--sweep", "rate=1,2"});
  EXPECT_EQ(full.status, 1);
  EXPECT_EQ(full.err, "vvinterpreter: " + (dir / "papers").string() +
                          ": the folder is not empty and holds no sweep (no sweep.txt); give a new or empty --out "
                          "folder\n");
  EXPECT_EQ(read(dir / "papers" / "draft.txt"), "mine");
}

TEST(SweepBadInput, AnAbsoluteOutputNameIsRefusedBecauseEveryRunWouldWriteIt) {
  fs::path out = fresh("bad_export") / "sweep";
  test_run::result r = sweep(out, {"--sweep", "rate=1,2", "--export", "/tmp/final.obj"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "vvinterpreter: --export /tmp/final.obj: in a sweep each run writes its files into its own folder "
                   "(DIR/run-NNNN/); give a relative name\n");
}

TEST(Sweep, EachRunsExportsGoToItsOwnFolder) {
  fs::path out = fresh("exports") / "sweep";
  test_run::result r = sweep(out, {"--seeds", "2", "--plots", "series.csv"});
  ASSERT_EQ(r.status, 0) << r.err;
  std::string series = read(out / "run-0002" / "series.csv");
  EXPECT_EQ(series.substr(0, series.find('\n') + 1), "step,value,draw\n");
  EXPECT_NE(series.find("\n3,3,"), std::string::npos) << series;
  EXPECT_FALSE(fs::exists(out / "run-0002" / "plots.csv"));
  // Seeds only: no parameter columns.
  std::string table = read(out / "runs.csv");
  EXPECT_EQ(table.substr(0, table.find('\n') + 1), "run,seed,step,value,draw\n");
  EXPECT_NE(table.find("\n2,2,3,3,"), std::string::npos) << table;
}

}  // namespace
