// How batch mode watches a model's blocks (runner/supervisor.hpp), as a
// modeller meets it: an exception of any type ends the run with a message
// naming its type, the block and the line that threw it. The model is
// supervision_models/misbehaves.vvp; `--set fault=N` picks what it does.
#include <cstdlib>

#include "viewer_harness.hpp"

namespace {

using namespace viewer_harness;

const std::string models = VV_TESTS_DIR "/supervision_models/";
const std::string misbehaves = models + "misbehaves.vvp";

// A model that hangs must not hang the suite: every run here ends well
// within this, or the test fails.
constexpr int run_limit = 60;

test_run::result batch(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {"--batch", "--quiet"};
  argv.insert(argv.end(), args.begin(), args.end());
  return test_run::run(test_run::interpreter(argv), run_limit);
}

// misbehaves.vvp with its fault in step 1 (of one step, unless `more` says).
test_run::result fault(int n, std::vector<std::string> more = {}) {
  std::vector<std::string> args = {"--set", "fault=" + std::to_string(n)};
  if (std::find(more.begin(), more.end(), "--steps") == more.end()) args.insert(args.end(), {"--steps", "1"});
  args.insert(args.end(), more.begin(), more.end());
  args.push_back(misbehaves);
  return batch(args);
}

//! An environment variable set for the life of the object.
class scoped_environment {
 public:
  scoped_environment(const char* name, const std::string& value) : name_(name) { setenv(name, value.c_str(), 1); }
  ~scoped_environment() { unsetenv(name_); }

 private:
  const char* name_;
};

//! "misbehaves.vvp:LINE" of the line holding `text`.
std::string at(const std::string& text) {
  static const std::string model = slurp(misbehaves);
  return misbehaves + ":" + std::to_string(line_of(model, text));
}

// ---------------------------------------------------------------------------
// Exceptions
// ---------------------------------------------------------------------------

// Issue 23, item 17: `throw 42` and `throw std::string("...")` were
// "unknown exception", the text lost; std::bad_alloc and .at()'s
// std::out_of_range came without a line. Each names the thrown type (and
// text) and the line of the statement that threw.
TEST(Supervision, AnExceptionOfAnyTypeIsNamedWithTheLineThatThrewIt) {
  // Under AddressSanitizer an impossible allocation fails as in a plain run.
  const char* asan = std::getenv("ASAN_OPTIONS");
  scoped_environment may_fail("ASAN_OPTIONS", std::string(asan ? asan : "") + ":allocator_may_return_null=1");
  struct thrown {
    int fault;
    std::string line, message;
  };
  const std::vector<thrown> cases = {
      {5, "throw 42", "an exception of type int"},
      {6, "throw std::string", "an exception of type std::string: cells must be positive"},
      {7, "three.at(5)", "vector::_M_range_check: __n (which is 5) >= this->size() (which is 3)"},
      {8, "none.reserve", "std::bad_alloc"},
  };
  for (const thrown& t : cases) {
    test_run::result r = fault(t.fault);
    EXPECT_EQ(r.status, 1) << report(r);
    EXPECT_EQ(r.err, "vvinterpreter: " + at(t.line) + ": " + t.message + " (in step 1)\n") << report(r);
  }
}

}  // namespace
