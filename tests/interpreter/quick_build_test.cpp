// Quick builds (vvinterpreter/compile/quick_build.hpp): after an edit, the
// program compiled unoptimised by clang and linked with the optimised
// build's declarations' part. They must compute what the optimised build
// computes, name .vvp lines in crash reports, and be replaced by the
// optimised build in the viewer at the step the model is at.
//
// A quick build whose compile fails gives way to g++, whose messages the
// user is shown: ModelCacheDeclarations.AnEditBelowThePropertyBlocks...
// checks g++'s words for an error in an edit made with --expect-edits.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cache_harness.hpp"
#include "model_compiler.hpp"
#include "control/model_controller.hpp"
#include "controller_harness.hpp"
#include "in_process_options.hpp"
#include "run_interpreter.hpp"
#include "test_files.hpp"

namespace fs = std::filesystem;

namespace {

const std::string growing_ring = VV_SOURCE_DIR "/examples/growing_ring.vvp";

//! A copy of `source` as dir/examples/m.vvp, with the files of models/
//! that examples read (growing_ring's profile).
std::string copied(const std::string& dir, const std::string& source) {
  fs::create_directories(dir + "examples");
  fs::copy(VV_SOURCE_DIR "/models", dir + "models", fs::copy_options::recursive);
  std::string model = dir + "examples/m.vvp";
  write(model, test_files::slurp(source));
  return model;
}

//! An edit that changes no computation, as a save while modelling does.
void edit(const std::string& model, const std::string& comment) {
  write(model, test_files::slurp(model) + "\n// " + comment + "\n");
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

const std::string quick_note = "(a quick build: unoptimised)";

//! Makes a file of a test's cache its own, where cache_with_header linked
//! in the suite's (in use by other tests), before the test damages it.
void make_own(const std::string& path) {
  fs::copy_file(path, path + ".own");
  fs::rename(path + ".own", path);
}

//! Damage a cached file as a disk might: its first bytes zeroed, its size as listed.
void zero_the_start(const std::string& path) {
  std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
  f.write(std::string(4096, '\0').data(), 4096);
}

}  // namespace

// growing_ring has parallel loops (two threads here, even on its few
// vertices) and grows by floating-point rules: the quick build's export is
// byte for byte the optimised build's.
TEST(QuickBuild, AnEditRunsAsAQuickBuildThatExportsTheOptimisedBuildsBytes) {
  const std::string dir = fresh_dir("quick_same_bytes");
  const std::string cache = cache_with_header(dir);
  const std::string model = copied(dir, growing_ring);
  auto batch = [&](const std::vector<std::string>& extra, const std::string& out) {
    std::vector<std::string> argv = {"env", "-C", dir, "VV_PARALLEL_GRAIN=1", VV_INTERPRETER, "--cache", cache,
                                     "--batch", "--threads", "2", "--steps", "20", "--export", dir + out};
    argv.insert(argv.end(), extra.begin(), extra.end());
    argv.push_back(model);
    return test_run::run(argv, 280);
  };
  test_run::result first = batch({"--expect-edits"}, "first.vvm");
  ASSERT_EQ(first.status, 0) << report(first);
  EXPECT_FALSE(contains(first.out, quick_note)) << report(first);  // nothing to link yet

  edit(model, "a saved edit");
  test_run::result quick = batch({"--expect-edits"}, "quick.vvm");
  ASSERT_EQ(quick.status, 0) << report(quick);
  EXPECT_TRUE(contains(quick.out, quick_note)) << report(quick);
  test_run::result again = batch({"--expect-edits"}, "again.vvm");  // found in the cache
  EXPECT_TRUE(contains(again.out, "compiled model found in the cache")) << report(again);

  // Without --expect-edits the edit is compiled optimised, by g++.
  test_run::result optimised = batch({}, "optimised.vvm");
  ASSERT_EQ(optimised.status, 0) << report(optimised);
  EXPECT_FALSE(contains(optimised.out, quick_note)) << report(optimised);
  EXPECT_TRUE(contains(optimised.out, "compiled in")) << report(optimised);

  const std::string expected = test_files::slurp(dir + "optimised.vvm");
  ASSERT_FALSE(expected.empty());
  EXPECT_EQ(test_files::slurp(dir + "quick.vvm"), expected);
  EXPECT_EQ(test_files::slurp(dir + "again.vvm"), expected);
  EXPECT_EQ(test_files::slurp(dir + "first.vvm"), expected);  // the edit was a comment
  // And once the optimised build is cached, --expect-edits runs it.
  test_run::result cached = batch({"--expect-edits"}, "cached.vvm");
  EXPECT_TRUE(contains(cached.out, "compiled model found in the cache")) << report(cached);
  EXPECT_EQ(test_files::slurp(dir + "cached.vvm"), expected);
}

// Line tables in the quick build too: a crash names the .vvp line.
TEST(QuickBuild, ACrashInAQuickBuildNamesItsLine) {
  const std::string dir = fresh_dir("quick_crash");
  const std::string cache = cache_with_header(dir);
  const std::string model = copied(dir, VV_TESTS_DIR "/fault_models/crash_in_step2.vvp");
  // From outside the model's folder: the report names the file by its whole path.
  test_run::result first = run_in("/", cache, {"--batch", "--expect-edits", "--steps", "1", model});
  ASSERT_EQ(first.status, 0) << report(first);

  edit(model, "an edit below the line that crashes");
  test_run::result crashed = run_in("/", cache, {"--batch", "--expect-edits", "--steps", "3", model});
  EXPECT_EQ(crashed.status, 1) << report(crashed);
  EXPECT_TRUE(contains(crashed.out, quick_note)) << report(crashed);
  std::vector<std::string> err = lines_of(crashed.err);
  ASSERT_GE(err.size(), 2u) << report(crashed);
  EXPECT_EQ(err[0], "vvinterpreter: " + model + ":23: crashed with SIGSEGV in step 2") << report(crashed);
  EXPECT_EQ(err[1], "  " + model + ":23 in the step block") << report(crashed);
}

// The viewer's loop, through the controller: the edit is reloaded as a
// quick build at once; the optimised build then takes its place, replayed
// to the same step, and exports the same bytes.
TEST(QuickBuild, TheOptimisedBuildTakesTheQuickBuildsPlaceAtTheSameStep) {
  using namespace controller_harness;
  const std::string dir = fresh_dir("quick_swap");
  const std::string model = copied(dir, growing_ring);
  vvi::options o = in_process_options(model);
  o.cache = cache_with_header(dir);
  o.batch = false;  // the viewer's builds: the declarations' part from the first one
  o.quiet = true;
  recording_view view;
  recording_jobs jobs{view};
  vvi::model_controller c(o, jobs, view);
  auto settle = [&] {
    for (int i = 0; i < 6000 && !c.idle(); ++i) {
      c.poll(0);
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  };
  auto exported = [&](const std::string& name) {
    command e = command::with_path(command::export_mesh, dir + name);
    c.submit(e);
    settle();
    return test_files::slurp(dir + name);
  };
  c.submit(command::of(command::reload));  // the first build
  settle();
  ASSERT_TRUE(c.runner().model()) << (view.errors.empty() ? "" : view.errors.back());
  c.submit(command::steps(7));
  settle();
  const std::string before = exported("before.vvm");
  ASSERT_FALSE(before.empty());

  edit(model, "a saved edit");
  view.said.clear();
  c.submit(command::of(command::reload));
  settle();
  ASSERT_EQ(view.said.size(), 2u) << ::testing::PrintToString(view.said);
  EXPECT_EQ(view.said[0], "reloaded " + model + " (unoptimised until its optimised build is ready)");
  EXPECT_EQ(view.said[1], "swapped in the optimised build of " + model);
  EXPECT_TRUE(view.errors.empty()) << view.errors.back();
  EXPECT_FALSE(c.optimising());
  EXPECT_EQ(c.facts().steps, 7u);
  EXPECT_EQ(c.status(), "running");
  // The plugin now running is g++'s build, not the quick one. (A host
  // built with clang gives both builds a precompiled header.)
  std::string command_file = fs::path(c.runner().plugin_path()).parent_path().string() + "/command";
  if (!model_compiler::clang) {
    EXPECT_FALSE(contains(test_files::slurp(command_file), "-include-pch")) << test_files::slurp(command_file);
  }
  EXPECT_EQ(exported("after.vvm"), before);
}

// The quick builds' precompiled header is checked as g++'s is: a wrong size
// is found before use (a note, built again); damage its size does not show
// makes clang fail, and g++ then builds the edit while the header is made
// again for the next one.
TEST(QuickBuild, ADamagedQuickHeaderIsBuiltAgain) {
  const std::string dir = fresh_dir("quick_damaged_header");
  const std::string cache = cache_with_header(dir);
  const std::string model = dir + "m.vvp";
  write(model, "#include <cstdio>\nvertex { double h; };\nmesh S;\n"
               "start { vertex v; v$h = 1.5; add v to S; std::printf(\"h=%g in %zu\\n\", v$h, S.size()); }\n");
  test_run::result first = run_in(dir, cache, {"--batch", "--expect-edits", model});
  ASSERT_EQ(first.status, 0) << report(first);
  // The quick builds' header; with a host built with clang, the optimised
  // builds' too (also a .pch), which --expect-edits leaves unused in batch.
  // cache_with_header links the suite's headers in: each is made a file of
  // this cache's own before it is damaged, as the suite's are in use.
  auto quick_headers = [&] {
    std::vector<std::string> found;
    for (const auto& e : fs::recursive_directory_iterator(cache + "/pch"))
      if (e.is_regular_file() && e.path().filename() == "model.hpp.pch") found.push_back(e.path().string());
    for (const std::string& header : found) make_own(header);
    return found;
  };
  std::vector<std::string> headers = quick_headers();
  ASSERT_FALSE(headers.empty());
  std::set<std::string> notes;
  for (const std::string& header : headers) {
    notes.insert(model + ": note: the cached precompiled vvlib header of quick builds was damaged "
                         "(model/model.hpp.pch has 1000000 bytes, " +
                 std::to_string(fs::file_size(header)) + " expected); it was built again\n");
    fs::resize_file(header, 1000000);
  }

  edit(model, "first edit");
  test_run::result truncated = run_in(dir, cache, {"--batch", "--expect-edits", model});
  EXPECT_EQ(truncated.status, 0) << report(truncated);
  EXPECT_TRUE(contains(truncated.out, quick_note)) << report(truncated);
  EXPECT_TRUE(contains(truncated.out, "h=1.5 in 1\n")) << report(truncated);
  EXPECT_EQ(notes.count(truncated.err), 1u) << report(truncated);

  // Its first bytes overwritten, its size as listed (a header built again
  // may differ in size by a few bytes: clang records where it was made).
  headers = quick_headers();
  ASSERT_FALSE(headers.empty());
  for (const std::string& header : headers) zero_the_start(header);
  edit(model, "second edit");
  test_run::result unreadable = run_in(dir, cache, {"--batch", "--expect-edits", model});
  EXPECT_EQ(unreadable.status, 0) << report(unreadable);
  EXPECT_FALSE(contains(unreadable.out, quick_note)) << report(unreadable);  // g++'s build
  EXPECT_TRUE(contains(unreadable.out, "h=1.5 in 1\n")) << report(unreadable);

  edit(model, "third edit");
  test_run::result again = run_in(dir, cache, {"--batch", "--expect-edits", model});
  EXPECT_EQ(again.status, 0) << report(again);
  EXPECT_TRUE(contains(again.out, quick_note)) << report(again);
  EXPECT_TRUE(contains(again.out, "h=1.5 in 1\n")) << report(again);
}

// The code of the quick builds' headers (their inline functions and
// templates, compiled once: compile/precompiled_header.hpp and
// compile/declarations_header.hpp) is checked by its content before each
// use: damaged, it is built again with a note, and the edit still runs
// quick.
TEST(QuickBuild, ADamagedQuickHeaderCodeIsBuiltAgain) {
  const std::string dir = fresh_dir("quick_damaged_header_code");
  const std::string cache = cache_with_header(dir);
  const std::string model = dir + "m.vvp";
  write(model, "#include <cstdio>\nvertex { double h; };\nmesh S;\n"
               "start { vertex v; v$h = 2.5; add v to S; std::printf(\"h=%g in %zu\\n\", v$h, S.size()); }\n");
  test_run::result first = run_in(dir, cache, {"--batch", "--expect-edits", model});
  ASSERT_EQ(first.status, 0) << report(first);
  // Each made a file of this cache's own (the suite's are linked in), then
  // its first bytes overwritten: its size is as listed.
  int damaged = 0;
  for (const auto& e : fs::recursive_directory_iterator(cache + "/pch")) {
    if (!e.is_regular_file() || e.path().filename() != "model.hpp.o") continue;
    std::string code = e.path().string();
    make_own(code);
    zero_the_start(code);
    ++damaged;
  }
  ASSERT_GT(damaged, 0);

  // An edit after the damage: still a quick build, with the right result,
  // and the one note naming what was found damaged.
  auto edit_notes = [&](const std::string& comment, const std::string& damage) {
    edit(model, comment);
    test_run::result r = run_in(dir, cache, {"--batch", "--expect-edits", model});
    EXPECT_EQ(r.status, 0) << report(r);
    EXPECT_TRUE(contains(r.out, quick_note)) << report(r);
    EXPECT_TRUE(contains(r.out, "h=2.5 in 1\n")) << report(r);
    EXPECT_EQ(r.err, model + ": note: the cached " + damage + "; it was built again\n") << report(r);
  };
  edit_notes("an edit", "precompiled vvlib header of quick builds was damaged "
                        "(model/model.hpp.o differs from what was built)");

  // The code of the header of the model's declarations
  // (compile/declarations_header.hpp), made on the new vvlib header by
  // that edit: damaged, it too is built again with a note.
  std::vector<std::string> declarations_code;
  for (const auto& e : fs::recursive_directory_iterator(cache + "/decl-headers"))
    if (e.is_regular_file() && e.path().filename() == "header.hpp.o") declarations_code.push_back(e.path().string());
  ASSERT_FALSE(declarations_code.empty());
  for (const std::string& code : declarations_code) zero_the_start(code);
  edit_notes("another edit", "header of the declarations was damaged (header.hpp.o differs from what was built)");
}
