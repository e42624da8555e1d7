// The optimised build behind a quick one is stopped when it can only be
// thrown away: a newer edit compiles, or the viewer closes. Before, a stale
// optimised build compiled to its end (about 9 s of g++ for an example)
// before the newest edit's could start, and closing the viewer waited for
// it.
//
// The model's optimised compile is made to hang: below its property blocks
// it includes a header that, only when optimising (__OPTIMIZE__, -O1),
// includes a named pipe nobody writes to. The quick build (-O0) never
// reads it. The test opens the pipe for writing at its end, so a compiler
// that was not stopped finishes, and the test fails instead of hanging.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <future>
#include <set>
#include <string>
#include <thread>

#include "cache_harness.hpp"
#include "control/model_controller.hpp"
#include "controller_harness.hpp"
#include "in_process_options.hpp"
#include "test_files.hpp"

namespace fs = std::filesystem;

namespace {

// The optimised builds' work folders (plugins/tmp-KEY-ID) now in the cache.
std::set<std::string> work_folders(const std::string& cache) {
  std::set<std::string> found;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(cache + "/plugins", ec))
    if (e.path().filename().string().rfind("tmp-", 0) == 0) found.insert(e.path().filename().string());
  return found;
}

// Lets every compiler waiting on the pipe go on (it reads an empty file).
void release_waiting_compilers(const std::string& pipe) {
  for (int i = 0; i < 50; ++i) {
    int fd = ::open(pipe.c_str(), O_WRONLY | O_NONBLOCK);
    if (fd >= 0) ::close(fd);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

}  // namespace

TEST(StaleOptimisedBuild, ANewerEditStopsItAndClosingStopsTheOneRunning) {
  using namespace controller_harness;
  const std::string dir = fresh_dir("stale_optimised");
  fs::create_directories(dir + "examples");
  fs::copy(VV_SOURCE_DIR "/models", dir + "models", fs::copy_options::recursive);
  const std::string model = dir + "examples/m.vvp";
  write(model, test_files::slurp(VV_SOURCE_DIR "/examples/growing_ring.vvp"));
  const std::string pipe = dir + "examples/never_written";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  write(dir + "examples/slow.hpp", "#ifdef __OPTIMIZE__\n#include \"never_written\"\n#endif\n");

  vvi::options o = in_process_options(model);
  o.cache = cache_with_header(dir);
  o.batch = false;  // the viewer's builds: quick after an edit, the optimised one behind
  o.quiet = true;
  recording_view view;
  recording_jobs jobs{view};
  auto c = std::make_unique<vvi::model_controller>(o, jobs, view);
  // Polls until `done` or 60 s have passed; whether `done` came.
  auto poll_until = [&](auto done) {
    for (int i = 0; i < 6000; ++i) {
      c->poll(0);
      if (done()) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
  };
  c->submit(command::of(command::reload));  // the first build, optimised: before the include
  ASSERT_TRUE(poll_until([&] { return c->idle(); }));
  ASSERT_TRUE(c->runner().model()) << (view.errors.empty() ? "" : view.errors.back());
  const std::string cache = o.cache;
  ASSERT_TRUE(work_folders(cache).empty());
  view.said.clear();

  // Edit 1: its quick build runs; its optimised build waits on the pipe.
  write(model, test_files::slurp(model) + "\n#include \"slow.hpp\"\n[[maybe_unused]] static const int edit_1 = 1;\n");
  c->submit(command::of(command::reload));
  const std::string quick_reload = "reloaded " + model + " (unoptimised until its optimised build is ready)";
  ASSERT_TRUE(poll_until([&] { return view.said.size() == 1 && !work_folders(cache).empty(); }))
      << ::testing::PrintToString(view.said);
  EXPECT_EQ(view.said[0], quick_reload);
  EXPECT_TRUE(c->optimising());
  const std::set<std::string> stale = work_folders(cache);
  ASSERT_EQ(stale.size(), 1u);

  // Edit 2 compiles: edit 1's optimised build is stopped (its work folder
  // goes), and edit 2's starts in a folder of its own.
  write(model, test_files::slurp(model) + "[[maybe_unused]] static const int edit_2 = 2;\n");
  c->submit(command::of(command::reload));
  const bool replaced = poll_until([&] {
    std::set<std::string> now = work_folders(cache);
    return view.said.size() == 2 && now.size() == 1 && now != stale;
  });
  EXPECT_TRUE(replaced) << "edit 1's optimised build went on: " << ::testing::PrintToString(work_folders(cache));
  ASSERT_EQ(view.said.size(), 2u) << ::testing::PrintToString(view.said);
  EXPECT_EQ(view.said[1], quick_reload);
  EXPECT_TRUE(c->optimising());
  EXPECT_TRUE(view.errors.empty()) << view.errors.back();

  // Closing does not wait for edit 2's optimised build, which would never end.
  std::future<void> closed = std::async(std::launch::async, [&c] { c.reset(); });
  const bool closed_at_once = closed.wait_for(std::chrono::seconds(60)) == std::future_status::ready;
  EXPECT_TRUE(closed_at_once) << "closing waited for the optimised build";
  if (!closed_at_once) release_waiting_compilers(pipe);
  closed.wait();
  release_waiting_compilers(pipe);  // whatever was not stopped
  EXPECT_TRUE(work_folders(cache).empty()) << "a stopped build left its work folder";
}
