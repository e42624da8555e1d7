#include "experiment/slurm.hpp"

#include <cstdio>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

#include "app/files.hpp"
#include "experiment/child_process.hpp"
#include "experiment/sweep_folder.hpp"

namespace vvi {

namespace fs = std::filesystem;

namespace {

std::string job_name(const slurm_job& j) {
  std::string stem = fs::path(j.model).stem().string();
  std::string name;
  for (char c : stem) name += std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' ? c : '_';
  return name;
}

std::string words(const std::vector<std::string>& ws) {
  std::string out;
  for (const std::string& w : ws) out += " " + shell_word(w);
  return out;
}

// The shard's folder: DIR/shards/I.
std::string shard_folder(const slurm_job& j, const std::string& i) { return absolute_path(j.sweep.out) + "/shards/" + i; }

// sbatch on the PATH, or "".
std::string find_sbatch() {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "";
  for (std::size_t from = 0; from <= dirs.size();) {
    std::size_t colon = dirs.find(':', from);
    if (colon == std::string::npos) colon = dirs.size();
    std::string candidate = (colon == from ? std::string(".") : dirs.substr(from, colon - from)) + "/sbatch";
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
    from = colon + 1;
  }
  return "";
}

// The job id sbatch --parsable printed ("123" or "123;cluster"), or "".
std::string job_id(const std::string& out) {
  std::string id = out.substr(0, out.find_first_of(";\n"));
  return !id.empty() && id.find_first_not_of("0123456789") == std::string::npos ? id : "";
}

}  // namespace

std::string shell_word(const std::string& s) {
  if (!s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-+=./:,@%") ==
                        std::string::npos)
    return s;
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string array_script(const slurm_job& j) {
  const std::string n = std::to_string(j.sweep.slurm);
  const unsigned jobs = j.sweep.jobs ? j.sweep.jobs : 1;
  std::vector<std::string> cmd = {j.self};
  for (const std::string& typed : j.sweep.sweeps) cmd.insert(cmd.end(), {"--sweep", typed});
  if (j.sweep.seeds) cmd.insert(cmd.end(), {"--seeds", std::to_string(j.sweep.seeds)});
  else cmd.insert(cmd.end(), {"--seed", std::to_string(j.seed)});
  cmd.insert(cmd.end(), {"--jobs", std::to_string(jobs), "--cache", j.args.cache});
  cmd.insert(cmd.end(), j.args.batch_options.begin(), j.args.batch_options.end());
  std::string out = absolute_path(j.sweep.out);
  return "#!/bin/sh\n"
         "# A vv sweep as a Slurm job array, one task per shard (written by vvinterpreter --slurm).\n"
         "# The merge job (merge.sbatch) joins the shards into " + out + " when all have ended.\n"
         "#SBATCH --job-name=vv-sweep-" + job_name(j) + "\n"
         "#SBATCH --array=1-" + n + "\n"
         "#SBATCH --cpus-per-task=" + std::to_string(jobs) + "\n"
         "#SBATCH --output=" + out + "/slurm/shard-%a.out\n"
         "exec" + words(cmd) + " \\\n"
         "  --shard \"$SLURM_ARRAY_TASK_ID/" + n + "\" --out " + shell_word(out + "/shards") +
         "/\"$SLURM_ARRAY_TASK_ID\" " + shell_word(j.args.model) + "\n";
}

std::string merge_script(const slurm_job& j) {
  std::string out = absolute_path(j.sweep.out);
  std::vector<std::string> cmd = {j.self, "--merge"};
  for (unsigned i = 1; i <= j.sweep.slurm; ++i) cmd.push_back(shard_folder(j, std::to_string(i)));
  cmd.insert(cmd.end(), {"--out", out});
  return "#!/bin/sh\n"
         "# Joins the shards of the vv sweep's job array (sweep.sbatch) into " + out + "\n"
         "# (written by vvinterpreter --slurm; submit it with --dependency=afterany:ARRAY_JOB_ID).\n"
         "#SBATCH --job-name=vv-merge-" + job_name(j) + "\n"
         "#SBATCH --output=" + out + "/slurm/merge.out\n"
         "exec" + words(cmd) + "\n";
}

int submit_to_slurm(const slurm_job& j, bool quiet) {
  std::string dir = j.sweep.out + "/slurm";
  std::error_code ec;
  fs::create_directories(dir, ec);
  std::string e = ec ? dir + ": " + ec.message() : write_in_folder(dir, "sweep.sbatch", array_script(j));
  if (e.empty()) e = write_in_folder(dir, "merge.sbatch", merge_script(j));
  if (!e.empty()) {
    std::fprintf(stderr, "vvinterpreter: %s\n", e.c_str());
    return 1;
  }
  std::string array = absolute_path(dir + "/sweep.sbatch"), merge = absolute_path(dir + "/merge.sbatch");
  std::string sbatch = find_sbatch();
  if (sbatch.empty()) {
    std::printf("%s", array_script(j).c_str());
    std::printf("\nsbatch was not found. The scripts are written; on the cluster, submit them with\n"
                "  jobid=$(sbatch --parsable %s)\n"
                "  sbatch --dependency=afterany:$jobid %s\n",
                shell_word(array).c_str(), shell_word(merge).c_str());
    return 0;
  }
  captured a = run_captured({sbatch, "--parsable", array});
  std::string id = job_id(a.out);
  if (a.status != 0 || id.empty()) {
    std::fprintf(stderr, "vvinterpreter: sbatch %s failed: %s%s", array.c_str(), a.err.c_str(), a.out.c_str());
    return 1;
  }
  captured m = run_captured({sbatch, "--parsable", "--dependency=afterany:" + id, merge});
  std::string merge_id = job_id(m.out);
  if (m.status != 0 || merge_id.empty()) {
    std::fprintf(stderr, "vvinterpreter: the job array %s was submitted, but sbatch %s failed: %s%s", id.c_str(),
                 merge.c_str(), m.err.c_str(), m.out.c_str());
    return 1;
  }
  if (!quiet)
    std::printf("submitted job array %s (%u shards) and merge job %s; the tables will be in %s\n", id.c_str(),
                j.sweep.slurm, merge_id.c_str(), absolute_path(j.sweep.out).c_str());
  return 0;
}

}  // namespace vvi
