// The viewer's file events (vvinterpreter/viewer/file_events.hpp): a save
// of a watched file is told at once, however the editor saves it, and
// nothing else in its folder is. Each event told is a wake, and inotify
// delivers events in order: "only the watched file woke it" is checked by
// counting the wakes once the watched file's save, made last, was told
// (and a moment more, for a wake that should not come).
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <string>
#include <thread>

#include "viewer/file_events.hpp"

namespace fs = std::filesystem;

namespace {

class wake_count {
 public:
  explicit wake_count(vvi::file_events& events) : events_(events) {
    events_.saved().connect([this] {
      std::lock_guard<std::mutex> lock(m_);
      ++wakes_;
      cv_.notify_all();
    });
  }
  ~wake_count() { events_.saved().disconnect(); }
  //! Waits (up to 10 s) until there have been `n` wakes in all.
  bool wakes_reach(int n) {
    std::unique_lock<std::mutex> lock(m_);
    return cv_.wait_for(lock, std::chrono::seconds(10), [&] { return wakes_ >= n; });
  }
  //! The wakes in all, a moment after the last awaited one.
  int wakes() {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    std::lock_guard<std::mutex> lock(m_);
    return wakes_;
  }

 private:
  vvi::file_events& events_;
  std::mutex m_;
  std::condition_variable cv_;
  int wakes_ = 0;
};

std::string events_folder(const std::string& name) {
  std::string dir = fs::temp_directory_path().string() + "/vv_file_events_" + name + "_" + std::to_string(getpid()) + "/";
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write_text(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// As editors save: a new file renamed over the old.
void save_by_renaming(const std::string& path, const std::string& text) {
  write_text(path + ".new", text);
  fs::rename(path + ".new", path);
}

}  // namespace

TEST(FileEvents, ASaveInPlaceOrByRenamingIsToldAtOnceAndTakenOnce) {
  const std::string dir = events_folder("saves");
  write_text(dir + "m.vvp", "mesh S;\n");
  vvi::file_events events;
  wake_count t(events);
  events.watch({dir + "m.vvp"});
  EXPECT_FALSE(events.pending());

  write_text(dir + "m.vvp", "mesh S; // in place\n");
  ASSERT_TRUE(t.wakes_reach(1));
  EXPECT_TRUE(events.pending());
  EXPECT_TRUE(events.take());
  EXPECT_FALSE(events.take());

  save_by_renaming(dir + "m.vvp", "mesh S; // renamed\n");
  ASSERT_TRUE(t.wakes_reach(2));
  EXPECT_TRUE(events.take());
  fs::remove_all(dir);
}

TEST(FileEvents, OnlyTheWatchedFilesOfAFolderAreTold) {
  const std::string dir = events_folder("others");
  write_text(dir + "m.vvp", "mesh S;\n");
  write_text(dir + "shape.vvm", "<vvm/>\n");
  vvi::file_events events;
  wake_count t(events);
  events.watch({dir + "m.vvp"});
  // The model's outputs beside it, a file it reads that is not watched,
  // and the editor's own files.
  write_text(dir + "out.obj", "v 0 0 0\n");
  save_by_renaming(dir + "shape.vvm", "<vvm></vvm>\n");
  write_text(dir + ".m.vvp.swp", "x");
  fs::remove(dir + ".m.vvp.swp");
  save_by_renaming(dir + "m.vvp", "mesh S; // saved\n");
  ASSERT_TRUE(t.wakes_reach(1));
  EXPECT_EQ(t.wakes(), 1);  // the events before it told nothing
  fs::remove_all(dir);
}

TEST(FileEvents, WatchingOtherFilesStopsTellingTheOldOnesAndARemovalIsTold) {
  const std::string old_dir = events_folder("old"), new_dir = events_folder("new");
  write_text(old_dir + "m.vvp", "mesh S;\n");
  write_text(new_dir + "m.vvp", "mesh S;\n");
  write_text(new_dir + "part.hpp", "// a header the model includes\n");
  vvi::file_events events;
  wake_count t(events);
  events.watch({old_dir + "m.vvp"});
  events.watch({new_dir + "m.vvp", new_dir + "part.hpp"});
  save_by_renaming(old_dir + "m.vvp", "mesh S; // no longer watched\n");
  write_text(new_dir + "part.hpp", "// changed\n");
  ASSERT_TRUE(t.wakes_reach(1));
  EXPECT_EQ(t.wakes(), 1);
  fs::remove(new_dir + "m.vvp");
  ASSERT_TRUE(t.wakes_reach(2));
  EXPECT_EQ(t.wakes(), 2);
  EXPECT_TRUE(events.take());
  fs::remove_all(old_dir);
  fs::remove_all(new_dir);
}
