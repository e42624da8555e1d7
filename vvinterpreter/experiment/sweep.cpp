#include "experiment/sweep.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include <vv/io/files.hpp>

#include "app/files.hpp"
#include "experiment/child_process.hpp"
#include "experiment/model_check.hpp"
#include "experiment/run_arguments.hpp"
#include "experiment/run_queue.hpp"
#include "experiment/run_record.hpp"
#include "experiment/runs_table.hpp"
#include "experiment/slurm.hpp"
#include "experiment/sweep_folder.hpp"
#include "experiment/sweep_identity.hpp"
#include "experiment/sweep_progress.hpp"

namespace vvi {

namespace fs = std::filesystem;

namespace {

int refuse(const std::string& why, int status = 2) {
  std::fprintf(stderr, "vvinterpreter: %s\n", why.c_str());
  return status;
}

// What the other options cannot be in a sweep: "" or why.
std::string unusable_with_sweep(const options& o, int argc, const char* const* argv) {
  if (o.list_params) return "--list-params lists the parameters; it cannot be used with a sweep";
  if (o.compile_only) return "--compile-only cannot be used with a sweep (a sweep compiles the model itself, once)";
  if (!o.script.empty()) return "--script drives the viewer; a sweep runs headless";
  if (o.debug || o.in_process)
    return std::string(o.debug ? "--debug" : "--in-process") +
           " runs the model unsupervised, for a debugger; a sweep runs each model supervised";
  const std::pair<const char*, const std::string*> outputs[] = {
      {"--export", &o.export_path}, {"--screenshot", &o.screenshot}, {"--plots", &o.plots_path}, {"--frames", &o.frames}};
  for (const auto& [name, path] : outputs)
    if (!path->empty() && (*path)[0] == '/')
      return std::string(name) + " " + *path +
             ": in a sweep each run writes its files into its own folder (DIR/run-NNNN/); give a relative name";
  if (o.sweep.seeds)
    for (int i = 1; i < argc; ++i)
      if (std::string(argv[i]) == "--seed" || std::string(argv[i]).rfind("--seed=", 0) == 0)
        return "--seeds " + std::to_string(o.sweep.seeds) + " runs seeds 1 to " + std::to_string(o.sweep.seeds) +
               "; --seed cannot be given with it";
  return "";
}

std::string this_program() {
  std::error_code ec;
  fs::path self = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("vvinterpreter") : self.string();
}

// A run's folder, emptied: what an unfinished or failed run left is gone.
std::string fresh_folder(const std::string& folder) {
  std::error_code ec;
  fs::remove_all(folder, ec);
  if (ec) return folder + ": cannot empty the run's folder: " + ec.message();
  fs::create_directories(folder, ec);
  if (ec) return folder + ": cannot make the run's folder: " + ec.message();
  return "";
}

// The outcome of a run that ended, marked in its folder: "" or the error.
std::string record(const run_end& e, const std::string& folder, const run_arguments& a, const options& o,
                   bool& failed) {
  failed = false;
  if (e.interrupted) return "";
  if (e.start_error.empty() && WIFEXITED(e.wait_status) && WEXITSTATUS(e.wait_status) == 0) return mark_finished(folder);
  failed = true;
  run_failure f;
  if (!e.start_error.empty()) {
    f.reason = e.start_error;
  } else {
    std::string err = vv::io::read_file(folder + "/" + run_error_file).value_or("");
    f = failure_from_output(err, how_it_ended(e.wait_status), a.model, o.model);
  }
  return mark_failed(folder, f);
}

// Writes DIR/runs.csv and DIR/failed.csv: "" or the error.
std::string write_tables(const sweep_plan& plan, const std::string& dir, const std::string& plots) {
  try {
    std::string e = write_in_folder(dir, "runs.csv", runs_csv(plan, dir, plots));
    if (e.empty()) e = write_in_folder(dir, "failed.csv", failed_csv(plan, dir));
    return e;
  } catch (const std::exception& e) {
    return e.what();
  }
}

struct sweep_setup {
  std::vector<swept_parameter> parameters;
  run_arguments args;
  sweep_identity identity;
};

}  // namespace

int run_sweep(const options& o, int argc, const char* const* argv) {
  if (std::string why = unusable_with_sweep(o, argc, argv); !why.empty()) return refuse(why);
  sweep_setup s;
  try {
    for (const std::string& typed : o.sweep.sweeps) s.parameters.push_back(parse_sweep(typed));
    (void)sweep_plan(s.parameters, o.sweep.seeds, o.seed);  // a parameter swept twice
  } catch (const std::invalid_argument& e) {
    return refuse(e.what());
  }
  const std::string self = this_program();
  std::string cache = o.cache.empty() ? default_cache_dir() : o.cache;
  s.args = arguments_of_runs(argc, argv, o.model, cache, o.plots_path);
  checked_model m = check_model(o, self, s.args, s.parameters);
  if (!m.error.empty()) return refuse(m.error, 1);
  s.identity = {m.program, s.args.plots, s.parameters, o.sweep.seeds, o.seed, options_deciding_results(s.args)};
  sweep_plan plan = s.identity.plan();

  sweep_folder folder(o.sweep.out, s.identity.text());
  if (!folder.error().empty()) return refuse(folder.error(), 1);
  if (o.sweep.slurm) {
    slurm_job job{self, s.args, o.sweep, o.seed, o.model};
    return submit_to_slurm(job, o.quiet);
  }

  // The runs of this sweep (or shard) that are not finished yet.
  std::vector<unsigned> mine = o.sweep.shards ? plan.shard(o.sweep.shard, o.sweep.shards) : plan.shard(1, 1);
  std::vector<queued_run> queue;
  std::size_t finished_before = 0;
  for (unsigned n : mine) {
    std::string dir = o.sweep.out + "/" + plan.folder(n);
    if (state_of_run(dir) == run_state::finished) {
      ++finished_before;
      continue;
    }
    if (std::string e = fresh_folder(dir); !e.empty()) return refuse(e, 1);
    planned_run r = plan.run(n);
    std::vector<std::pair<std::string, std::string>> settings;
    for (std::size_t k = 0; k < s.parameters.size(); ++k) settings.emplace_back(s.parameters[k].name, r.values[k]);
    queue.push_back({n, run_command(self, s.args, settings, r.seed), dir});
  }
  unsigned jobs = o.sweep.jobs ? o.sweep.jobs : usable_cores();
  if (!o.quiet) {
    std::printf("%zu runs%s: %zu finished before, %zu to run, %u at a time\n", mine.size(),
                o.sweep.shards ? (" in shard " + std::to_string(o.sweep.shard) + "/" + std::to_string(o.sweep.shards) +
                                  " of " + std::to_string(plan.size()))
                                     .c_str()
                               : "",
                finished_before, queue.size(), jobs);
    std::fflush(stdout);
  }

  bool on_terminal = isatty(STDERR_FILENO);
  sweep_progress progress(queue.size(), on_terminal ? stderr : stdout, on_terminal);
  std::size_t failures = 0;
  std::string record_error;
  int interrupted = run_all(
      queue, jobs,
      [&](const run_end& e) {
        bool failed = false;
        std::string err = record(e, o.sweep.out + "/" + plan.folder(e.number), s.args, o, failed);
        if (!err.empty() && record_error.empty()) record_error = err;
        if (e.interrupted) return;
        failures += failed;
        if (!o.quiet) progress.ended(failed, "run " + std::to_string(e.number) + " (" + plan.describe(plan.run(e.number)) + ")");
      },
      [&] {
        if (!o.quiet) progress.tick();
      });
  if (!o.quiet) progress.finish();
  if (!record_error.empty()) return refuse(record_error, 1);
  if (std::string e = write_tables(plan, o.sweep.out, s.args.plots); !e.empty()) return refuse(e, 1);
  if (interrupted) {
    refuse(std::string("interrupted (SIG") + (sigabbrev_np(interrupted) ? sigabbrev_np(interrupted) : "?") +
               "); the unfinished runs run when the same command is given again",
           1);
    return 128 + interrupted;
  }
  if (!o.quiet) std::printf("wrote %s/runs.csv\n", o.sweep.out.c_str());
  if (failures) {
    return refuse(std::to_string(failures) + " of " + std::to_string(queue.size()) + " runs failed: see " +
                      o.sweep.out + "/failed.csv",
                  1);
  }
  return 0;
}

}  // namespace vvi
