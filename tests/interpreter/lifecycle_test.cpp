// A model's life in batch mode, as the modelling loop needs it to be
// trustworthy: what runs is what the files say (a header edit rebuilds),
// a crash or an endless step ends the run with the .vvp line and the step
// (and keeps everything the model printed), an exception in a global
// initialiser is reported, --end runs the end block, --mesh A,B exports
// the union, --debug builds for gdb, and the compiler's messages carry .vvp
// columns. Models live in fault_models/.
#include "model_compiler.hpp"
#include "viewer_harness.hpp"

namespace {

const std::string fault_models = VV_TESTS_DIR "/fault_models/";

test_run::result batch(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {"--batch"};
  argv.insert(argv.end(), args.begin(), args.end());
  return test_run::run(test_run::interpreter(argv), 280);
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// Regression (issue 8, defect 1): the cache entry was named by the
// translated C++, which a header edit leaves unchanged, so the fresh build
// lost the rename to the old one and the old code ran.
TEST(Lifecycle, AHeaderEditRebuildsAndRunsTheNewCode) {
  std::string d = fresh_dir("header_edit");
  fs::copy_file(fault_models + "with_header.vvp", d + "model.vvp");
  write_text(d + "rate.h", "const int rate = 1;\n");
  test_run::result first = batch({"--quiet", d + "model.vvp"});
  ASSERT_EQ(first.status, 0) << report(first);
  EXPECT_EQ(first.out, "rate 1\n");
  write_text(d + "rate.h", "const int rate = 22;  // edited\n");
  test_run::result second = batch({d + "model.vvp"});
  ASSERT_EQ(second.status, 0) << report(second);
  EXPECT_TRUE(has(second.out, "compiled in")) << "the edited header was not compiled\n" << report(second);
  EXPECT_TRUE(has(second.out, "rate 22\n")) << report(second);
  // Unchanged since: the cache answers, with the new build.
  test_run::result third = batch({d + "model.vvp"});
  EXPECT_TRUE(has(third.out, "found in the cache")) << report(third);
  EXPECT_TRUE(has(third.out, "rate 22\n")) << report(third);
}

// Regression (defect 5): a null pointer in the model's own code killed the
// interpreter with "Segmentation fault", and output still in stdio's buffer
// (stdout is a pipe here) was lost.
TEST(Lifecycle, ACrashNamesTheLineAndTheStepAndKeepsTheOutput) {
  test_run::result r = batch({"--quiet", "--steps", "3", fault_models + "crash_in_step2.vvp"});
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_NE(r.status, 0) << report(r);
  std::vector<std::string> err = lines_of(r.err);
  ASSERT_FALSE(err.empty()) << report(r);
  EXPECT_EQ(err[0], "vvinterpreter: " + fault_models + "crash_in_step2.vvp:23: crashed with SIGSEGV in step 2")
      << report(r);
  // The call stack as .vvp lines follows.
  ASSERT_GE(err.size(), 2u) << report(r);
  EXPECT_EQ(err[1], "  " + fault_models + "crash_in_step2.vvp:23 in the step block") << report(r);
  EXPECT_EQ(r.out, "step 1\npartial line of step 1\nstep 2\npartial line of step 2") << report(r);
}

// binutils 2.40's addr2line read the DWARF 5 line tables g++ 12 writes
// by default as naming the translated .cpp for the first function in the
// model's .text: a crash there fell back to the bare model name. Models
// are compiled with DWARF 4 line tables, which it reads right.
TEST(Lifecycle, ACrashInTheModelsFirstFunctionNamesItsLine) {
  const std::string model = fault_models + "crash_in_first_function.vvp";
  test_run::result r = batch({"--quiet", "--steps", "1", model});
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_EQ(r.status, 1) << report(r);
  std::vector<std::string> err = lines_of(r.err);
  ASSERT_EQ(err.size(), 3u) << report(r);
  EXPECT_EQ(err[0], "vvinterpreter: " + model + ":11: crashed with SIGSEGV in step 1") << report(r);
  EXPECT_EQ(err[1], "  " + model + ":11 in write_nowhere(int)") << report(r);
  EXPECT_EQ(err[2], "  " + model + ":15 in the step block") << report(r);
}

// The interpreter loads a private copy of the plugin from $TMPDIR. It was
// named "vv-model-PID-N.so": two containers with their own PID namespaces
// and one /tmp wrote over each other's copy. Its name now holds the PID
// namespace and random letters (made with O_EXCL), and it is removed once
// loaded; copies of dead processes of this namespace go with the next load,
// those of other namespaces stay.
TEST(Lifecycle, ThePluginsPrivateCopyIsUniqueAndRemovedOnceLoaded) {
  std::string d = fresh_dir("plugin_copy");
  std::string link = fs::read_symlink("/proc/self/ns/pid").string();  // "pid:[4026531836]"
  std::ostringstream ns;
  ns << std::hex << std::stoull(link.substr(link.find('[') + 1));
  pid_t gone = fork();
  if (gone == 0) _exit(0);
  waitpid(gone, nullptr, 0);
  std::string dead = ".vv-model-1.vvtmp-" + std::to_string(gone) + "-" + ns.str() + "-AbCdEf.so";
  std::string elsewhere = ".vv-model-1.vvtmp-" + std::to_string(gone) + "-1-AbCdEf.so";
  write_text(d + dead, "a dead run's copy");
  write_text(d + elsewhere, "another container's copy");
  std::vector<std::string> argv = {"env", "TMPDIR=" + d.substr(0, d.size() - 1)};
  for (const std::string& a :
       test_run::interpreter({"--batch", "--quiet", "--steps", "0", fault_models + "prints_where_it_is_loaded_from.vvp"}))
    argv.push_back(a);
  test_run::result r = test_run::run(argv, 280);
  ASSERT_EQ(r.status, 0) << report(r);
  const std::string prefix = "loaded from " + d + ".vv-model-1.vvtmp-";
  ASSERT_EQ(r.out.rfind(prefix, 0), 0u) << report(r);
  std::string id = r.out.substr(prefix.size());  // "PID-NS-XXXXXX.so (removed)\n"
  EXPECT_TRUE(has(id, "-" + ns.str() + "-")) << r.out;
  EXPECT_EQ(id.substr(id.find('-', id.find('-') + 1) + 7), ".so (removed)\n") << r.out;
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(d)) left.push_back(e.path().filename().string());
  EXPECT_EQ(left, std::vector<std::string>{elsewhere});
}

// Regression (defect 4): an endless step froze everything; now
// --step-timeout ends it with a message naming the step and the line it
// was at, with the model's stack as a crash report gives it.
TEST(Lifecycle, AStepPastTheTimeLimitEndsTheRun) {
  test_run::result r =
      batch({"--quiet", "--steps", "3", "--step-timeout", "1.5", fault_models + "endless_step2.vvp"});
  ASSERT_FALSE(r.timed_out) << "the endless step was not ended\n" << report(r);
  EXPECT_NE(r.status, 0) << report(r);
  const std::string model = fault_models + "endless_step2.vvp";
  EXPECT_EQ(r.err, "vvinterpreter: " + model + ":22: step 2 ran longer than 1.5 s and was ended\n  " + model +
                       ":22 in the step block\n")
      << report(r);
}

TEST(Lifecycle, StepTimeoutNeedsAPositiveNumber) {
  for (const char* bad : {"0", "-1", "soon", ""}) {
    test_run::result r = batch({"--step-timeout", bad, fault_models + "counter.vvp"});
    EXPECT_EQ(r.status, 2) << bad << "\n" << report(r);
    EXPECT_TRUE(has(r.err, "--step-timeout needs a number of seconds")) << report(r);
  }
}

// Regression (defect 6): an exception thrown while the model's globals are
// initialised (inside dlopen) aborted the interpreter.
TEST(Lifecycle, AnExceptionInAGlobalInitialiserIsReported) {
  test_run::result r = batch({"--quiet", "--steps", "1", fault_models + "global_throws.vvp"});
  ASSERT_FALSE(r.timed_out) << report(r);
  EXPECT_NE(r.status, 0) << report(r);
  std::vector<std::string> err = lines_of(r.err);
  ASSERT_GE(err.size(), 3u) << report(r);
  EXPECT_EQ(err[0], "vvinterpreter: " + fault_models +
                        "global_throws.vvp:7: crashed with an uncaught exception (cannot parse rates.txt) while "
                        "loading the model (in a global initialiser)")
      << report(r);
  EXPECT_EQ(err[1], "  " + fault_models + "global_throws.vvp:7 in rate_from_file()") << report(r);
  EXPECT_EQ(err[2], "  " + fault_models + "global_throws.vvp:9 in a global initialiser") << report(r);
}

// Regression (defect 8): batch mode never ran the end block.
TEST(Lifecycle, EndRunsTheEndBlockAfterTheLastStep) {
  test_run::result without = batch({"--quiet", "--steps", "4", fault_models + "end_block.vvp"});
  EXPECT_EQ(without.status, 0) << report(without);
  EXPECT_EQ(without.out, "");
  test_run::result with = batch({"--quiet", "--steps", "4", "--end", fault_models + "end_block.vvp"});
  EXPECT_EQ(with.status, 0) << report(with);
  EXPECT_EQ(with.out, "summary: 4 steps\n");
}

// Regression (defect 8): only one global mesh could be exported.
TEST(Lifecycle, SeveralMeshesExportAsTheirUnion) {
  std::string d = fresh_dir("mesh_union");
  std::string two = VV_TESTS_DIR "/models/two_meshes.vvp";
  test_run::result r = batch({"--quiet", "--mesh", "Fan,Pyramid", "--export", d + "both.vvm", two});
  ASSERT_EQ(r.status, 0) << report(r);
  EXPECT_EQ(vvm_vertex_count(d + "both.vvm"), 7 + 6);
  // As polygons: the fan's six triangles (its hexagonal boundary is a hole
  // with --max-face 3) and the pyramid's eight.
  r = batch({"--quiet", "--mesh", "Fan,Pyramid", "--max-face", "3", "--export", d + "both.obj", two});
  ASSERT_EQ(r.status, 0) << report(r);
  std::string obj = slurp(d + "both.obj");
  long v = 0, f = 0;
  for (const std::string& l : lines_of(obj)) v += l.rfind("v ", 0) == 0, f += l.rfind("f ", 0) == 0;
  EXPECT_EQ(v, 13);
  EXPECT_EQ(f, 6 + 8);
  // A name that is not a global mesh is an error naming the ones there are.
  r = batch({"--quiet", "--mesh", "Fan,Walls", "--export", d + "bad.vvm", two});
  EXPECT_NE(r.status, 0);
  EXPECT_EQ(r.err, "vvinterpreter: " + two + ": the model has no global mesh named Walls (it has Fan, Pyramid)\n");
  EXPECT_FALSE(fs::exists(d + "bad.vvm"));
  EXPECT_EQ(batch({"--mesh", "Fan,", two}).status, 2);
}

// Issue 9, item 19: a screenshot of a mesh without positions was a blank
// picture without a word.
TEST(Lifecycle, AScreenshotOfAMeshWithoutPositionsIsAnError) {
  std::string d = fresh_dir("no_pos_shot");
  test_run::result r = batch({"--quiet", "--screenshot", d + "blank.png", fault_models + "end_block.vvp"});
  EXPECT_NE(r.status, 0) << report(r);
  EXPECT_EQ(r.err, "vvinterpreter: " + d + "blank.png: nothing to draw: the vertices of the model's mesh have no "
                   "'pos' property (give them one, or draw them in a render block)\n");
  EXPECT_FALSE(fs::exists(d + "blank.png"));
}

// Issue 9, item 22: SIGTERM during an export left a temporary of tens of
// MB beside the target. Now the run ends, the temporary goes, and the
// previous file (none here) is untouched.
TEST(Lifecycle, SigtermDuringAnExportLeavesNoTemporary) {
  std::string d = fresh_dir("sigterm_export");
  std::string target = d + "big.obj";
  // The run's own temporary beside the target (runner/output_file.hpp).
  auto writing_now = [&] {
    for (const auto& e : fs::directory_iterator(d))
      if (e.path().filename().string().rfind(".big.vvtmp-", 0) == 0) return true;
    return false;
  };
  // Loop to 2,097,152 triangles: the OBJ takes a while to write.
  std::vector<std::string> argv =
      test_run::interpreter({"--batch", "--quiet", "--steps", "9", "--export", target, VV_SOURCE_DIR "/examples/loop.vvp"});
  pid_t pid = fork();
  if (pid == 0) {
    std::vector<char*> a;
    for (const std::string& s : argv) a.push_back(const_cast<char*>(s.c_str()));
    a.push_back(nullptr);
    execv(a[0], a.data());
    _exit(127);
  }
  ASSERT_GT(pid, 0);
  auto until = std::chrono::steady_clock::now() + std::chrono::seconds(240);
  bool writing = false;
  while (!(writing = writing_now()) && std::chrono::steady_clock::now() < until &&
         waitpid(pid, nullptr, WNOHANG) == 0)
    usleep(2000);
  ASSERT_TRUE(writing) << "the export was never seen being written";
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 128 + SIGTERM) << status;
  EXPECT_FALSE(writing_now());
  EXPECT_TRUE(fs::is_empty(d));
}

// Issue 9, item 23: "(in start)" was left out whenever the message held the
// word "start" (here, in the file's name).
TEST(Lifecycle, AnErrorAlwaysNamesItsBlock) {
  test_run::result r = batch({"--quiet", fault_models + "reads_restart.vvp"});
  EXPECT_NE(r.status, 0) << report(r);
  std::vector<std::string> err = lines_of(r.err);
  ASSERT_EQ(err.size(), 1u) << report(r);
  EXPECT_EQ(err[0].rfind("vvinterpreter: " + fault_models + "reads_restart.vvp:9: readXMLFile: ", 0), 0u) << report(r);
  EXPECT_TRUE(has(err[0], "restart.vvm")) << report(r);
  EXPECT_EQ(err[0].substr(err[0].size() - 11), " (in start)") << report(r);
}

// Issue 9, item 17: `v->x` on the null vertex said "$: property access on
// the null vertex" without a line (operator-> takes no source location);
// the interpreter finds the line in the model's line tables.
TEST(Lifecycle, ANullVertexErrorNamesItsLineAlsoThroughTheArrow) {
  const std::string model = fault_models + "null_vertex.vvp";
  test_run::result arrow = batch({"--quiet", "--steps", "0", "--end", model});
  EXPECT_NE(arrow.status, 0) << report(arrow);
  EXPECT_EQ(arrow.err, "vvinterpreter: " + model + ":9: $: property access on the null vertex (in end)\n")
      << report(arrow);
  test_run::result dollar = batch({"--quiet", "--steps", "1", "--in-process", model});
  EXPECT_NE(dollar.status, 0) << report(dollar);
  EXPECT_EQ(dollar.err, "vvinterpreter: " + model + ":17: $: property access on the null vertex (in step 1)\n")
      << report(dollar);
}

// Issue 9, item 19: --check finds the broken neighbourhood after the step
// that broke it and names the line of the edit that left it so; without
// --check the same run goes on.
TEST(Lifecycle, CheckStopsAtTheStepAndLineThatBrokeANeighbourhood) {
  const std::string model = fault_models + "breaks_symmetry.vvp";
  test_run::result checked = batch({"--quiet", "--steps", "3", "--check", model});
  EXPECT_EQ(checked.status, 1) << report(checked);
  EXPECT_EQ(checked.out, "step 1\nstep 2\n") << report(checked);
  EXPECT_EQ(checked.err, "vvinterpreter: " + model + ":22: check: mesh S: vertex 1 is a neighbour of vertex 2 "
                         "but not the other way round (last edits: vertex 2 at " + model + ":12, vertex 1 at " +
                         model + ":22) (after step 2)\n")
      << report(checked);
  test_run::result unchecked = batch({"--quiet", "--steps", "3", model});
  EXPECT_EQ(unchecked.status, 0) << report(unchecked);
  EXPECT_EQ(unchecked.out, "step 1\nstep 2\nstep 3\n") << report(unchecked);
}

// Issue 9, item 5: a closed curve of 128 vertices was drawn as two filled
// 128-gons and exported as two faces; now it is drawn as its outline and
// exported as one closed `l` polyline.
TEST(Lifecycle, ACurveIsDrawnAndExportedAsLines) {
  std::string d = fresh_dir("curve_lines");
  test_run::result r = batch({"--quiet", "--steps", "0", "--export", d + "curve.obj", "--screenshot",
                              d + "curve.png", "--size", "300x300", VV_TESTS_DIR "/models/circle128.vvp"});
  ASSERT_EQ(r.status, 0) << report(r);
  std::ifstream obj_file(d + "curve.obj");
  std::string obj((std::istreambuf_iterator<char>(obj_file)), std::istreambuf_iterator<char>());
  std::vector<std::string> l_lines, f_lines;
  for (const std::string& line : lines_of(obj)) {
    if (line.rfind("l ", 0) == 0) l_lines.push_back(line);
    if (line.rfind("f ", 0) == 0) f_lines.push_back(line);
  }
  EXPECT_TRUE(f_lines.empty()) << obj;
  ASSERT_EQ(l_lines.size(), 1u) << obj;
  std::istringstream indices(l_lines[0].substr(2));
  std::vector<int> loop;
  for (int i; indices >> i;) loop.push_back(i);
  ASSERT_EQ(loop.size(), 129u);
  EXPECT_EQ(loop.front(), loop.back());
  for (std::size_t i = 0; i + 1 < loop.size(); ++i)  // around the circle, one way or the other
    EXPECT_EQ((loop[i + 1] - loop[i] + 128) % 128 == 1 || (loop[i] - loop[i + 1] + 128) % 128 == 1, true) << i;
  // An outline covers a thin ring of the picture: the filled disc of this
  // size covered over a third of it.
  image im = load_png(d + "curve.png");
  ASSERT_TRUE(im.ok());
  box b = object_box(im);
  ASSERT_FALSE(b.empty());
  EXPECT_GT(b.width(), 150) << describe(b);
  EXPECT_LT(b.pixels, long(im.width) * im.height / 20) << describe(b);
}

// Issue 9, item 4: a model reads OBJ (OFF, PLY, STL) with readFile, as it
// reads .vvm, without including anything; errors name the .vvp line.
TEST(Lifecycle, AModelReadsPolygonFilesWithReadFile) {
  const std::string model = VV_TESTS_DIR "/models/reads_obj.vvp";
  test_run::result r = batch({"--quiet", model});
  EXPECT_EQ(r.out, "6 vertices, 7 edges\n") << report(r);
  EXPECT_NE(r.status, 0) << report(r);
  EXPECT_EQ(r.err, "vvinterpreter: " + model + ":14: readFile: " VV_TESTS_DIR
                   "/models/missing.ply: cannot open file: No such file or directory (in start)\n")
      << report(r);
}

// Issue 10, parameters: `param` globals listed, set from the command line,
// and every wrong --set refused with one line naming the parameter.
TEST(Parameters, ListedAndSetFromTheCommandLine) {
  const std::string model = VV_TESTS_DIR "/models/parameters.vvp";
  test_run::result plain = batch({"--quiet", model});
  EXPECT_EQ(plain.out, "rate 0.5 cells 3 grow 1 seeds 7 scale 0.1\n") << report(plain);
  test_run::result set = batch({"--quiet", "--set", "rate=0.25", "--set", "grow=false", "--set", "cells=100",
                                "--set", "scale=2.5", model});
  EXPECT_EQ(set.status, 0) << report(set);
  EXPECT_EQ(set.out, "rate 0.25 cells 100 grow 0 seeds 7 scale 2.5\n") << report(set);
  test_run::result listed = batch({"--list-params", "--set", "seed_count=12", model});
  EXPECT_EQ(listed.status, 0) << report(listed);
  EXPECT_EQ(listed.out,
            "rate double 0.5 [0, 1]\ncells int 3 [1, 100]\ngrow bool true\nseed_count unsigned 12\n"
            "scale float 0.1\n")
      << report(listed);
}

TEST(Parameters, AWrongSetIsOneLineNamingTheParameter) {
  const std::string model = VV_TESTS_DIR "/models/parameters.vvp";
  struct wrong {
    std::string set, message;
  };
  const std::vector<wrong> cases = {
      {"speed=1", model + ": --set speed=1: the model has no parameter speed (it has rate, cells, grow, "
                          "seed_count, scale)"},
      {"cells=1.5", model + ":4: --set cells=1.5: parameter cells is an int, and \"1.5\" is not one"},
      {"seed_count=-2", model + ":6: --set seed_count=-2: parameter seed_count is an unsigned, and \"-2\" is not one"},
      {"grow=yes", model + ":5: --set grow=yes: parameter grow is a bool, and \"yes\" is not one (true, false, 1 or 0)"},
      {"rate=2", model + ":3: --set rate=2: 2 is outside the range [0, 1] of parameter rate"},
      {"cells=0", model + ":4: --set cells=0: 0 is outside the range [1, 100] of parameter cells"},
  };
  for (const wrong& w : cases) {
    test_run::result r = batch({"--quiet", "--set", w.set, model});
    EXPECT_EQ(r.status, 1) << w.set << "\n" << report(r);
    EXPECT_EQ(r.out, "") << w.set << "\n" << report(r);
    EXPECT_EQ(r.err, "vvinterpreter: " + w.message + "\n") << report(r);
  }
  test_run::result malformed = batch({"--set", "rate", model});
  EXPECT_EQ(malformed.status, 2) << report(malformed);
  EXPECT_TRUE(has(malformed.err, "--set needs NAME=VALUE, e.g. --set rate=0.5")) << report(malformed);
}

// Issue 9, items 1 and 2: a vv 1.1 program sees OpenGL without including
// it and writes 2D points with two coordinates; it draws its own red
// triangle in the screenshot.
TEST(Lifecycle, AVv11ProgramDrawsWithOpenGlItDidNotInclude) {
  std::string d = fresh_dir("vv11_gl");
  test_run::result r = batch({"--quiet", "--screenshot", d + "shot.png", "--size", "200x150",
                              VV_TESTS_DIR "/models/vv11_gl_render.vvp"});
  ASSERT_EQ(r.status, 0) << report(r);
  image im = load_png(d + "shot.png");
  ASSERT_TRUE(im.ok());
  long red = 0;
  for (int y = 0; y < im.height; ++y)
    for (int x = 0; x < im.width; ++x) {
      const unsigned char* p = im.at(x, y);
      red += p[0] > 200 && p[1] < 60 && p[2] < 60;
    }
  EXPECT_GT(red, 200 * 150 / 10) << "the triangle is not drawn";
}

// Defect 7: models were built without debug information. --debug builds
// with -g -O0 and keeps the generated C++ beside the plugin; normal builds
// carry line tables (crash reports use them) at the level asked for (the
// default's level depends on VV_OPT, which the test suite may set).
TEST(Lifecycle, DebugBuildsForGdbAndKeepsTheGeneratedCpp) {
  test_run::result r = test_run::run(test_run::interpreter({"--compile-only", "--debug", fault_models + "counter.vvp"}));
  ASSERT_EQ(r.status, 0) << report(r);
  std::vector<std::string> out = lines_of(r.out);
  ASSERT_FALSE(out.empty());
  fs::path plugin = out.back();
  ASSERT_TRUE(fs::exists(plugin)) << report(r);
  std::string command = slurp((plugin.parent_path() / "command").string());
  EXPECT_TRUE(has(command, " -g ") && has(command, " -O0 ")) << command;
  EXPECT_TRUE(has(slurp((plugin.parent_path() / "model.cpp").string()), "#line ")) << "no generated C++ beside it";
  // -O0, as the other tests build this model: the build is theirs, not one more compile.
  r = test_run::run(test_run::interpreter({"--compile-only", "--opt", "0", fault_models + "counter.vvp"}));
  ASSERT_EQ(r.status, 0) << report(r);
  plugin = lines_of(r.out).back();
  command = slurp((plugin.parent_path() / "command").string());
  EXPECT_TRUE(has(command, " -g1 ") && has(command, " -O0 ") && !has(command, " -g ")) << command;
  // Line tables and the functions' names, nothing more: a -gdwarf-4 after
  // -g1 gave g++ and clang all of the debug information (a third of the
  // compile time, five times the object).
  test_run::result info = test_run::run({"readelf", "--debug-dump=info", plugin.string()});
  ASSERT_EQ(info.status, 0) << info.err;
  EXPECT_TRUE(has(info.out, "DW_TAG_subprogram")) << "no functions named in " << plugin;
  EXPECT_FALSE(has(info.out, "DW_TAG_formal_parameter")) << "parameters described in " << plugin;
}

// The compiler's error about a .vvp line shows the .vvp column (not the
// column in the generated line) and the .vvp line with a caret under it.
TEST(Lifecycle, CompilerErrorsPointIntoTheVvpLine) {
  std::string model = VV_TESTS_DIR "/models/compile_error.vvp";
  test_run::result r = test_run::run(test_run::interpreter({"--compile-only", model}));
  EXPECT_NE(r.status, 0);
  // Line 11 is "  std::string name = v$pos;": g++ points at pos, clang at
  // the variable it cannot initialise.
  const std::string at = model_compiler::clang ? ":11:15: error: no viable conversion from" : ":11:24: error: conversion from";
  const std::string caret = model_compiler::clang ? "                ^\n" : "                         ^\n";
  EXPECT_TRUE(has(r.out, model + at)) << report(r);
  EXPECT_TRUE(has(r.out, "\n    std::string name = v$pos;\n" + caret)) << report(r);
  EXPECT_EQ(r.err.rfind("vvinterpreter: " + model + at.substr(0, 13), 0), 0u) << report(r);
}

}  // namespace
