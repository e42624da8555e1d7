// The host's build stage in-process (vvinterpreter/compile): the compiler's
// messages read into .vvp terms, the spelling of a model's path, and the
// model cache's manifests and leftovers. No compiler runs here; the tests
// that compile real models are in model_cache_test.cpp and
// compiler_output_test.cpp.
#include <gtest/gtest.h>

#include <sched.h>
#include <sys/time.h>

#include <ctime>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "compile/build_cores.hpp"
#include "compile/build_history.hpp"
#include "compile/compiler_messages.hpp"
#include "compile/model_cache.hpp"
#include "compile/model_path.hpp"
#include "compile/property_messages.hpp"
#include "compile/shared_declarations.hpp"
#include "test_files.hpp"

namespace fs = std::filesystem;
using test_files::scratch_dir;

namespace {

std::string fresh_dir(const std::string& name) {
  std::string d = scratch_dir() + name;
  fs::remove_all(d);
  fs::create_directories(d);
  return fs::canonical(d).string();
}

void write(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  ASSERT_TRUE(out.good()) << path;
}

// ---------------------------------------------------------------------------
// Compiler messages
// ---------------------------------------------------------------------------

// A #line beyond INT_MAX is legal C++; g++ then prints the line wrapped to a
// negative number. Neither may stop the host: the message stays as g++
// wrote it (there is no .vvp line to show), and the rest is read as usual.
TEST(CompilerMessages, LineNumbersBeyondIntAreLeftAsTheCompilerWroteThem) {
  std::string dir = fresh_dir("line_beyond_int");
  std::string vvp = dir + "/w.vvp";
  write(vvp, "start { int unused_x = 1; }\nstart { int y; }\n");
  std::string cpp = "#line 3000000000 \"" + vvp + "\"\nvoid vv_block_start() { int unused_x = 1; }\n" +
                    "#line 99999999999999999999999 \"" + vvp + "\"\nint z;\n";
  std::string output = vvp + ": In function 'void vv_block_start()':\n" + vvp +
                       ":-1294967296:36: warning: unused variable 'unused_x' [-Wunused-variable]\n" +
                       vvp +
                       ":99999999999999999999999:1: warning: a line no int holds\n" + vvp +
                       ":2:13: warning: unused variable 'y'\n";
  std::string shown = vvi::compiler_messages(output, {"/nowhere/vvlib", cpp, {}});
  EXPECT_EQ(shown, vvp + ": In function 'void vv_block_start()':\n" + vvp +
                       ":-1294967296:36: warning: unused variable 'unused_x' [-Wunused-variable]\n" + vvp +
                       ":99999999999999999999999:1: warning: a line no int holds\n" + vvp +
                       ":2: warning: unused variable 'y'\n  start { int y; }\n");
}

TEST(CompilerMessages, TypographicQuotesBecomePlainOnes) {
  EXPECT_EQ(vvi::plain_quotes("In function \xE2\x80\x98void relax()\xE2\x80\x99: \xE2\x80\x9Cx\xE2\x80\x9D caf\xC3\xA9"),
            "In function 'void relax()': \"x\" caf\xC3\xA9");
  std::string output = "m.vvp: In function \xE2\x80\x98void vv_block_start()\xE2\x80\x99:\n";
  EXPECT_EQ(vvi::compiler_messages(output, {"/nowhere/vvlib", "", {}}), "m.vvp: In function 'void vv_block_start()':\n");
}

// The messages g++ 12 gives for a misspelt vertex, half-edge and mesh
// member of a program with these blocks.
const vvi::property_fields fields{{"crease"}, {"pos", "c"}, {"generation"}};

TEST(PropertyMessages, MisspeltVertexPropertyListsTheVertexProperties) {
  EXPECT_EQ(vvi::property_message("error: 'const vv::traits<vv_vertex_props, vv_edge_props, vv_mesh_props>::"
                                  "vertex_props' has no member named 'position'",
                                  fields),
            "error: the vertex has no property 'position'; its properties are: pos, c");
  EXPECT_EQ(vvi::property_message("error: 'using vertex_props = struct vv_vertex_props' {aka 'struct "
                                  "vv_vertex_props'} has no member named 'posx'; did you mean 'pos'?",
                                  fields),
            "error: the vertex has no property 'posx' (did you mean 'pos'?); its properties are: pos, c");
  EXPECT_EQ(vvi::property_message("error: 'const vv::traits<vv_vertex_props, vv_edge_props, vv_mesh_props>::"
                                  "vertex_props' {aka 'const struct vv_vertex_props'} has no member named 'q'",
                                  fields),
            "error: the vertex has no property 'q'; its properties are: pos, c");
}

TEST(PropertyMessages, MisspeltEdgeAndMeshPropertiesListTheirOwn) {
  EXPECT_EQ(vvi::property_message("error: 'using edge_props = struct vv_edge_props' {aka 'struct vv_edge_props'} "
                                  "has no member named 'creasy'; did you mean 'crease'?",
                                  fields),
            "error: the half-edge record has no property 'creasy' (did you mean 'crease'?); its properties are: "
            "crease");
  EXPECT_EQ(vvi::property_message("error: 'edge' {aka 'vv_edge_props'} has no member named 'w'", fields),
            "error: the half-edge record has no property 'w'; its properties are: crease");
  EXPECT_EQ(vvi::property_message("error: 'using mesh = class vv::mesh<vv_traits>' {aka 'class "
                                  "vv::mesh<vv_traits>'} has no member named 'generations'; did you mean "
                                  "'generation'?",
                                  fields),
            "error: the mesh has no property or member function 'generations' (did you mean 'generation'?); its "
            "properties are: generation");
}

// clang 14's words for the same misspelt members.
TEST(PropertyMessages, ClangsWordsAreRewrittenAlike) {
  EXPECT_EQ(vvi::property_message("error: no member named 'position' in 'vv_vertex_props'", fields),
            "error: the vertex has no property 'position'; its properties are: pos, c");
  EXPECT_EQ(vvi::property_message("error: no member named 'creasy' in 'vv_edge_props'; did you mean 'crease'?", fields),
            "error: the half-edge record has no property 'creasy' (did you mean 'crease'?); its properties are: "
            "crease");
  EXPECT_EQ(vvi::property_message("error: no member named 'q' in 'const vv_vertex_props'", fields),
            "error: the vertex has no property 'q'; its properties are: pos, c");
  EXPECT_EQ(vvi::property_message(
                "error: no member named 'generations' in 'vv::mesh<vv_traits>'; did you mean 'generation'?", fields),
            "error: the mesh has no property or member function 'generations' (did you mean 'generation'?); its "
            "properties are: generation");
  EXPECT_EQ(vvi::property_message("error: no member named 'z' in 'util::Point<double>'", fields), "");
  EXPECT_EQ(vvi::property_message("error: no member named 'pos' in 'vv::vertex<vv_traits>'", fields), "");
  EXPECT_EQ(vvi::property_message("error: no member named 'pos' in namespace 'vv'", fields), "");
}

TEST(PropertyMessages, AKindWithoutABlockHasNone) {
  EXPECT_EQ(vvi::property_message("error: 'struct vv_vertex_props' has no member named 'pos'", {}),
            "error: the vertex has no property 'pos'; it has none (a vertex block declares them)");
}

TEST(PropertyMessages, OtherTypesAndMessagesAreLeftAlone) {
  EXPECT_EQ(vvi::property_message("error: 'struct Pt' has no member named 'z'", fields), "");
  EXPECT_EQ(vvi::property_message("error: 'vertex' {aka 'vv::vertex<vv_traits>'} has no member named 'pos'", fields),
            "");
  EXPECT_EQ(vvi::property_message("error: 'x' was not declared in this scope", fields), "");
  EXPECT_EQ(vvi::property_message("no colon at all has no member named 'x'", fields), "");
}

TEST(CompilerMessages, MisspeltPropertyIsRewrittenAtItsVvpLine) {
  std::string dir = fresh_dir("misspelt_property");
  std::string vvp = dir + "/p.vvp";
  write(vvp, "vertex { double pos; };\nstart { vertex v; v$position = 1; }\n");
  std::string cpp = "#line 2 \"" + vvp + "\"\nvoid vv_block_start() { vertex v; v.props().position = 1; }\n";
  std::string output = vvp + ":2:45: error: \xE2\x80\x98using vertex_props = struct vv_vertex_props\xE2\x80\x99 {aka "
                             "\xE2\x80\x98struct vv_vertex_props\xE2\x80\x99} has no member named "
                             "\xE2\x80\x98position\xE2\x80\x99\n";
  EXPECT_EQ(vvi::compiler_messages(output, {"/nowhere/vvlib", cpp, {{}, {"pos"}, {}}}),
            vvp + ":2:21: error: the vertex has no property 'position'; its properties are: pos\n"
                  "  start { vertex v; v$position = 1; }\n"
                  "                      ^\n");
}

// clang quotes the generated C++ under its message, with a caret and a
// fix-it, and a note where the suggested member is declared; it ends with
// a count. The message moves to the .vvp column and quotes the .vvp line;
// the note quotes the property block's line.
TEST(CompilerMessages, ClangsExcerptsAndCountAreReplacedByTheVvpLines) {
  std::string dir = fresh_dir("misspelt_property_clang");
  std::string vvp = dir + "/p.vvp";
  write(vvp, "vertex { double pos; };\nstart { vertex v; v$poss = 1; }\n");
  std::string cpp = "#line 1 \"" + vvp + "\"\nstruct vv_vertex_props { double pos{}; };\nvoid vv_block_start() { vertex v; "
                    "v.props().poss = 1; }\n";
  std::string output = vvp + ":2:45: error: no member named 'poss' in 'vv_vertex_props'; did you mean 'pos'?\n"
                             "void vv_block_start() { vertex v; v.props().poss = 1; }\n"
                             "                                  ~~~~~~~~~ ^~~~\n"
                             "                                            pos\n" +
                       vvp + ":1:33: note: 'pos' declared here\n"
                             "struct vv_vertex_props { double pos{};\n"
                             "                                ^\n"
                             "1 error generated.\n";
  EXPECT_EQ(vvi::compiler_messages(output, {"/nowhere/vvlib", cpp, {{}, {"pos"}, {}}}),
            vvp + ":2:21: error: the vertex has no property 'poss' (did you mean 'pos'?); its properties are: pos\n"
                  "  start { vertex v; v$poss = 1; }\n"
                  "                      ^\n" +
            vvp + ":1:17: note: 'pos' declared here\n"
                  "  vertex { double pos; };\n"
                  "                  ^\n");
}

// ---------------------------------------------------------------------------
// The spelling of a model's path
// ---------------------------------------------------------------------------

class ModelPath : public testing::Test {
 protected:
  void SetUp() override {
    root_ = fresh_dir("model_path");
    fs::create_directories(root_ + "/m/sub");
    write(root_ + "/m/t.vvp", "start {}\n");
    fs::create_directory_symlink("m", root_ + "/mlink");
    fs::create_symlink("t.vvp", root_ + "/m/same_folder_link.vvp");
    fs::create_directories(root_ + "/other");
    fs::create_symlink("../m/t.vvp", root_ + "/other/t.vvp");
    before_ = fs::current_path();
    fs::current_path(root_);
  }
  void TearDown() override { fs::current_path(before_); }
  std::string root_;
  fs::path before_;
};

TEST_F(ModelPath, EverySpellingOfOneFileIsBuiltUnderOneName) {
  const std::string built = root_ + "/m/t.vvp";
  for (const std::string& typed : std::vector<std::string>{"m/t.vvp", "./m/t.vvp", "m/./t.vvp", "m/sub/../t.vvp", "mlink/t.vvp", root_ + "/m/t.vvp",
        root_ + "/mlink/../m/t.vvp", "m/same_folder_link.vvp"})
    EXPECT_EQ(vvi::model_path(typed).built(), built) << typed;
}

// The model's folder decides what it includes and reads: a link from
// another folder makes that folder the model's, so it is a model of its own.
TEST_F(ModelPath, ALinkInAnotherFolderIsAModelOfThatFolder) {
  EXPECT_EQ(vvi::model_path("other/t.vvp").built(), root_ + "/other/t.vvp");
}

TEST_F(ModelPath, AMissingFileKeepsItsTypedName) {
  EXPECT_EQ(vvi::model_path("m/missing.vvp").built(), "m/missing.vvp");
  EXPECT_EQ(vvi::model_path("m").built(), "m");
}

TEST_F(ModelPath, MessagesNameFilesAsTyped) {
  vvi::model_path p("./mlink/t.vvp");
  EXPECT_EQ(p.shown(root_ + "/m/t.vvp"), "./mlink/t.vvp");
  EXPECT_EQ(p.shown(root_ + "/m/lib.vvp"), "./mlink/lib.vvp");        // included beside it
  EXPECT_EQ(p.shown(root_ + "/m/../shared.vvp"), "./mlink/../shared.vvp");
  EXPECT_EQ(p.shown("/usr/include/x.hpp"), "/usr/include/x.hpp");
  EXPECT_EQ(p.shown_in(root_ + "/m/t.vvp: In function 'f':\n" + root_ + "/m/t.vvp:1:3: warning: w\n  start {}\n"),
            "./mlink/t.vvp: In function 'f':\n./mlink/t.vvp:1:3: warning: w\n  start {}\n");
  fs::current_path(root_ + "/m");
  EXPECT_EQ(vvi::model_path("t.vvp").shown(root_ + "/m/lib.vvp"), "lib.vvp");
}

// ---------------------------------------------------------------------------
// The model cache
// ---------------------------------------------------------------------------

TEST(ModelCacheIds, AreRandomNotProcessIds) {
  std::set<std::string> ids;
  for (int i = 0; i < 100; ++i) ids.insert(vvi::cache::unique_id());
  EXPECT_EQ(ids.size(), 100u);
  EXPECT_EQ(ids.begin()->size(), 32u);
}

TEST(ModelCacheManifest, FindsTruncatedChangedAndMissingFiles) {
  std::string dir = fresh_dir("manifest");
  write(dir + "/model.so", std::string(5000, 'x'));
  write(dir + "/big.gch", std::string(7000, 'y'));
  ASSERT_TRUE(vvi::cache::write_manifest(dir, {{"model.so", vvi::cache::check::content},
                                               {"big.gch", vvi::cache::check::size}}));
  std::string why;
  EXPECT_EQ(vvi::cache::verify(dir, why), vvi::cache::verdict::good) << why;

  fs::resize_file(dir + "/model.so", 4096);
  EXPECT_EQ(vvi::cache::verify(dir, why), vvi::cache::verdict::damaged);
  EXPECT_EQ(why, "model.so has 4096 bytes, 5000 expected");

  write(dir + "/model.so", std::string(4999, 'x') + "z");  // the same size, other bytes
  EXPECT_EQ(vvi::cache::verify(dir, why), vvi::cache::verdict::damaged);
  EXPECT_EQ(why, "model.so differs from what was built");

  write(dir + "/model.so", std::string(5000, 'x'));
  write(dir + "/big.gch", std::string(7000, 'z'));  // only its size is checked
  EXPECT_EQ(vvi::cache::verify(dir, why), vvi::cache::verdict::good) << why;
  fs::remove(dir + "/big.gch");
  EXPECT_EQ(vvi::cache::verify(dir, why), vvi::cache::verdict::damaged);
  EXPECT_EQ(why, "big.gch is missing");

  fs::remove(dir + "/manifest");
  EXPECT_EQ(vvi::cache::verify(dir, why), vvi::cache::verdict::unlisted);
}

void age(const std::string& path, long seconds) {
  struct timeval times[2];
  times[0].tv_sec = times[1].tv_sec = std::time(nullptr) - seconds;
  times[0].tv_usec = times[1].tv_usec = 0;
  ASSERT_EQ(lutimes(path.c_str(), times), 0) << path;
}

TEST(ModelCacheLeftovers, OldOnesGoAndEverythingInUseStays) {
  std::string dir = fresh_dir("leftovers");
  const long old = 2 * 3600, young = 60;
  auto folder = [&](const std::string& name, long seconds) {
    fs::create_directories(dir + "/" + name);
    age(dir + "/" + name, seconds);
  };
  folder("tmp-k1-dead", old);           // a build that was killed
  folder("tmp-k1-running", young);      // a build in progress elsewhere
  folder("k1.current", old);            // the build k1 names
  folder("k1.replaced", old);           // a build k1 no longer names
  folder("k1.just-replaced", young);    // ... that a process may be about to load
  folder("k2.unnamed", old);            // a build whose key was never published
  folder("k3", old);                    // the layout before manifests
  fs::create_directory_symlink("k1.current", dir + "/k1");
  age(dir + "/k1", old);
  fs::create_directory_symlink("k1.current", dir + "/link-dead");
  age(dir + "/link-dead", old);
  vvi::cache::remove_leftovers(dir);
  std::set<std::string> left;
  for (const auto& e : fs::directory_iterator(dir)) left.insert(e.path().filename().string());
  EXPECT_EQ(left, (std::set<std::string>{"tmp-k1-running", "k1.current", "k1.just-replaced", "k1"}));
}

TEST(ModelCachePublish, SwitchesTheKeyAndReplacesAnOldLayoutFolder) {
  std::string dir = fresh_dir("publish");
  fs::create_directories(dir + "/k/vv/plugin");  // the layout before manifests
  fs::create_directories(dir + "/k.a");
  fs::create_directories(dir + "/k.b");
  vvi::cache::publish(dir, "k", "k.a");
  EXPECT_EQ(fs::read_symlink(dir + "/k"), "k.a");
  vvi::cache::publish(dir, "k", "k.b");
  EXPECT_EQ(fs::read_symlink(dir + "/k"), "k.b");
  EXPECT_TRUE(fs::exists(dir + "/k.a"));  // a process may still load it
  for (const auto& e : fs::directory_iterator(dir))
    EXPECT_NE(e.path().filename().string().rfind("link-", 0), 0u) << "a link left behind";
}

}  // namespace

// ---- declarations' parts shared across folders (compile/shared_declarations) ----

TEST(SharedDeclarations, OnlyTheLineNamesInsideTheModelsFolderAreMarked) {
  const std::string text =
      "#line 1 \"<vvc generated>\"\n"
      "#line 1 \"/w/a/m.vvp\"\n"
      "#line 4 \"/w/a/parts/p.vvp\"\n"
      "#line 9 \"/w/ab/m.vvp\"\n"
      "const char* here = \"/w/a/m.vvp\";\n";
  EXPECT_EQ(vvi::declarations_without_folder(text, "/w/a"),
            "#line 1 \"<vvc generated>\"\n"
            "#line 1 \"/vv-model-folder/m.vvp\"\n"
            "#line 4 \"/vv-model-folder/parts/p.vvp\"\n"
            "#line 9 \"/w/ab/m.vvp\"\n"
            "const char* here = \"/w/a/m.vvp\";\n");
  EXPECT_EQ(vvi::in_model_folder("/vv-model-folder/parts/p.vvp", "/w/b"), "/w/b/parts/p.vvp");
  EXPECT_EQ(vvi::in_model_folder("/w/a/m.vvp", "/w/b"), "/w/a/m.vvp");
  EXPECT_EQ(vvi::in_model_folder("/vv-model-folder/m.vvp", ""), "/vv-model-folder/m.vvp");
  EXPECT_EQ(vvi::with_model_folder("/vv-model-folder/m.vvp:2: at: /vv-model-folder/p.vvp:3: made: raised", "/w/b"),
            "/w/b/m.vvp:2: at: /w/b/p.vvp:3: made: raised");
}

TEST(SharedDeclarations, ABuildsModelFolderIsThatOfTheFirstVvpItsSourceNames) {
  namespace fs = std::filesystem;
  const std::string build = test_files::scratch_dir() + "shared_declarations_build";
  fs::remove_all(build);
  fs::create_directories(build);
  std::ofstream(build + "/model.cpp") << "#line 1 \"<vvc generated>\"\n#include <x.hpp>\n"
                                         "#line 1 \"/w/a/m.vvp\"\n#line 4 \"/w/a/parts/p.vvp\"\n";
  EXPECT_EQ(vvi::model_folder_of_build(build + "/model.so"), "/w/a");
  EXPECT_EQ(vvi::model_folder_of_build(build + "/missing/model.so"), "");
}

TEST(SharedDeclarations, AHeaderTheDeclarationsCouldFindInTheFolderMakesThePartTheFolders) {
  namespace fs = std::filesystem;
  const std::string dir = test_files::scratch_dir() + "shared_declarations";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string text = "#include <cstdio>\n  #  include \"shapes.hpp\"\nvertex_props {};\n";
  EXPECT_FALSE(vvi::declarations_may_read_folder(text, dir));
  std::ofstream(dir + "/cstdio") << "";
  EXPECT_TRUE(vvi::declarations_may_read_folder(text, dir));
  fs::remove(dir + "/cstdio");
  std::ofstream(dir + "/shapes.hpp") << "";
  EXPECT_TRUE(vvi::declarations_may_read_folder(text, dir));
  fs::remove(dir + "/shapes.hpp");
  // vvlib's own headers are looked for in the model's folder first too.
  fs::create_directories(dir + "/util");
  EXPECT_TRUE(vvi::declarations_may_read_folder(text, dir));
}

// ---- when a new model's declarations' part is made (build_cores, build_history) ----

// A build may run as many compilers as its process has cores that are
// idle: never more than its CPU affinity allows (a Slurm allocation of one
// CPU compiles a new model whole) nor than VV_BUILD_CORES, never fewer
// than one.
TEST(BuildCores, NoMoreThanTheProcessMayUseOrTheLimitAndAtLeastOne) {
  cpu_set_t all;
  ASSERT_EQ(sched_getaffinity(0, sizeof all, &all), 0);
  unsigned usable = static_cast<unsigned>(CPU_COUNT(&all));
  unsigned idle = vvi::idle_cores_for_a_build(0);
  EXPECT_GE(idle, 1u);
  EXPECT_LE(idle, usable);
  EXPECT_EQ(vvi::idle_cores_for_a_build(1), 1u);
  cpu_set_t one;
  CPU_ZERO(&one);
  for (int c = 0; c < CPU_SETSIZE; ++c)
    if (CPU_ISSET(c, &all)) {
      CPU_SET(c, &one);
      break;
    }
  ASSERT_EQ(sched_setaffinity(0, sizeof one, &one), 0);
  unsigned on_one = vvi::idle_cores_for_a_build(0);
  ASSERT_EQ(sched_setaffinity(0, sizeof all, &all), 0);
  EXPECT_EQ(on_one, 1u);
}

// The cache remembers a file by its identity alone: a file is new until a
// build of it has been attempted.
TEST(BuildHistory, AFileIsNewUntilItHasBeenCompiled) {
  std::string cache = fresh_dir("build_history");
  EXPECT_FALSE(vvi::compiled_before(cache, "0123abcd"));
  vvi::remember_compiled(cache, "0123abcd");
  EXPECT_TRUE(vvi::compiled_before(cache, "0123abcd"));
  EXPECT_FALSE(vvi::compiled_before(cache, "0123abce"));
  vvi::remember_compiled(cache, "0123abcd");  // again: still the one mark
  EXPECT_TRUE(vvi::compiled_before(cache, "0123abcd"));
}
