#include "experiment/sweep_options.hpp"

#include <CLI/CLI.hpp>

#include <cstdlib>
#include <functional>

namespace vvi {

namespace {

[[noreturn]] void invalid_value(const std::string& why) { throw CLI::ValidationError(why); }

bool whole_number(const std::string& s, unsigned long& out) {
  if (s.empty() || s.size() > 9 || s.find_first_not_of("0123456789") != std::string::npos) return false;
  out = std::strtoul(s.c_str(), nullptr, 10);
  return true;
}

unsigned count_of(const std::string& v, unsigned long lo, unsigned long hi, const std::string& need) {
  unsigned long n = 0;
  if (!whole_number(v, n) || n < lo || n > hi) invalid_value(need);
  return static_cast<unsigned>(n);
}

// The section of --help these options are listed in.
const char* const section = "experiments";

// One value per occurrence, in command-line order; a missing value reaches
// `take` as "" so that each option says what it needs. `value` and `what`
// are its line in --help.
void with_value(CLI::App& app, const std::string& name, const std::string& value, const std::string& what,
                std::function<void(const std::string&)> take) {
  app.add_option_function<std::string>(name, std::move(take), what)
      ->expected(0, 1)
      ->trigger_on_parse()
      ->option_text(value)
      ->group(section);
}

// I/N with 1 <= I <= N.
void read_shard(const std::string& v, sweep_options& s) {
  std::size_t slash = v.find('/');
  unsigned long i = 0, n = 0;
  if (slash == std::string::npos || !whole_number(v.substr(0, slash), i) || !whole_number(v.substr(slash + 1), n))
    invalid_value("--shard needs I/N, e.g. --shard 2/8 (the second of 8 shards)" +
           std::string(v.empty() ? "" : "; \"" + v + "\" is not"));
  if (n == 0) invalid_value("--shard " + v + ": the number of shards must be 1 or more");
  if (i < 1 || i > n)
    invalid_value("--shard " + v + ": shard " + std::to_string(i) + " is out of range: shards are numbered 1 to " +
           std::to_string(n));
  s.shard = static_cast<unsigned>(i);
  s.shards = static_cast<unsigned>(n);
}

}  // namespace

void add_sweep_options(CLI::App& app, sweep_options& s) {
  with_value(app, "--sweep", "NAME=V1,V2,...",
             "run the model for each value of the parameter NAME, or NAME=LO:HI:COUNT for COUNT values from LO "
             "to HI; repeatable (every combination runs)",
             [&s](const std::string& v) {
               if (v.empty()) invalid_value("--sweep needs NAME=V1,V2,... or NAME=LO:HI:COUNT, e.g. --sweep rate=0.1,0.2");
               s.sweeps.push_back(v);  // read in full by the sweep's plan, which names what is wrong
             });
  with_value(app, "--seeds", "K", "run each combination with the seeds 1 to K", [&s](const std::string& v) {
    s.seeds = count_of(v, 1, 1000000, "--seeds needs a number of seeds from 1 to 1000000 (the runs use seeds 1 to K)");
  });
  with_value(app, "--jobs", "J", "runs at a time, each in its own process (default: the cores)",
             [&s](const std::string& v) {
               s.jobs = count_of(v, 1, 4096, "--jobs needs a number of runs at a time from 1 to 4096");
             });
  with_value(app, "--out", "DIR", "the sweep's folder: run-NNNN/ per run, runs.csv, failed.csv",
             [&s](const std::string& v) {
               if (v.empty()) invalid_value("--out needs a folder");
               s.out = v;
             });
  with_value(app, "--shard", "I/N", "run only every N-th run from run I (a cluster's job array)",
             [&s](const std::string& v) { read_shard(v, s); });
  with_value(app, "--slurm", "N",
             "write (and submit with sbatch) a Slurm job array of N shards and a job that merges them into DIR",
             [&s](const std::string& v) {
               s.slurm = count_of(v, 1, 100000, "--slurm needs the number of shards (array tasks) from 1 to 100000");
             });
  app.add_option_function<std::vector<std::string>>(
         "--merge",
         [&s](const std::vector<std::string>& dirs) {
           if (dirs.empty()) invalid_value("--merge needs the folders of the shards to merge, e.g. --merge a b --out all");
           for (const std::string& d : dirs) {
             if (d.empty()) invalid_value("--merge needs the folders of the shards to merge, e.g. --merge a b --out all");
             s.merge.push_back(d);
           }
         },
         "join shard folders of one sweep into --out DIR")
      ->expected(0, -1)
      ->trigger_on_parse()
      ->option_text("DIR...")
      ->group(section);
}

std::string check_sweep_options(const sweep_options& s, bool model_given) {
  if (s.merging()) {
    if (s.sweeping() || s.jobs || s.shards || s.slurm)
      return "--merge joins finished folders; it takes no --sweep, --seeds, --jobs, --shard or --slurm";
    if (s.out.empty()) return "--merge needs --out DIR, the folder to merge into";
    if (model_given) return "--merge takes no model: the folders' sweep names it";
    return "";
  }
  if (!s.sweeping()) {
    if (s.jobs) return "--jobs is for sweeps (--sweep or --seeds)";
    if (s.shards) return "--shard is for sweeps (--sweep or --seeds)";
    if (s.slurm) return "--slurm is for sweeps (--sweep or --seeds)";
    if (!s.out.empty()) return "--out is for sweeps (--sweep or --seeds) and --merge";
    return "";
  }
  if (s.out.empty()) return "a sweep needs --out DIR, the folder for its runs and tables";
  if (s.slurm && s.shards) return "--slurm writes one job per shard itself; it takes no --shard";
  return "";
}

}  // namespace vvi
