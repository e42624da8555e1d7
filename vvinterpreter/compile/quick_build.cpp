#include "compile/quick_build.hpp"

#include "compile/build_config.hpp"
#include "compile/process.hpp"

namespace vvi {

bool quick_builds_available() { return *config::quick_compiler != '\0'; }

std::vector<std::string> quick_flags(const std::string& include) {
  // As the optimised build's (model_build.cpp), but -O0: line tables for
  // crash reports, the same visibility, OpenMP for parallel forall.
  return {"-std=c++17", "-O0",       "-g1",     "-gdwarf-4", "-fPIC", "-fvisibility=hidden", "-fvisibility-inlines-hidden",
          "-fopenmp",   "-isystem", include};
}

header_request quick_header(const std::string& cache_dir, const std::string& include, const std::string& stamp) {
  return make_header_request(cache_dir, include, quick_flags(include), config::quick_compiler, true, stamp);
}

std::vector<std::string> quick_command(const quick_job& job) {
  std::vector<std::string> argv = {config::quick_compiler, "-include-pch", job.header_file};
  std::vector<std::string> flags = quick_flags(job.include);
  argv.insert(argv.end(), flags.begin(), flags.end());
  argv.insert(argv.end(), {"-Wall", "-Wextra", "-I", job.model_dir, "-DVV_DECLARATIONS_APART", "-shared", "-MD", "-MF",
                           job.work + "/model.d", "-o", job.work + "/model.so", job.work + "/model.cpp", job.part});
  argv.insert(argv.end(), job.libraries.begin(), job.libraries.end());
  return argv;
}

}  // namespace vvi
