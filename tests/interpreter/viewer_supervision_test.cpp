// The viewer's end under supervision (runner/supervisor.hpp): quitting
// never waits for ever on a model's close block.
#include <cstdlib>

#include "viewer_harness.hpp"

namespace {

using namespace viewer_harness;

// Issue 23, item 13: a close block that never returned hung the viewer's
// quit, whatever the options. Closing has a limit (10 s, VV_CLOSE_TIMEOUT):
// the window goes, with a message naming the close block's line, and the
// viewer exits 1.
TEST(ViewerSupervision, QuitEndsACloseBlockThatNeverReturns) {
  const std::string model = VV_TESTS_DIR "/supervision_models/never_returns.vvp";
  std::string d = fresh_dir("viewer_close_never_returns");
  write_text(d + "s.txt", script({"step 1", "quit"}));
  setenv("VV_CLOSE_TIMEOUT", "0.5", 1);
  test_run::result r = test_run::run(test_run::in_virtual_display(test_run::interpreter({"--script", d + "s.txt", model})), 90);
  unsetenv("VV_CLOSE_TIMEOUT");
  ASSERT_FALSE(r.timed_out) << "the close block hung the viewer's quit\n" << report(r);
  EXPECT_EQ(r.status, 1) << report(r);
  EXPECT_TRUE(has(r.out, "stepped\n")) << report(r);
  EXPECT_EQ(viewer_errors(r.err),
            std::vector<std::string>{"vvinterpreter: the viewer could not close: " + model + ":" +
                                     std::to_string(line_of(slurp(model), "for (;;)")) +
                                     ": the close block ran longer than 0.5 s and was ended"})
      << report(r);
}

}  // namespace
