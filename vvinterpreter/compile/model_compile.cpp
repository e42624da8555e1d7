#include "compile/model_compile.hpp"

#include <filesystem>
#include <future>
#include <sstream>

#include "compile/declarations_part.hpp"

namespace vvi {

namespace {

std::vector<std::string> operator+(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// Whether the compiler found an error on a line of a .vvp file: the
// program's own mistake, which compiling it whole would only repeat.
bool error_in_the_program(const std::string& output) {
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    std::size_t vvp = line.find(".vvp:");
    if (vvp != std::string::npos && line.find(": error:", vvp) != std::string::npos) return true;
  }
  return false;
}

class compilation {
 public:
  explicit compilation(const compile_job& j) : j_(j) {}

  compile_outcome run() {
    if (j_.declarations.empty()) return whole();
    declarations_part part = find_declarations(j_.cache_dir, j_.declarations_key);
    if (!part.why.empty() && part.state == declarations_part::missing) out_.notes += "note: " + part.why + "; it was compiled again\n";
    if (part.state == declarations_part::unusable || (part.state == declarations_part::missing && !j_.make_part))
      return whole();
    if (part.state == declarations_part::usable) {
      // The part compiles and defines nothing the program defines: what
      // fails here fails in the program.
      out_.apart = true;
      out_.result = run(apart() + std::vector<std::string>{"-shared"} + depfile() +
                        std::vector<std::string>{"-o", so(), cpp(), part.object} + j_.libraries);
      return out_;
    }
    return with_new_part();
  }

 private:
  std::string cpp() const { return j_.work + "/model.cpp"; }
  std::string so() const { return j_.work + "/model.so"; }
  std::string object() const { return j_.work + "/model.o"; }
  std::vector<std::string> depfile() const { return {"-MD", "-MF", j_.work + "/model.d"}; }
  std::vector<std::string> apart() const { return j_.compiler + std::vector<std::string>{"-DVV_DECLARATIONS_APART"}; }

  process_result run(const std::vector<std::string>& argv) {
    out_.commands += command_line(argv) + "\n";
    return run_process(argv, j_.niceness, j_.cancel);
  }

  compile_outcome whole() {
    out_.apart = false;
    out_.result = run(j_.compiler + std::vector<std::string>{"-shared"} + depfile() +
                      std::vector<std::string>{"-o", so(), cpp()} + j_.libraries);
    return out_;
  }

  // No part for these declarations yet: it compiles beside the program,
  // then the two are linked.
  compile_outcome with_new_part() {
    declarations_request request{j_.cache_dir, j_.declarations_key, j_.declarations, j_.include, j_.compiler};
    std::future<declarations_part> building =
        std::async(std::launch::async, [request] { return build_declarations(request); });
    process_result program = run(apart() + depfile() + std::vector<std::string>{"-c", "-o", object(), cpp()});
    declarations_part part = building.get();
    out_.commands += "(the declarations' part: " + j_.cache_dir + "/decls/" + j_.declarations_key + "/command)\n";
    std::error_code ec;
    if (program.cancelled || (part.state == declarations_part::usable && program.status != 0)) {
      // Cancelled: nothing is concluded of the part, nor compiled whole.
      std::filesystem::remove(object(), ec);
      out_.result = program;
      return out_;
    }
    if (part.state == declarations_part::usable) {
      process_result linked = run(j_.compiler + std::vector<std::string>{"-shared", "-o", so(), object(), part.object} +
                                  j_.libraries);
      std::filesystem::remove(object(), ec);
      if (linked.cancelled) {
        out_.result = linked;
        return out_;
      }
      if (linked.status == 0) {
        out_.apart = true;
        out_.result = {0, program.output + linked.output};  // the program's warnings
        return out_;
      }
      return whole_instead("it did not link with the program");
    }
    std::filesystem::remove(object(), ec);
    if (program.status != 0 && error_in_the_program(program.output)) {
      out_.result = program;
      return out_;
    }
    if (part.state == declarations_part::unusable) return whole();  // the cache has its verdict
    return whole_instead(part.why);
  }

  // The part could not serve: the program compiled whole. If that works,
  // the cache remembers, and later builds go straight to it.
  compile_outcome whole_instead(const std::string& why) {
    whole();
    if (out_.result.status == 0 && !out_.result.cancelled) record_unusable(j_.cache_dir, j_.declarations_key, why);
    return out_;
  }

  const compile_job& j_;
  compile_outcome out_;
};

}  // namespace

compile_outcome compile_model(const compile_job& job) { return compilation(job).run(); }

}  // namespace vvi
