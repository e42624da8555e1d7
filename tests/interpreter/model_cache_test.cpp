// The model cache as users meet it (docs/interpreter.md, "Building and
// caching models"): one entry per file however its path is typed; damaged
// plugins and precompiled headers rebuilt with a note; --rebuild; the
// leftovers of killed builds removed; builds of one model at once, even
// from separate PID namespaces, all succeed.
//
// Models are tiny and each test compiles as few as it needs (a compile is
// about two seconds). Most use the suite's shared cache; their models live
// in this process's scratch folder, so each run compiles them afresh.
#include <gtest/gtest.h>

#include <sys/time.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <future>
#include <string>
#include <vector>

#include "cache_harness.hpp"
#include "model_compiler.hpp"
#include "run_interpreter.hpp"
#include "test_files.hpp"

using test_files::scratch_dir;

namespace fs = std::filesystem;

namespace {

//! The plugin path --compile-only prints (its last line of output).
std::string plugin_of(const test_run::result& r) {
  std::string s = r.out;
  while (!s.empty() && s.back() == '\n') s.pop_back();
  std::size_t nl = s.rfind('\n');
  return nl == std::string::npos ? s : s.substr(nl + 1);
}

// A model that says it ran, with a warning (so that the cached warnings
// are shown too). `tag` makes its text, and so its cache key, its own.
std::string tiny_model(const std::string& tag) {
  return "#include <cstdio>\n"
         "// " + tag + "\n"
         "start { int unused_x = 1; std::printf(\"model ran: %d\\n\", 6 * 7); }\n";
}

const std::string found_in_cache = ": compiled model found in the cache\n";

// The warning of tiny_model, under the name `typed`.
std::string tiny_warning(const std::string& typed) {
  return model_compiler::in_function(typed) + typed +
         ":3:13: warning: unused variable 'unused_x' [-Wunused-variable]\n"
         "  start { int unused_x = 1; std::printf(\"model ran: %d\\n\", 6 * 7); }\n"
         "              ^\n";
}

// examples/x.vvp, ./x.vvp, an absolute path, a path through `..`, through a
// linked folder, and a link to the file beside it: one file, one entry.
// Each later spelling finds the first one's build, and its warning names
// the file as that spelling types it.
TEST(ModelCache, OneFileHasOneEntryHoweverItsPathIsTyped) {
  const std::string dir = fresh_dir("spellings");
  fs::create_directories(dir + "m/sub");
  write(dir + "m/t.vvp", tiny_model("spellings"));
  fs::create_directory_symlink("m", dir + "mlink");
  fs::create_symlink("t.vvp", dir + "m/link.vvp");

  test_run::result first = run_in(dir, VV_TEST_CACHE, {"--compile-only", "m/t.vvp"});
  ASSERT_EQ(first.status, 0) << report(first);
  ASSERT_TRUE(contains(first.out, "m/t.vvp: translated in")) << report(first);
  EXPECT_EQ(first.err, tiny_warning("m/t.vvp"));
  const std::string plugin = plugin_of(first);

  struct spelling {
    std::string cwd, typed;
  };
  for (const spelling& s : std::vector<spelling>{{dir, "./m/t.vvp"},
                                                 {dir, dir + "m/t.vvp"},
                                                 {dir + "m/sub", "../t.vvp"},
                                                 {dir + "m", "t.vvp"},
                                                 {dir, "mlink/t.vvp"},
                                                 {dir, "m/sub/../../mlink/./t.vvp"},
                                                 {dir, "m/link.vvp"}}) {
    SCOPED_TRACE(s.typed + " in " + s.cwd);
    test_run::result again = run_in(s.cwd, VV_TEST_CACHE, {"--compile-only", s.typed});
    EXPECT_EQ(again.status, 0) << report(again);
    EXPECT_EQ(again.out, s.typed + found_in_cache + plugin + "\n");
    EXPECT_EQ(again.err, tiny_warning(s.typed));
  }
  test_run::result ran = run_in(dir + "m", VV_TEST_CACHE, {"--batch", "../mlink/t.vvp"});
  EXPECT_EQ(ran.status, 0) << report(ran);
  EXPECT_TRUE(contains(ran.out, "../mlink/t.vvp" + found_in_cache)) << report(ran);
  EXPECT_TRUE(contains(ran.out, "model ran: 42\n")) << report(ran);
}

// A truncated plugin in the cache is found out before it is loaded: the
// model is compiled again, with one line saying why, and runs.
TEST(ModelCache, TruncatedPluginIsCompiledAgainWithANote) {
  const std::string dir = fresh_dir("truncated_plugin");
  const std::string model = dir + "t.vvp";
  write(model, tiny_model("truncated plugin"));
  test_run::result built = run({"--compile-only", model});
  ASSERT_EQ(built.status, 0) << report(built);
  const std::string plugin = plugin_of(built);
  const std::uintmax_t size = fs::file_size(plugin);
  fs::resize_file(plugin, 4096);

  test_run::result ran = run({"--batch", model});
  EXPECT_EQ(ran.status, 0) << report(ran);
  EXPECT_EQ(ran.err, model + ": note: the cached build was damaged (model.so has 4096 bytes, " +
                         std::to_string(size) + " expected); compiling it again\n" + tiny_warning(model));
  EXPECT_TRUE(contains(ran.out, model + ": translated in")) << report(ran);
  EXPECT_TRUE(contains(ran.out, "model ran: 42\n")) << report(ran);

  test_run::result again = run({"--batch", model});
  EXPECT_EQ(again.status, 0) << report(again);
  EXPECT_TRUE(contains(again.out, model + found_in_cache)) << report(again);
  EXPECT_EQ(again.err, tiny_warning(model));
}

// A truncated precompiled header is built again (in a cache of this test's
// own: the suite's is in use by other tests), with one line saying why.
TEST(ModelCache, TruncatedPrecompiledHeaderIsBuiltAgainWithANote) {
  const std::string dir = fresh_dir("truncated_header");
  ASSERT_NO_FATAL_FAILURE(suite_header_exists());
  const std::string cache = dir + "cache";
  fs::create_directories(cache);
  fs::copy(std::string(VV_TEST_CACHE) + "/pch", cache + "/pch", fs::copy_options::recursive | fs::copy_options::copy_symlinks);
  int truncated = 0;
  for (const auto& e : fs::recursive_directory_iterator(cache + "/pch"))
    if (e.is_regular_file() && e.path().filename() == model_compiler::precompiled_header)
      fs::resize_file(e.path(), 1000000), ++truncated;
  ASSERT_GT(truncated, 0);

  const std::string model = dir + "t.vvp";
  write(model, tiny_model("truncated header"));
  test_run::result built = run_in(dir, cache, {"--batch", model});
  EXPECT_EQ(built.status, 0) << report(built);
  const std::string note = model + ": note: the cached precompiled vvlib header was damaged "
                                   "(model/" + model_compiler::precompiled_header + " has 1000000 bytes, ";
  EXPECT_EQ(built.err.rfind(note, 0), 0u) << report(built);
  EXPECT_TRUE(contains(built.err, " expected); it was built again\n" + tiny_warning(model))) << report(built);
  EXPECT_TRUE(contains(built.out, "model ran: 42\n")) << report(built);
}

void age(const std::string& path, long seconds) {
  struct timeval times[2];
  times[0].tv_sec = times[1].tv_sec = std::time(nullptr) - seconds;
  times[0].tv_usec = times[1].tv_usec = 0;
  ASSERT_EQ(lutimes(path.c_str(), times), 0) << path;
}

// --rebuild compiles a model the cache holds; that build, like any, removes
// what killed builds left in the cache once it is an hour old, and leaves
// a build that may still be running elsewhere.
TEST(ModelCache, RebuildCompilesAgainAndRemovesOldLeftoversOfKilledBuilds) {
  const std::string dir = fresh_dir("rebuild");
  const std::string model = dir + "t.vvp";
  write(model, tiny_model("rebuild"));
  test_run::result built = run({"--compile-only", model});
  ASSERT_EQ(built.status, 0) << report(built);

  const std::string cache = VV_TEST_CACHE;
  const std::string tag = "0123456789abcdef0123456789abcdef-" + std::to_string(getpid());
  const std::string dead_header = cache + "/pch/tmp-" + tag + "-dead";
  const std::string dead_plugin = cache + "/plugins/tmp-" + tag + "-dead";
  const std::string running = cache + "/plugins/tmp-" + tag + "-running";
  for (const std::string& d : {dead_header + "/model", dead_plugin, running}) fs::create_directories(d);
  write(dead_header + "/model/model.hpp.gch", std::string(1 << 20, 'x'));
  write(dead_plugin + "/model.so", std::string(1 << 16, 'x'));
  age(dead_header, 2 * 3600);
  age(dead_plugin, 2 * 3600);

  test_run::result again = run({"--compile-only", "--rebuild", model});
  EXPECT_EQ(again.status, 0) << report(again);
  EXPECT_TRUE(contains(again.out, model + ": translated in")) << report(again);
  EXPECT_NE(plugin_of(again), plugin_of(built));
  EXPECT_TRUE(fs::is_regular_file(plugin_of(again))) << report(again);
  EXPECT_FALSE(fs::exists(dead_header));
  EXPECT_FALSE(fs::exists(dead_plugin));
  EXPECT_TRUE(fs::exists(running));
  fs::remove_all(running);
}

TEST(ModelCache, RebuildIsRefusedByTheViewer) {
  test_run::result r = run({"--rebuild", "model.vvp"});
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.substr(0, r.err.find('\n')),
            "vvinterpreter: --rebuild is for --batch and --compile-only (the viewer rebuilds with its Recompile "
            "button)");
}

// VV_OPT in the environment gives the default optimisation level, --opt
// overrides it, and a level it cannot be is refused naming it. The level
// is read from the command the build kept beside its plugin.
TEST(ModelCache, VvOptGivesTheDefaultLevelAndOptOverridesIt) {
  const std::string model = fresh_dir("levels") + "t.vvp";
  write(model, tiny_model("levels"));
  auto compile = [&](const std::string& setting, std::vector<std::string> more) {
    std::vector<std::string> argv = {"env", setting, VV_INTERPRETER, "--cache", VV_TEST_CACHE, "--compile-only"};
    argv.insert(argv.end(), more.begin(), more.end());
    argv.push_back(model);
    return test_run::run(argv, 280);
  };
  auto command_of = [](const test_run::result& r) {
    return test_files::slurp((fs::path(plugin_of(r)).parent_path() / "command").string());
  };
  test_run::result quick = compile("VV_OPT=0", {});
  ASSERT_EQ(quick.status, 0) << report(quick);
  EXPECT_TRUE(contains(command_of(quick), " -O0 ")) << command_of(quick);
  test_run::result told = compile("VV_OPT=0", {"--opt", "1"});
  ASSERT_EQ(told.status, 0) << report(told);
  EXPECT_TRUE(contains(command_of(told), " -O1 ")) << command_of(told);
  EXPECT_FALSE(contains(command_of(told), " -O0 ")) << command_of(told);
  test_run::result bad = compile("VV_OPT=7", {});
  EXPECT_EQ(bad.status, 2) << report(bad);
  EXPECT_EQ(bad.err.substr(0, bad.err.find('\n')), "vvinterpreter: VV_OPT needs a level from 0 to 3") << report(bad);
  // Its neighbour VV_BUILD_CORES (compilers one build may run) likewise.
  for (const char* cores : {"VV_BUILD_CORES=0", "VV_BUILD_CORES=two"}) {
    test_run::result refused = compile(cores, {});
    EXPECT_EQ(refused.status, 2) << report(refused);
    EXPECT_EQ(refused.err.substr(0, refused.err.find('\n')),
              "vvinterpreter: VV_BUILD_CORES needs a number of cores (1 or more)")
        << report(refused);
  }
}

// Two builds of one model at once into one cache both succeed: the model is
// compiled once, and the second build uses the first's plugin. Where the
// machine allows, each runs as process 1 of a PID namespace of its own, as
// in two containers sharing a cache: temporaries named by process id would
// be the same file.
TEST(ModelCache, TwoBuildsOfOneModelAtOnceCompileItOnceAndBothUseIt) {
  const std::string dir = fresh_dir("at_once");
  const std::string model = dir + "t.vvp";
  write(model, tiny_model("at once"));
  std::vector<std::string> prefix;
  if (test_run::run({"unshare", "--pid", "--fork", "true"}, 30).status == 0) prefix = {"unshare", "--pid", "--fork"};
  else std::fprintf(stderr, "note: no PID namespaces here; the two builds share one\n");
  std::vector<std::string> argv = prefix;
  for (const std::string& a : {std::string(VV_INTERPRETER), std::string("--cache"), std::string(VV_TEST_CACHE),
                               std::string("--compile-only"), model})
    argv.push_back(a);
  auto one = std::async(std::launch::async, [&] { return test_run::run(argv, 280); });
  auto two = std::async(std::launch::async, [&] { return test_run::run(argv, 280); });
  test_run::result a = one.get(), b = two.get();
  EXPECT_EQ(a.status, 0) << report(a);
  EXPECT_EQ(b.status, 0) << report(b);
  EXPECT_TRUE(fs::is_regular_file(plugin_of(a))) << report(a);
  EXPECT_TRUE(fs::is_regular_file(plugin_of(b))) << report(b);
  // One compiled it; the other waited for it (the key's build lock) and
  // found that build in the cache.
  const bool a_found = contains(a.out, model + found_in_cache), b_found = contains(b.out, model + found_in_cache);
  EXPECT_NE(a_found, b_found) << report(a) << report(b);
  EXPECT_EQ(plugin_of(a), plugin_of(b)) << report(a) << report(b);
  test_run::result ran = run({"--batch", model});
  EXPECT_EQ(ran.status, 0) << report(ran);
  EXPECT_TRUE(contains(ran.out, model + found_in_cache)) << report(ran);
  EXPECT_TRUE(contains(ran.out, "model ran: 42\n")) << report(ran);
}

#ifdef VV_MODELS_LINK_WITH_LLD
// Where lld is installed, models are linked with it (a third of the default
// linker's time, every edit): it names itself in the plugin.
TEST(ModelCache, PluginsAreLinkedWithLldWhereItIsInstalled) {
  const std::string dir = fresh_dir("lld");
  write(dir + "m.vvp", "#include <cstdio>\nstart { std::printf(\"linked\\n\"); }\n");
  test_run::result compiled = run({"--compile-only", "--rebuild", dir + "m.vvp"});
  ASSERT_EQ(compiled.status, 0) << report(compiled);
  test_run::result comment = test_run::run({"readelf", "-p", ".comment", plugin_of(compiled)});
  EXPECT_TRUE(contains(comment.out, "Linker: ") && contains(comment.out, " LLD ")) << comment.out;
}
#endif

// ---- the declarations' part (vvinterpreter/compile/declarations_part.hpp) ----

//! The entries (keys) of the cache's decls/ folder.
std::vector<std::string> parts_in(const std::string& cache) {
  std::vector<std::string> keys;
  for (const auto& e : fs::directory_iterator(cache + "/decls"))
    if (fs::is_symlink(e.symlink_status())) keys.push_back(e.path().string());
  return keys;
}

//! How the plugin --compile-only printed was built (its command file).
std::string command_of(const test_run::result& compiled) {
  return test_files::slurp(fs::path(plugin_of(compiled)).parent_path().string() + "/command");
}

const std::string apart_flag = "-DVV_DECLARATIONS_APART";

// The tests below that make parts from a model's first build say
// --expect-edits, as the viewer does. Without it, batch runs and
// --compile-only make the part of a new model only on an idle second core
// (VV_BUILD_CORES=1 here says there is none): on a busy machine they
// compile it whole until its file changes, since the part costs half a
// compile more and pays off only from the first edit on.
TEST(ModelCacheDeclarations, BatchCompilesANewModelWholeOnOneCoreAndMakesItsPartOnceTheFileChanges) {
  const std::string dir = fresh_dir("apart_when_edited");
  const std::string cache = cache_with_header(dir);
  const std::string model = dir + "m.vvp";
  const std::string head = "#include <cstdio>\nvertex { double h; };\nmesh S;\n";
  write(model, head + "start { vertex v; v$h = 1.5; std::printf(\"h=%g\\n\", v$h); }\n");
  test_run::result first =
      test_run::run({"env", "-C", dir, "VV_BUILD_CORES=1", VV_INTERPRETER, "--cache", cache, "--compile-only", model}, 280);
  ASSERT_EQ(first.status, 0) << report(first);
  std::string command = command_of(first);
  EXPECT_EQ(std::count(command.begin(), command.end(), '\n'), 1) << command;
  EXPECT_FALSE(contains(command, apart_flag)) << command;
  EXPECT_FALSE(fs::exists(cache + "/decls") && !parts_in(cache).empty());

  // Edited: the part is made beside the program, and the next edit links it.
  write(model, head + "start { vertex v; v$h = 2.5; std::printf(\"h=%g\\n\", v$h); }\n");
  test_run::result edited = run_in(dir, cache, {"--batch", model});
  ASSERT_EQ(edited.status, 0) << report(edited);
  EXPECT_TRUE(contains(edited.out, "h=2.5\n")) << report(edited);
  ASSERT_EQ(parts_in(cache).size(), 1u);
  write(model, head + "start { vertex v; v$h = 3.5; std::printf(\"h=%g\\n\", v$h); }\n");
  test_run::result again = run_in(dir, cache, {"--compile-only", model});
  ASSERT_EQ(again.status, 0) << report(again);
  command = command_of(again);
  EXPECT_EQ(std::count(command.begin(), command.end(), '\n'), 1) << command;
  EXPECT_TRUE(contains(command, apart_flag)) << command;

  // A part that exists serves a first build of the same declarations (the
  // same program in another folder).
  fs::create_directories(dir + "other");
  write(dir + "other/m.vvp", head + "start { vertex v; v$h = 4.5; std::printf(\"h=%g\\n\", v$h); }\n");
  test_run::result other = run_in(dir, cache, {"--batch", dir + "other/m.vvp"});
  ASSERT_EQ(other.status, 0) << report(other);
  EXPECT_TRUE(contains(other.out, "h=4.5\n")) << report(other);
  test_run::result listed = run_in(dir, cache, {"--compile-only", dir + "other/m.vvp"});
  EXPECT_TRUE(contains(command_of(listed), apart_flag)) << command_of(listed);
  EXPECT_EQ(parts_in(cache).size(), 1u);
}

// An edit below the last property block compiles the program alone and
// links the part compiled for the declarations the first time.
TEST(ModelCacheDeclarations, AnEditBelowThePropertyBlocksCompilesOnlyTheProgram) {
  const std::string dir = fresh_dir("apart_edit");
  const std::string cache = cache_with_header(dir);
  const std::string model = dir + "m.vvp";
  const std::string head = "#include <cstdio>\nvertex { double h; };\nmesh S;\n";
  write(model, head + "start { vertex v; v$h = 1.5; add v to S; std::printf(\"h=%g in %zu\\n\", v$h, S.size()); }\n");
  test_run::result first = run_in(dir, cache, {"--batch", "--expect-edits", model});
  ASSERT_EQ(first.status, 0) << report(first);
  EXPECT_TRUE(contains(first.out, "h=1.5 in 1\n")) << report(first);
  ASSERT_EQ(parts_in(cache).size(), 1u);
  const std::string part = fs::canonical(parts_in(cache)[0]).string();
  EXPECT_EQ(test_files::slurp(part + "/verdict"), "usable");
  const auto compiled_at = fs::last_write_time(part + "/declarations.o");

  write(model, head + "start { vertex v; v$h = 2.5; add v to S; std::printf(\"h=%g in %zu\\n\", v$h, S.size()); }\n");
  test_run::result edited = run_in(dir, cache, {"--compile-only", "--expect-edits", model});
  ASSERT_EQ(edited.status, 0) << report(edited);
  // One compiler run: the program, linked with the part as it was.
  std::string command = command_of(edited);
  EXPECT_EQ(std::count(command.begin(), command.end(), '\n'), 1) << command;
  EXPECT_TRUE(contains(command, apart_flag)) << command;
  EXPECT_TRUE(contains(command, " " + part + "/declarations.o ")) << command;
  EXPECT_EQ(parts_in(cache).size(), 1u);
  EXPECT_EQ(fs::last_write_time(part + "/declarations.o"), compiled_at);
  test_run::result ran = run_in(dir, cache, {"--batch", "--expect-edits", model});
  EXPECT_EQ(ran.status, 0) << report(ran);
  EXPECT_TRUE(contains(ran.out, "h=2.5 in 1\n")) << report(ran);

  // The compiler's errors about the program still name its lines.
  write(model, head + "start { vertex v; v$h = no_such_value; }\n");
  test_run::result broken = run_in(dir, cache, {"--batch", "--expect-edits", model});
  EXPECT_EQ(broken.status, 1) << report(broken);
  const std::string undeclared = model_compiler::clang ? "use of undeclared identifier 'no_such_value'"
                                                       : "'no_such_value' was not declared in this scope";
  EXPECT_TRUE(contains(broken.err, model + ":4:25: error: " + undeclared)) << report(broken);
}

// Declarations that keep state of their own (here a static counter that
// every new vertex's property reads) would have two copies of it, the
// part's and the program's: such a model is compiled whole.
TEST(ModelCacheDeclarations, DeclarationsThatHoldStateAreCompiledWithTheProgram) {
  const std::string dir = fresh_dir("apart_state");
  const std::string cache = cache_with_header(dir);
  const std::string model = dir + "m.vvp";
  write(model,
        "#include <cstdio>\n"
        "static int made = 0;\n"
        "static int next_id() { return ++made; }\n"
        "vertex { int id = next_id(); };\n"
        "mesh S;\n"
        "start { S.readXMLFile(\"" VV_SOURCE_DIR "/models/pyramid.vvm\"); vertex v;\n"
        "  std::printf(\"vertex %d of %d made\\n\", v$id, made); }\n");
  test_run::result ran = run_in(dir, cache, {"--batch", "--expect-edits", model});
  ASSERT_EQ(ran.status, 0) << report(ran);
  // One counter: every vertex's properties made count (a chunk of vertex
  // slots makes them a thousand at a time, its old copies too), so the
  // count the program reads is at least the number of its new vertex.
  std::size_t at = ran.out.find("vertex ");
  ASSERT_NE(at, std::string::npos) << report(ran);
  int id = 0, made = 0;
  ASSERT_EQ(std::sscanf(ran.out.c_str() + at, "vertex %d of %d made", &id, &made), 2) << report(ran);
  EXPECT_GE(id, 7) << report(ran);
  EXPECT_GE(made, id) << report(ran);
  ASSERT_EQ(parts_in(cache).size(), 1u);
  EXPECT_EQ(test_files::slurp(parts_in(cache)[0] + "/verdict"), "writable data of its own (_ZL4made)");
  test_run::result again = run_in(dir, cache, {"--compile-only", "--expect-edits", "--rebuild", model});
  ASSERT_EQ(again.status, 0) << report(again);
  EXPECT_FALSE(contains(command_of(again), apart_flag)) << command_of(again);
}

// A part that does not compile on its own (a function whose return type is
// deduced from a body it does not hold) leaves the model compiled whole,
// at once from then on.
TEST(ModelCacheDeclarations, DeclarationsThatDoNotCompileApartAreCompiledWithTheProgram) {
  const std::string dir = fresh_dir("apart_fails");
  const std::string cache = cache_with_header(dir);
  const std::string model = dir + "m.vvp";
  const std::string head = "#include <cstdio>\nauto scale() { return 2.0; }\nvertex { double h = scale(); };\n";
  write(model, head + "start { vertex v; std::printf(\"h=%g\\n\", v$h); }\n");
  test_run::result ran = run_in(dir, cache, {"--batch", "--expect-edits", model});
  ASSERT_EQ(ran.status, 0) << report(ran);
  EXPECT_TRUE(contains(ran.out, "h=2\n")) << report(ran);
  ASSERT_EQ(parts_in(cache).size(), 1u);
  EXPECT_EQ(test_files::slurp(parts_in(cache)[0] + "/verdict"), "the declarations' part does not compile");

  write(model, head + "start { vertex v; std::printf(\"h=%g!\\n\", v$h); }\n");
  test_run::result edited = run_in(dir, cache, {"--compile-only", "--expect-edits", model});
  ASSERT_EQ(edited.status, 0) << report(edited);
  std::string command = command_of(edited);
  EXPECT_EQ(std::count(command.begin(), command.end(), '\n'), 1) << command;
  EXPECT_FALSE(contains(command, apart_flag)) << command;
}

// The same program in two folders shares one part (its #line names hold
// the model's folder as a marker), and a crash or a run-time error in the
// part's code is reported at each folder's own file and line. A folder holding a header
// the declarations include gets a part of its own.
TEST(ModelCacheDeclarations, OneProgramInTwoFoldersSharesItsPartAndReportsNameEachFolder) {
  const std::string dir = fresh_dir("apart_folders");
  const std::string cache = cache_with_header(dir);
  // The properties' initialiser traps once a vertex is made; the code that
  // makes vertices is the part's (vv::context is instantiated there).
  const std::string program =
      "#include <cstdio>\n"
      "inline double made(int n) { if (n > 2) __builtin_trap(); return n; }\n"
      "vertex { double h = made(3); };\n"
      "mesh S;\n"
      "start { std::printf(\"started\\n\"); vertex v; add v to S; }\n";
  std::vector<std::string> reports;
  for (const char* folder : {"a", "b"}) {
    fs::create_directories(dir + folder);
    const std::string model = dir + folder + "/m.vvp";
    write(model, program);
    test_run::result ran = run_in(dir, cache, {"--batch", "--expect-edits", "--steps", "0", model});
    EXPECT_NE(ran.status, 0) << report(ran);
    // The mesh's initialiser makes the first vertices; paths as the user
    // typed them, relative to the working folder.
    EXPECT_TRUE(contains(ran.err, std::string(folder) + "/m.vvp:2: crashed with SIGILL")) << report(ran);
    EXPECT_TRUE(contains(ran.err, "  " + std::string(folder) + "/m.vvp:2 in made(int)\n")) << report(ran);
    EXPECT_FALSE(contains(ran.err, "vv-model-folder")) << report(ran);
  }
  ASSERT_EQ(parts_in(cache).size(), 1u);

  // An exception raised there names each folder's file too. The properties
  // of a thousand vertices are made at a time, by the part's code: the
  // 2000th vertex makes new ones.
  const std::string raising =
      "#include <cstdlib>\n"
      "inline double made() { if (std::getenv(\"VV_RAISE\")) throw vv::error(vv::where::here(), \"made\", \"raised\"); return 1; }\n"
      "vertex { double h = made(); };\n"
      "mesh S;\n"
      "start { setenv(\"VV_RAISE\", \"1\", 1); for (int i = 0; i < 2000; ++i) { vertex v; add v to S; } }\n";
  for (const char* folder : {"a", "b"}) {
    const std::string model = dir + folder + "/r.vvp";
    write(model, raising);
    test_run::result ran = run_in(dir, cache, {"--batch", "--expect-edits", "--steps", "0", model});
    EXPECT_NE(ran.status, 0) << report(ran);
    // Thrown where vertices' properties are made, it ends the model.
    EXPECT_TRUE(contains(ran.err, std::string(folder) + "/r.vvp:2: crashed with an uncaught exception (" + model +
                                      ":2: made: raised)"))
        << report(ran);
    EXPECT_FALSE(contains(ran.err, "vv-model-folder")) << report(ran);
  }
  ASSERT_EQ(parts_in(cache).size(), 2u);

  // <vector> found beside the model: the compiler would read that one.
  fs::create_directories(dir + "c");
  write(dir + "c/m.vvp", "#include <vector>\n" + program);
  write(dir + "c/vector", "#include_next <vector>\n");
  write(dir + "b/m.vvp", "#include <vector>\n" + program);
  for (const char* folder : {"b", "c"}) {
    test_run::result compiled = run_in(dir, cache, {"--compile-only", "--expect-edits", dir + folder + "/m.vvp"});
    EXPECT_EQ(compiled.status, 0) << report(compiled);
  }
  EXPECT_EQ(parts_in(cache).size(), 4u);
}

// A damaged part is found out before it is linked: compiled again, with
// one line saying why.
TEST(ModelCacheDeclarations, DamagedPartIsCompiledAgainWithANote) {
  const std::string dir = fresh_dir("apart_damaged");
  const std::string cache = cache_with_header(dir);
  const std::string model = dir + "m.vvp";
  const std::string head = "#include <cstdio>\nvertex { double h; };\n";
  write(model, head + "start { vertex v; v$h = 3; std::printf(\"h=%g\\n\", v$h); }\n");
  test_run::result first = run_in(dir, cache, {"--compile-only", "--expect-edits", model});
  ASSERT_EQ(first.status, 0) << report(first);
  ASSERT_EQ(parts_in(cache).size(), 1u);
  const std::string object = fs::canonical(parts_in(cache)[0]).string() + "/declarations.o";
  const std::uintmax_t size = fs::file_size(object);
  fs::resize_file(object, 4096);

  write(model, head + "start { vertex v; v$h = 4; std::printf(\"h=%g\\n\", v$h); }\n");
  test_run::result ran = run_in(dir, cache, {"--batch", "--expect-edits", model});
  EXPECT_EQ(ran.status, 0) << report(ran);
  EXPECT_EQ(ran.err, model + ": note: the cached declarations' part was damaged (declarations.o has 4096 bytes, " +
                         std::to_string(size) + " expected); it was compiled again\n");
  EXPECT_TRUE(contains(ran.out, "h=4\n")) << report(ran);
}

}  // namespace
