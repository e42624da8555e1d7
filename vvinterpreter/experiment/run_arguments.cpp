#include "experiment/run_arguments.hpp"

#include <filesystem>

#include "app/files.hpp"

namespace vvi {

namespace {

// Options the runs do not get, and whether each takes a value.
struct dropped {
  const char* name;
  bool value;
};
const dropped dropped_options[] = {
    {"--sweep", true}, {"--seeds", true}, {"--jobs", true}, {"--shard", true}, {"--out", true},
    {"--slurm", true}, {"--merge", true}, {"--cache", true}, {"--seed", true}, {"--batch", false},
    {"--rebuild", false},  // the sweep compiled the model; the runs find it in the cache
};

}  // namespace

run_arguments arguments_of_runs(int argc, const char* const* argv, const std::string& model, const std::string& cache,
                                const std::string& plots) {
  run_arguments a;
  a.model = absolute_path(model);
  a.cache = absolute_path(cache);
  a.plots_given = !plots.empty();
  a.plots = plots.empty() ? "plots.csv" : plots;
  bool model_seen = false;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    bool skip = false;
    for (const dropped& d : dropped_options) {
      if (arg == d.name) {
        skip = true;
        if (d.value && i + 1 < argc && argv[i + 1][0] != '-') ++i;  // "--out DIR"
      } else if (d.value && arg.rfind(std::string(d.name) + "=", 0) == 0) {
        skip = true;  // "--out=DIR"
      }
    }
    if (skip) continue;
    if (!model_seen && arg == model) {  // the model: given apart, absolute
      model_seen = true;
      continue;
    }
    a.batch_options.push_back(arg);
  }
  return a;
}

std::vector<std::string> options_deciding_results(const run_arguments& a) {
  std::vector<std::string> out;
  for (const std::string& o : a.batch_options)
    if (o != "--quiet") out.push_back(o);
  return out;
}

std::vector<std::string> run_command(const std::string& self, const run_arguments& a,
                                     const std::vector<std::pair<std::string, std::string>>& settings,
                                     std::uint64_t seed) {
  std::vector<std::string> cmd = {self, "--batch", "--cache", a.cache};
  cmd.insert(cmd.end(), a.batch_options.begin(), a.batch_options.end());
  for (const auto& [name, value] : settings) {
    cmd.push_back("--set");
    cmd.push_back(name + "=" + value);
  }
  cmd.push_back("--seed");
  cmd.push_back(std::to_string(seed));
  if (!a.plots_given) {
    cmd.push_back("--plots");
    cmd.push_back(a.plots);
  }
  cmd.push_back(a.model);
  return cmd;
}

}  // namespace vvi
