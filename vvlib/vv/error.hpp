// Run-time errors of the vertex-vertex algebra and the source location they
// are reported at.
#pragma once

#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#if __has_include(<execinfo.h>)
#include <execinfo.h>
#define VV_HAVE_BACKTRACE 1
#endif

namespace vv {

//! Where an operation was written. Every algebra function takes one as a
//! defaulted last argument, so the location is the caller's: in a translated
//! program the `#line` directives make that the .vvp file and line.
struct where {
  const char* file = nullptr;
  int line = 0;

  static constexpr where here(const char* f = __builtin_FILE(),
                              int l = __builtin_LINE()) noexcept {
    return where{f, l};
  }
};

//! Every run-time error of vvlib: a null target, a duplicate in `make`, a
//! missing half-edge, a malformed .vvm file, ...  what() is the whole
//! one-line message, "file:line: operation: problem".
class error : public std::runtime_error {
 public:
  error(const where& w, const std::string& operation, const std::string& problem)
      : std::runtime_error(compose(w, operation, problem)),
        file_(w.file ? w.file : ""), line_(w.line) {
    if (!w.file) keep_frames();
  }

  //! An error in a data file (line 0: the file as a whole).
  error(std::string file, int line, const std::string& problem)
      : std::runtime_error(file + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " +
                           problem),
        file_(std::move(file)), line_(line) {}

  const std::string& file() const noexcept { return file_; }
  int line() const noexcept { return line_; }
  //! Return addresses where an error without a source location was raised
  //! (`v->pos` on the null vertex cannot name its line): a host finds the
  //! .vvp line in the model's line tables (vvinterpreter does).
  const std::vector<void*>& frames() const noexcept { return frames_; }

 private:
  void keep_frames() {
#ifdef VV_HAVE_BACKTRACE
    frames_.resize(48);
    frames_.resize(static_cast<std::size_t>(::backtrace(frames_.data(), static_cast<int>(frames_.size()))));
#endif
  }

  static std::string compose(const where& w, const std::string& operation,
                             const std::string& problem) {
    std::ostringstream os;
    if (w.file) os << w.file << ':' << w.line << ": ";
    os << operation << ": " << problem;
    return os.str();
  }

  std::string file_;
  int line_;
  std::vector<void*> frames_;
};

//! Throws vv::error with the problem text make_problem() builds. Kept out
//! of line and marked cold so that the checks on hot paths inline to a
//! test and a call: the message is only built when it is needed.
template <class MakeProblem>
[[noreturn, gnu::noinline, gnu::cold]] void raise(const where& w, const char* operation,
                                                 MakeProblem&& make_problem) {
  throw error(w, operation, make_problem());
}

//! Runs fn; a vv::error it throws (a file's own "file:line: problem") is
//! thrown again as an error of `operation` at w, the caller's line.
template <class Fn>
void at_caller(const where& w, const char* operation, Fn&& fn) {
  try {
    fn();
  } catch (const error& e) {
    throw error(w, operation, e.what());
  }
}

}  // namespace vv
