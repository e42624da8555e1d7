// The quick builds' header of a model's declarations
// (vvinterpreter/compile/declarations_header.hpp): made while the first
// build compiles (--expect-edits), then every edit compiles only the
// program on it. The header holds the declarations' code once: the program
// must still have one of each of its variables (a parameter set from the
// command line is the one the code reads), give the declarations' warnings
// and follow a change to a header of the model's own. A damaged entry:
// QuickBuild.ADamagedQuickHeaderCodeIsBuiltAgain.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cache_harness.hpp"
#include "run_interpreter.hpp"
#include "test_files.hpp"

namespace fs = std::filesystem;

namespace {

const std::string quick_build_note = "(a quick build: unoptimised)";

void append_comment(const std::string& model, const std::string& comment) {
  write(model, test_files::slurp(model) + "\n// " + comment + "\n");
}

//! The files named `name` in the cache's entries of declarations' headers.
std::vector<std::string> header_files(const std::string& cache, const std::string& name) {
  std::vector<std::string> found;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(cache + "/decl-headers", ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
    if (it->is_regular_file() && it->path().filename() == name) found.push_back(it->path().string());
  return found;
}

//! The command the newest build in the cache was made with.
std::string newest_command(const std::string& cache) {
  fs::file_time_type newest{};
  std::string command;
  for (const auto& e : fs::directory_iterator(cache + "/plugins")) {
    fs::path file = e.path() / "command";
    std::error_code ec;
    if (!e.is_directory() || !fs::exists(file, ec)) continue;
    if (command.empty() || fs::last_write_time(file) > newest) {
      newest = fs::last_write_time(file);
      command = test_files::slurp(file.string());
    }
  }
  return command;
}

// The declarations: a header of the model's folder, a parameter, and an
// inline function with an unused variable (a warning at line 4).
const std::string declarations_model =
    "#include <cstdio>\n"
    "#include \"base.h\"\n"
    "param double rate = 0.5;\n"
    "inline double twice(double x) { int never_used = 0; return 2 * x; }\n"
    "vertex { double h; };\n"
    "mesh S;\n"
    "start { vertex v; v$h = twice(rate) + base(); add v to S; std::printf(\"h=%g\\n\", v$h); }\n";

}  // namespace

TEST(QuickDeclarationsHeader, AnEditCompilesTheProgramAloneAndRunsAsTheWholeDoes) {
  const std::string dir = fresh_dir("quick_declarations_header");
  const std::string cache = cache_with_header(dir);
  const std::string model = dir + "m.vvp";
  write(dir + "base.h", "inline double base() { return 10; }\n");
  write(model, declarations_model);
  auto run = [&] { return run_in(dir, cache, {"--batch", "--expect-edits", "--set", "rate=1.5", model}); };

  test_run::result first = run();
  ASSERT_EQ(first.status, 0) << report(first);
  EXPECT_TRUE(contains(first.out, "h=13\n")) << report(first);
  // Made while the first build compiled, for the edits to come.
  EXPECT_EQ(header_files(cache, "header.hpp.pch").size(), 1u);

  append_comment(model, "an edit");
  test_run::result edited = run();
  ASSERT_EQ(edited.status, 0) << report(edited);
  EXPECT_TRUE(contains(edited.out, quick_build_note)) << report(edited);
  // The value set is the one the code reads: one `rate`, not one per object.
  EXPECT_TRUE(contains(edited.out, "h=13\n")) << report(edited);
  std::string command = newest_command(cache);
  EXPECT_TRUE(contains(command, "/decl-headers/")) << command;
  EXPECT_TRUE(contains(command, "/program.cpp ")) << command;
  // The declarations' warning, at its .vvp line, as in the first build.
  EXPECT_TRUE(contains(first.err, "m.vvp:4:")) << report(first);
  EXPECT_TRUE(contains(edited.err, "m.vvp:4:")) << report(edited);
  EXPECT_TRUE(contains(edited.err, "never_used")) << report(edited);

  // A change to the model's own header: the next builds read the new one.
  write(dir + "base.h", "inline double base() { return 20; }\n");
  test_run::result changed = run();
  ASSERT_EQ(changed.status, 0) << report(changed);
  EXPECT_TRUE(contains(changed.out, "h=23\n")) << report(changed);
  append_comment(model, "another edit");
  test_run::result after = run();
  ASSERT_EQ(after.status, 0) << report(after);
  EXPECT_TRUE(contains(after.out, quick_build_note)) << report(after);
  EXPECT_TRUE(contains(after.out, "h=23\n")) << report(after);
}
