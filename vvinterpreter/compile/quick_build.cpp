#include "compile/quick_build.hpp"

#include "compile/build_config.hpp"
#include "compile/hashing.hpp"
#include "compile/process.hpp"

namespace vvi {

bool quick_builds_available() { return *config::quick_compiler != '\0'; }

std::vector<std::string> quick_flags(const std::string& include) {
  // As the optimised build's (model_build.cpp), but -O0: line tables for
  // crash reports (the DWARF version before -g1, or clang writes all of
  // the debug information), the same visibility, OpenMP for parallel forall.
  return {"-std=c++17", "-O0",       "-gdwarf-4", "-g1",     "-fPIC", "-fvisibility=hidden", "-fvisibility-inlines-hidden",
          "-fopenmp",   "-isystem", include};
}

header_request quick_header(const std::string& cache_dir, const std::string& include, const std::string& stamp) {
  return make_header_request(cache_dir, include, quick_flags(include), config::quick_compiler, true, stamp);
}

std::vector<std::string> quick_program_flags(const std::string& model_dir) {
  return {"-Wall", "-Wextra", "-I", model_dir, "-DVV_DECLARATIONS_APART"};
}

namespace {

// The compiler on a precompiled header, with every flag of the program.
std::vector<std::string> compiler_on(const std::string& pch, const std::string& include, const std::string& model_dir) {
  std::vector<std::string> argv = {config::quick_compiler, "-include-pch", pch};
  std::vector<std::string> flags = quick_flags(include), program = quick_program_flags(model_dir);
  argv.insert(argv.end(), flags.begin(), flags.end());
  argv.insert(argv.end(), program.begin(), program.end());
  return argv;
}

}  // namespace

declarations_header_request quick_declarations_header(const std::string& cache_dir, const std::string& include,
                                                      const std::string& model_dir, const std::string& vvlib_pch,
                                                      const std::string& text) {
  declarations_header_request r;
  r.cache_dir = cache_dir;
  r.include = include;
  r.text = text;
  // The vvlib header's path names its build (KEY.ID): one built again
  // makes a new key here too.
  r.argv = compiler_on(vvlib_pch, include, model_dir);
  r.key = content_hash().add(command_line(r.argv)).add(text).hex();
  return r;
}

std::vector<std::string> quick_command(const quick_job& job) {
  std::vector<std::string> argv = compiler_on(job.header_file, job.include, job.model_dir);
  argv.insert(argv.end(), {"-shared", "-MD", "-MF", job.work + "/model.d", "-o", job.work + "/model.so",
                           job.work + "/" + job.source, job.part});
  argv.insert(argv.end(), job.libraries.begin(), job.libraries.end());
  return argv;
}

}  // namespace vvi
