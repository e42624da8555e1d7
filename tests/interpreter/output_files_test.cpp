// The files batch writes for the user (--export, --screenshot, --plots;
// runner/output_file.hpp over vv/io/output_file.hpp): each run writes a temporary of its own, so two
// runs never lose each other's work; a symbolic link, a device or a FIFO
// is written through and stays what it was; a name that fits is written
// whatever its length; and a run that is killed leaves nothing behind, with
// a message that says what killed it.
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include "spawned_run.hpp"
#include "viewer_harness.hpp"

namespace {

using namespace viewer_harness;

const std::string loop = VV_SOURCE_DIR "/examples/loop.vvp";
constexpr int run_limit = 120;

test_run::result batch(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {"--batch", "--quiet"};
  argv.insert(argv.end(), args.begin(), args.end());
  return test_run::run(test_run::interpreter(argv), run_limit);
}

//! Loop subdivision's double pyramid after `steps`, exported to `path`.
test_run::result export_loop(const std::string& path, int steps = 0) {
  return batch({"--steps", std::to_string(steps), "--export", path, loop});
}

std::vector<std::string> names_in(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

bool is_symlink(const std::string& path) { return fs::is_symlink(fs::symlink_status(path)); }

// The inode of the PID namespace, as the interpreter names it in its
// temporaries (hex).
std::string pid_namespace() {
  std::string link = fs::read_symlink("/proc/self/ns/pid").string();  // "pid:[4026531836]"
  std::ostringstream hex;
  hex << std::hex << std::stoull(link.substr(link.find('[') + 1));
  return hex.str();
}

// Issue 23, item 14: every run wrote "out.obj.vvtmp.obj" and removed it
// first, so two runs to one path deleted each other's temporary (run A said
// "wrote out.obj" while the file held run B's mesh). A run now leaves a file
// by that name — another run's, for all it knows — alone.
TEST(OutputFiles, AnotherRunsTemporaryBesideTheTargetIsLeftAlone) {
  std::string d = fresh_dir("others_temporary");
  write_text(d + "out.obj.vvtmp.obj", "another run's bytes");
  test_run::result r = export_loop(d + "out.obj");
  ASSERT_EQ(r.status, 0) << report(r);
  EXPECT_EQ(slurp(d + "out.obj.vvtmp.obj"), "another run's bytes");
  EXPECT_EQ(names_in(d), (std::vector<std::string>{"out.obj", "out.obj.vvtmp.obj"}));
  ASSERT_EQ(export_loop(d + "reference.obj").status, 0);
  EXPECT_EQ(slurp(d + "out.obj"), slurp(d + "reference.obj"));
}

// Issue 23, item 14: as root, an export aimed at a FIFO replaced it with a
// regular file and said it had written it. The FIFO stays, and the reader
// gets the file.
TEST(OutputFiles, AFifoIsWrittenThroughAndStays) {
  std::string d = fresh_dir("fifo_export");
  ASSERT_EQ(mkfifo((d + "pipe.obj").c_str(), 0600), 0);
  int reader = open((d + "pipe.obj").c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  test_run::result r = export_loop(d + "pipe.obj");  // a few hundred bytes: the pipe holds them
  std::string got;
  char buf[4096];
  for (ssize_t n; (n = read(reader, buf, sizeof buf)) > 0;) got.append(buf, static_cast<std::size_t>(n));
  close(reader);
  ASSERT_EQ(r.status, 0) << report(r);
  EXPECT_TRUE(fs::is_fifo(d + "pipe.obj")) << "the FIFO was replaced";
  ASSERT_EQ(export_loop(d + "reference.obj").status, 0);
  EXPECT_EQ(got, slurp(d + "reference.obj"));
  EXPECT_EQ(names_in(d), (std::vector<std::string>{"pipe.obj", "reference.obj"}));
}

// Issue 23, item 14: `-o /dev/full` replaced the device and reported
// success. A device is written through: a full one is an error saying so,
// and both devices (made here, in a scratch folder) stay devices.
TEST(OutputFiles, ADeviceIsWrittenThroughAndStays) {
  std::string d = fresh_dir("device_export");
  if (mknod((d + "full.obj").c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0 ||
      mknod((d + "null.obj").c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0)
    GTEST_SKIP() << "cannot make device nodes here (not root, or no CAP_MKNOD)";
  test_run::result full = export_loop(d + "full.obj");
  EXPECT_EQ(full.status, 1) << report(full);
  EXPECT_EQ(full.err, "vvinterpreter: " + d + "full.obj: cannot write file: No space left on device\n") << report(full);
  test_run::result null = export_loop(d + "null.obj");
  EXPECT_EQ(null.status, 0) << report(null);
  EXPECT_TRUE(fs::is_character_file(d + "full.obj"));
  EXPECT_TRUE(fs::is_character_file(d + "null.obj"));
  EXPECT_EQ(names_in(d), (std::vector<std::string>{"full.obj", "null.obj"}));
}

// Issue 23, item 14: an export to a dangling symbolic link replaced the
// link. The link stays and its target is written (made), for --export,
// --screenshot and --plots alike; a loop of links is refused.
TEST(OutputFiles, SymbolicLinksAreWrittenThroughAndLoopsRefused) {
  std::string d = fresh_dir("link_export");
  fs::create_directory(d + "real");
  fs::create_symlink("real/mesh.obj", d + "mesh.obj");
  fs::create_symlink(d + "real/shot.png", d + "shot.png");
  fs::create_symlink("real/plots.csv", d + "plots.csv");
  test_run::result r = batch({"--export", d + "mesh.obj", "--screenshot", d + "shot.png", "--size", "64x48",
                              "--plots", d + "plots.csv", loop});
  ASSERT_EQ(r.status, 0) << report(r);
  for (const char* name : {"mesh.obj", "shot.png", "plots.csv"}) {
    EXPECT_TRUE(is_symlink(d + name)) << name << " was replaced";
    EXPECT_TRUE(fs::is_regular_file(d + "real/" + name)) << name << "'s target was not written";
  }
  ASSERT_EQ(export_loop(d + "reference.obj").status, 0);
  EXPECT_EQ(slurp(d + "real/mesh.obj"), slurp(d + "reference.obj"));
  EXPECT_EQ(slurp(d + "real/plots.csv"), "step\n");

  fs::create_symlink("b.obj", d + "a.obj");
  fs::create_symlink("a.obj", d + "b.obj");
  test_run::result looped = export_loop(d + "a.obj");
  EXPECT_EQ(looped.status, 1) << report(looped);
  EXPECT_EQ(looped.err,
            "vvinterpreter: " + d + "a.obj: cannot write file: the symbolic link is part of a loop of links\n")
      << report(looped);
  EXPECT_TRUE(is_symlink(d + "a.obj") && is_symlink(d + "b.obj"));
}

// Issue 23, item 17: a 250-byte export name failed ("File name too long")
// only because of the temporary's suffix. Any name that fits is written;
// a longer one is refused by the system, as before.
TEST(OutputFiles, ANameThatFitsIsWrittenWhateverItsLength) {
  std::string d = fresh_dir("long_name");
  // 246 bytes + ".obj": 250; the longest a folder takes: 255.
  std::string accented;
  for (int i = 0; i < 100; ++i) accented += "\xC3\xA9";  // é, two bytes
  for (const std::string& name :
       {std::string(246, 'n') + ".obj", accented + std::string(46, 'x') + ".obj", std::string(251, 'v') + ".vvm"}) {
    SCOPED_TRACE(name.size());
    test_run::result r = export_loop(d + name);
    EXPECT_EQ(r.status, 0) << report(r);
    EXPECT_TRUE(fs::is_regular_file(d + name));
  }
  EXPECT_EQ(names_in(d).size(), 3u);
}

// Issue 23, item 15: a run killed during an export left its temporary until
// the next run to that same path. A temporary whose process is gone (its
// name says which) goes with the next file written in the folder; those of
// live processes, and of processes of another PID namespace, stay.
TEST(OutputFiles, TemporariesOfRunsThatDiedAreRemovedByTheNextOne) {
  std::string d = fresh_dir("stale_temporaries");
  pid_t gone = fork();
  if (gone == 0) _exit(0);
  waitpid(gone, nullptr, 0);
  std::string ns = pid_namespace();
  std::string dead = ".old.vvtmp-" + std::to_string(gone) + "-" + ns + "-0a1b2c.obj";
  std::string dead_inner = dead + ".vvtmp.obj";
  std::string alive = ".old.vvtmp-" + std::to_string(getpid()) + "-" + ns + "-0a1b2c.obj";
  std::string elsewhere = ".old.vvtmp-" + std::to_string(gone) + "-1-0a1b2c.obj";
  for (const std::string& name : {dead, dead_inner, alive, elsewhere}) write_text(d + name, "left over");
  test_run::result r = export_loop(d + "new.obj");
  ASSERT_EQ(r.status, 0) << report(r);
  std::vector<std::string> expected = {alive, elsewhere, "new.obj"};
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(names_in(d), expected);
}

// Issue 23, item 15: kill -9 during an export left its temporary, and the
// message guessed "(out of memory?)". The model is killed here while it
// writes into a FIFO nobody reads (so it is surely still writing): its
// temporary goes, and the message says what the system knows.
TEST(OutputFiles, AKilledExportLeavesNoTemporaryAndSaysWhatKilledIt) {
  std::string d = fresh_dir("killed_export");
  ASSERT_EQ(mkfifo((d + "pipe.obj").c_str(), 0600), 0);
  int reader = open((d + "pipe.obj").c_str(), O_RDONLY | O_NONBLOCK);  // open, never read: a full pipe
  ASSERT_GE(reader, 0);
  std::vector<std::string> argv = {"env", "TMPDIR=" + d};  // the temporary of a FIFO's export goes there
  for (const std::string& a : test_run::interpreter({"--batch", "--quiet", "--steps", "4", "--export", d + "pipe.obj", loop}))
    argv.push_back(a);
  test_run::spawned run(argv, run_limit);
  ASSERT_TRUE(run.started());
  // The temporary names the process writing it: the model's.
  pid_t writer = 0;
  auto until = std::chrono::steady_clock::now() + std::chrono::seconds(run_limit);
  while (writer == 0 && run.running() && std::chrono::steady_clock::now() < until) {
    for (const std::string& name : names_in(d))
      if (name.rfind(".pipe.vvtmp-", 0) == 0) writer = static_cast<pid_t>(std::stol(name.substr(12)));
    usleep(10000);
  }
  ASSERT_GT(writer, 0) << "the export was never seen being written";
  usleep(200000);  // well into the write to the full pipe
  kill(writer, SIGKILL);
  test_run::result r = run.finish();
  close(reader);
  EXPECT_EQ(r.status, 1) << report(r);
  const std::string killed = "vvinterpreter: " + loop + ": killed by SIGKILL while writing " + d + "pipe.obj";
  if (has(slurp("/proc/vmstat"), "\noom_kill ")) {
    EXPECT_EQ(r.err, killed + " (not by the kernel's out-of-memory killer)\n") << report(r);
  } else {
    EXPECT_EQ(r.err.rfind(killed + " (", 0), 0u) << report(r);
  }
  EXPECT_EQ(names_in(d), (std::vector<std::string>{"pipe.obj"})) << "a temporary was left";
}

}  // namespace
