// vvinterpreter in batch mode, run as users and test suites run it
// (DESIGN.md "Command-line contracts", `vvinterpreter --help`):
//   1. exports of examples/loop.vvp in every format, read back with vvlib
//      and OpenMesh; determinism; --mesh; --max-face
//   2. offscreen screenshots
//   3. --seed
//   4. error paths: one line on stderr naming the .vvp file and line;
//      usage errors
//   5. --compile-only, the model cache, loading a plugin directly
//   6. --version and --help
// Every test works in its own scratch folder; the test models are in
// tests/interpreter/models.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <vv/vv.hpp>
#include <vv/io/mesh_io.hpp>
#include <model/abi.hpp>

#include <util/point.hpp>

#include <stb/stb_image.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run_interpreter.hpp"
#include "test_files.hpp"

using test_files::scratch_dir;
using test_files::slurp;

namespace fs = std::filesystem;

namespace {

// ---------------------------------------------------------------------------
// Paths and running the interpreter
// ---------------------------------------------------------------------------

const std::string loop_vvp = VV_SOURCE_DIR "/examples/loop.vvp";
const std::string pyramid_vvm = VV_SOURCE_DIR "/models/pyramid.vvm";

std::string test_model(const std::string& name) { return VV_TESTS_DIR "/models/" + name; }

//! A fresh, empty folder for one test (with a trailing slash).
std::string fresh_dir(const std::string& name) {
  std::string dir = scratch_dir() + name;
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir);
  return dir + "/";
}

//! vvinterpreter with the test suite's model cache and these arguments. The
//! first run of the suite also builds the precompiled vvlib header.
test_run::result vvi(const std::vector<std::string>& args) {
  return test_run::run(test_run::interpreter(args), 280);
}

//! vvinterpreter --batch ARGS..., expecting success.
void batch_ok(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {"--batch"};
  argv.insert(argv.end(), args.begin(), args.end());
  test_run::result r = vvi(argv);
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.status, 0) << "stderr: " << r.err << "\nstdout: " << r.out;
}

//! Runs loop.vvp for `steps` steps and exports to `path`.
void export_loop(unsigned steps, const std::string& path) {
  batch_ok({"--steps", std::to_string(steps), "--export", path, loop_vvp});
}

// "exactly one line": the whole text is one line ending in a newline.
testing::AssertionResult is_one_line(const std::string& text) {
  if (text.empty()) return testing::AssertionFailure() << "nothing on stderr";
  std::size_t newlines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
  if (newlines != 1 || text.back() != '\n')
    return testing::AssertionFailure() << "expected exactly one line, got " << newlines
                                       << " newline(s):\n" << text;
  return testing::AssertionSuccess();
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

//! The files (names) in a folder.
std::vector<std::string> files_in(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

void spit(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  ASSERT_TRUE(out.good()) << "cannot write " << path;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "\"" << from << "\" is not in the text";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

//! A copy of examples/loop.vvp in `dir` reading the pyramid by its
//! absolute path (so the copy works from any folder).
std::string loop_copy(const std::string& dir, const std::string& name = "loop_copy.vvp") {
  std::string text = replaced(slurp(loop_vvp), "\"../models/pyramid.vvm\"", "\"" + pyramid_vvm + "\"");
  spit(dir + name, text);
  return dir + name;
}

// ---------------------------------------------------------------------------
// Reading exported meshes back
// ---------------------------------------------------------------------------

using Pt = util::Point<double>;
using Key = std::array<double, 3>;

struct VP {
  Pt pos;
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos);
  }
};
using G = vv::graph<VP>;

struct read_back {
  std::vector<Key> positions;                // in file order
  std::vector<std::size_t> face_sizes;       // one per face (orbit)
  std::size_t triangles() const {
    return static_cast<std::size_t>(std::count(face_sizes.begin(), face_sizes.end(), 3u));
  }
};

//! Any format, through vvlib (vv::read_mesh): vertices and face orbits.
read_back read_with_vvlib(const std::string& path) {
  G::context ctx;
  G::mesh M(ctx);
  vv::read_mesh(M, path);
  read_back r;
  for (G::vertex v : M) r.positions.push_back({v->pos.x(), v->pos.y(), v->pos.z()});
  for (const auto& f : vv::face_orbits(M)) r.face_sizes.push_back(f.size());
  return r;
}

// OpenMesh with double coordinates, so that nothing is lost on our side.
struct DoubleTraits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
using OMesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;

read_back read_with_openmesh(const std::string& path) {
  OMesh mesh;
  read_back r;
  EXPECT_TRUE(OpenMesh::IO::read_mesh(mesh, path)) << "OpenMesh cannot read " << path;
  for (auto vh : mesh.vertices()) {
    const auto& p = mesh.point(vh);
    r.positions.push_back({p[0], p[1], p[2]});
  }
  for (auto fh : mesh.faces()) r.face_sizes.push_back(mesh.valence(fh));
  return r;
}

// A double rounded to float (volatile: GCC 12 at -O2 may drop the rounding
// of double(float(x)) pairs otherwise).
double through_float(double d) {
  volatile float f = static_cast<float>(d);
  return static_cast<double>(f);
}
std::vector<Key> rounded_to_float(std::vector<Key> ps) {
  for (Key& k : ps)
    for (double& c : k) c = through_float(c);
  return ps;
}
std::vector<Key> sorted(std::vector<Key> ps) {
  std::sort(ps.begin(), ps.end());
  return ps;
}

//! The face sizes of an OBJ file ("f" lines), read directly.
std::vector<std::size_t> obj_face_sizes(const std::string& path) {
  std::vector<std::size_t> sizes;
  std::istringstream in(slurp(path));
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag != "f") continue;
    std::size_t n = 0;
    for (std::string w; words >> w;) ++n;
    sizes.push_back(n);
  }
  return sizes;
}

// ---------------------------------------------------------------------------
// PNG images
// ---------------------------------------------------------------------------

struct image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;  // 3 bytes a pixel, rows top to bottom
  std::array<int, 3> at(int x, int y) const {
    std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x));
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

image load_png(const std::string& path) {
  image img;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &img.width, &img.height, &channels, 3);
  EXPECT_NE(data, nullptr) << "stb_image cannot read " << path << ": " << stbi_failure_reason();
  if (!data) return img;
  img.rgb.assign(data, data + 3 * img.width * img.height);
  stbi_image_free(data);
  return img;
}

int colour_distance(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
}

// ===========================================================================
// 1. Exports of examples/loop.vvp
// ===========================================================================

// Requirement 1: --export .vvm after 0..3 steps of Loop subdivision of the
// double pyramid has 6, 18, 66, 258 vertices and 8, 32, 128, 512 face orbits.
TEST(LoopExport, VvmHasTheVertexAndFaceCountsOfEachStep) {
  const std::string dir = fresh_dir("vvm_counts");
  const std::size_t vertices[] = {6, 18, 66, 258};
  const std::size_t faces[] = {8, 32, 128, 512};
  for (unsigned steps = 0; steps <= 3; ++steps) {
    SCOPED_TRACE("after " + std::to_string(steps) + " steps");
    const std::string path = dir + "loop" + std::to_string(steps) + ".vvm";
    ASSERT_NO_FATAL_FAILURE(export_loop(steps, path));
    G::context ctx;
    G::mesh M(ctx);
    ASSERT_NO_THROW(vv::read_vvm(M, path));
    EXPECT_EQ(M.size(), vertices[steps]);
    auto orbits = vv::face_orbits(M);
    EXPECT_EQ(orbits.size(), faces[steps]);
    for (const auto& f : orbits) EXPECT_EQ(f.size(), 3u);
    EXPECT_EQ(vv::euler_characteristic(M), 2);
  }
}

// Requirement 1: .obj .off .ply .stl after 2 steps, read back with OpenMesh:
// 66 vertices, 128 triangles, the positions of the .vvm export. OpenMesh 9's
// readers round coordinates to float even into a double mesh, so positions
// are compared to float precision here; the vvlib test below checks them
// exactly.
TEST(LoopExport, PolygonFormatsReadBackWithOpenMesh) {
  const std::string dir = fresh_dir("openmesh_read");
  ASSERT_NO_FATAL_FAILURE(export_loop(2, dir + "loop.vvm"));
  const read_back reference = read_with_vvlib(dir + "loop.vvm");
  ASSERT_EQ(reference.positions.size(), 66u);
  for (const std::string ext : {".obj", ".off", ".ply", ".stl"}) {
    SCOPED_TRACE(ext);
    const std::string path = dir + "loop" + ext;
    ASSERT_NO_FATAL_FAILURE(export_loop(2, path));
    const read_back r = read_with_openmesh(path);
    EXPECT_EQ(r.positions.size(), 66u);
    EXPECT_EQ(r.face_sizes.size(), 128u);
    EXPECT_EQ(r.triangles(), 128u);
    if (ext == ".stl")  // vertices merged by the reader, in its own order
      EXPECT_EQ(sorted(rounded_to_float(r.positions)), sorted(rounded_to_float(reference.positions)));
    else
      EXPECT_EQ(rounded_to_float(r.positions), rounded_to_float(reference.positions));
  }
}

// Requirement 1: the same files read back with vvlib's vv::read_mesh: 66
// vertices, 128 triangles, positions exactly those of the .vvm export
// (to float precision for STL, which stores floats).
TEST(LoopExport, PolygonFormatsReadBackWithVvlib) {
  const std::string dir = fresh_dir("vvlib_read");
  ASSERT_NO_FATAL_FAILURE(export_loop(2, dir + "loop.vvm"));
  const read_back reference = read_with_vvlib(dir + "loop.vvm");
  ASSERT_EQ(reference.positions.size(), 66u);
  for (const std::string ext : {".obj", ".off", ".ply", ".stl"}) {
    SCOPED_TRACE(ext);
    const std::string path = dir + "loop" + ext;
    ASSERT_NO_FATAL_FAILURE(export_loop(2, path));
    read_back r;
    ASSERT_NO_THROW(r = read_with_vvlib(path));
    EXPECT_EQ(r.positions.size(), 66u);
    EXPECT_EQ(r.face_sizes.size(), 128u);
    EXPECT_EQ(r.triangles(), 128u);
    if (ext == ".stl")
      EXPECT_EQ(sorted(r.positions), sorted(rounded_to_float(reference.positions)));
    else
      EXPECT_EQ(r.positions, reference.positions);  // exact
  }
}

// Requirement 1 (determinism): a second identical run writes byte-identical
// files, in every format.
TEST(LoopExport, SecondRunWritesByteIdenticalFiles) {
  const std::string dir = fresh_dir("determinism");
  for (const std::string ext : {".vvm", ".obj", ".off", ".ply", ".stl"}) {
    SCOPED_TRACE(ext);
    ASSERT_NO_FATAL_FAILURE(export_loop(2, dir + "first" + ext));
    ASSERT_NO_FATAL_FAILURE(export_loop(2, dir + "second" + ext));
    const std::string first = slurp(dir + "first" + ext), second = slurp(dir + "second" + ext);
    EXPECT_FALSE(first.empty());
    EXPECT_TRUE(first == second) << "the two runs wrote different " << ext << " files";
  }
}

// Requirement 1: --mesh S names loop.vvp's mesh explicitly; the export is the
// default one.
TEST(LoopExport, MeshOptionNamingTheMeshExportsIt) {
  const std::string dir = fresh_dir("mesh_named");
  ASSERT_NO_FATAL_FAILURE(batch_ok({"--steps", "1", "--mesh", "S", "--export", dir + "named.vvm", loop_vvp}));
  ASSERT_NO_FATAL_FAILURE(export_loop(1, dir + "default.vvm"));
  EXPECT_EQ(read_with_vvlib(dir + "named.vvm").positions.size(), 18u);
  EXPECT_EQ(slurp(dir + "named.vvm"), slurp(dir + "default.vvm"));
}

// Requirement 1: --mesh with a name the model does not declare fails with
// one line naming it, and writes nothing.
TEST(LoopExport, MeshOptionWithUnknownNameFailsNamingIt) {
  const std::string dir = fresh_dir("mesh_unknown");
  test_run::result r = vvi({"--batch", "--mesh", "nosuch", "--export", dir + "out.vvm", loop_vvp});
  EXPECT_NE(r.status, 0);
  EXPECT_TRUE(is_one_line(r.err));
  EXPECT_TRUE(contains(r.err, "nosuch")) << r.err;
  EXPECT_TRUE(files_in(dir).empty());
}

// Requirement 1: with two global meshes, the default is the first declared
// and --mesh picks the other (tests/interpreter/models/two_meshes.vvp).
TEST(LoopExport, MeshOptionPicksTheSecondOfTwoMeshes) {
  const std::string dir = fresh_dir("mesh_second");
  ASSERT_NO_FATAL_FAILURE(batch_ok({"--export", dir + "default.obj", test_model("two_meshes.vvp")}));
  ASSERT_NO_FATAL_FAILURE(batch_ok({"--mesh", "Pyramid", "--export", dir + "pyramid.obj", test_model("two_meshes.vvp")}));
  EXPECT_EQ(read_with_vvlib(dir + "default.obj").positions.size(), 7u);  // Fan
  const read_back pyramid = read_with_vvlib(dir + "pyramid.obj");
  EXPECT_EQ(pyramid.positions.size(), 6u);
  EXPECT_EQ(pyramid.triangles(), 8u);
}

// Requirement 1: --max-face 3 leaves out a longer orbit. The open hexagonal
// fan (models/hex_fan.vvm) has six triangles and a boundary orbit of six;
// without the option that orbit is written as a seventh face.
TEST(LoopExport, MaxFaceLeavesOutLongerOrbits) {
  const std::string dir = fresh_dir("max_face");
  ASSERT_NO_FATAL_FAILURE(batch_ok({"--export", dir + "all.obj", test_model("two_meshes.vvp")}));
  ASSERT_NO_FATAL_FAILURE(
      batch_ok({"--max-face", "3", "--export", dir + "triangles.obj", test_model("two_meshes.vvp")}));

  std::vector<std::size_t> all = obj_face_sizes(dir + "all.obj");
  std::sort(all.begin(), all.end());
  EXPECT_EQ(all, (std::vector<std::size_t>{3, 3, 3, 3, 3, 3, 6}));  // control: the orbit exists

  EXPECT_EQ(obj_face_sizes(dir + "triangles.obj"), std::vector<std::size_t>(6, 3u));
  const read_back r = read_with_vvlib(dir + "triangles.obj");
  EXPECT_EQ(r.positions.size(), 7u);  // all vertices are kept
  EXPECT_EQ(r.triangles(), 6u);
}

// ===========================================================================
// 2. Offscreen screenshots
// ===========================================================================

// Requirement 2: the pyramid at 0 steps, --size 320x240: exactly that size,
// not blank, the object wholly inside the frame with a background border.
TEST(Screenshot, PyramidFitsInsideA320x240Frame) {
  const std::string dir = fresh_dir("screenshot");
  ASSERT_NO_FATAL_FAILURE(batch_ok({"--screenshot", dir + "pyramid.png", "--size", "320x240", loop_vvp}));
  const image img = load_png(dir + "pyramid.png");
  ASSERT_EQ(img.width, 320);
  ASSERT_EQ(img.height, 240);

  // The background is the corner's colour; every border pixel has it.
  const std::array<int, 3> background = img.at(0, 0);
  const int same = 12, different = 60;  // summed over the three channels
  int border_off = 0;
  for (int x = 0; x < img.width; ++x)
    for (int y : {0, img.height - 1}) border_off += colour_distance(img.at(x, y), background) > same;
  for (int y = 0; y < img.height; ++y)
    for (int x : {0, img.width - 1}) border_off += colour_distance(img.at(x, y), background) > same;
  EXPECT_EQ(border_off, 0) << "border pixels that are not background";

  // Not blank: a clearly different colour covers a fair part of the frame.
  int minx = img.width, maxx = -1, miny = img.height, maxy = -1, object_pixels = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (colour_distance(img.at(x, y), background) > different) {
        ++object_pixels;
        minx = std::min(minx, x), maxx = std::max(maxx, x);
        miny = std::min(miny, y), maxy = std::max(maxy, y);
      }
  ASSERT_GT(object_pixels, img.width * img.height / 20) << "the image is (nearly) blank";

  // Well inside: at least 5% of the frame free on every side, and the
  // object is not a speck.
  EXPECT_GE(minx, img.width / 20);
  EXPECT_LE(maxx, img.width - 1 - img.width / 20);
  EXPECT_GE(miny, img.height / 20);
  EXPECT_LE(maxy, img.height - 1 - img.height / 20);
  EXPECT_GE(maxx - minx, img.width / 5);
  EXPECT_GE(maxy - miny, img.height / 5);
}

// Requirement 2 (determinism): a second run gives an identical PNG file.
TEST(Screenshot, SecondRunGivesIdenticalPng) {
  const std::string dir = fresh_dir("screenshot_twice");
  for (const char* name : {"first.png", "second.png"})
    ASSERT_NO_FATAL_FAILURE(batch_ok({"--screenshot", dir + name, "--size", "320x240", loop_vvp}));
  const std::string first = slurp(dir + "first.png"), second = slurp(dir + "second.png");
  EXPECT_FALSE(first.empty());
  EXPECT_TRUE(first == second) << "the two screenshots differ";
}

// Requirement: the screenshot uses the model's render and render_screen
// blocks (legacy GL, as vv 1.1 programs draw) when it has them.
TEST(Screenshot, RenderBlocksDrawTheModel) {
  const std::string dir = fresh_dir("render_block");
  ASSERT_NO_FATAL_FAILURE(batch_ok({"--screenshot", dir + "shot.png", "--size", "200x150",
                                    test_model("render_block.vvp")}));
  image img = load_png(dir + "shot.png");
  ASSERT_EQ(img.width, 200);
  ASSERT_EQ(img.height, 150);
  std::size_t red = 0, blue_in_corner = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      std::array<int, 3> c = img.at(x, y);
      if (c[0] > 200 && c[1] < 60 && c[2] < 60) ++red;
      // render_screen's square: pixels 20..60 from the bottom-left corner.
      bool in_square = x >= 22 && x < 58 && y >= img.height - 58 && y < img.height - 22;
      if (in_square && c[2] > 200 && c[0] < 60 && c[1] < 60) ++blue_in_corner;
    }
  EXPECT_GT(red, 500u) << "the render block's red triangles are missing";
  EXPECT_EQ(blue_in_corner, 36u * 36u) << "render_screen's square is missing or misplaced";
}

// ===========================================================================
// 3. --seed
// ===========================================================================

// Exports a random model after 3 steps with a seed ("" = no --seed option).
std::string random_run(const std::string& model, const std::string& dir, const std::string& seed,
                       const std::string& name) {
  std::vector<std::string> args = {"--steps", "3", "--export", dir + name};
  if (!seed.empty()) args.insert(args.end(), {"--seed", seed});
  args.push_back(test_model(model));
  batch_ok(args);
  return fs::exists(dir + name) ? slurp(dir + name) : std::string();
}

// Requirement 3: a model drawing from the host-seeded generator (vv_random(),
// which vvc gives every program): the same seed gives identical output.
TEST(Seed, SameSeedGivesIdenticalOutput) {
  const std::string dir = fresh_dir("seed_same");
  const std::string a = random_run("random_walk.vvp", dir, "7", "a.vvm");
  const std::string b = random_run("random_walk.vvp", dir, "7", "b.vvm");
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(a, b);
  EXPECT_NE(read_with_vvlib(dir + "a.vvm").positions, read_with_vvlib(pyramid_vvm).positions)
      << "the model did not move its vertices";
}

// Requirement 3: different seeds give different output; no --seed is seed 0.
TEST(Seed, DifferentSeedsGiveDifferentOutput) {
  const std::string dir = fresh_dir("seed_different");
  const std::string one = random_run("random_walk.vvp", dir, "1", "one.vvm");
  const std::string two = random_run("random_walk.vvp", dir, "2", "two.vvm");
  const std::string zero = random_run("random_walk.vvp", dir, "0", "zero.vvm");
  const std::string none = random_run("random_walk.vvp", dir, "", "none.vvm");
  ASSERT_FALSE(one.empty());
  EXPECT_NE(one, two);
  EXPECT_NE(one, zero);
  EXPECT_EQ(zero, none) << "--help says the default seed is 0";
}

// Requirement 3: vv 1.1 programs draw from std::rand and drand48, which the
// host seeds too: same seed, same output; different seeds, different output.
TEST(Seed, CLibraryGeneratorsFollowTheSeed) {
  const std::string dir = fresh_dir("seed_c_library");
  const std::string a = random_run("c_random.vvp", dir, "5", "a.vvm");
  const std::string b = random_run("c_random.vvp", dir, "5", "b.vvm");
  const std::string c = random_run("c_random.vvp", dir, "6", "c.vvm");
  ASSERT_FALSE(a.empty());
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
}

// ===========================================================================
// 4. Error paths: non-zero exit, one line on stderr naming file and line
// ===========================================================================

// Requirement 4: a syntax error is reported as file:line:col (line 9,
// column 25 of models/syntax_error.vvp), on one line.
TEST(Errors, SyntaxErrorNamesLineAndColumn) {
  test_run::result r = vvi({"--batch", test_model("syntax_error.vvp")});
  EXPECT_NE(r.status, 0);
  EXPECT_TRUE(is_one_line(r.err));
  EXPECT_TRUE(contains(r.err, "syntax_error.vvp:9:25: error:")) << r.err;
}

// Requirement 4: a model that translates but fails to compile (a C++ type
// error on line 11 of models/type_mismatch.vvp): one line naming that .vvp
// line, not generated code or vvlib.
TEST(Errors, CompileErrorNamesTheVvpLine) {
  test_run::result r = vvi({"--batch", test_model("type_mismatch.vvp")});
  EXPECT_NE(r.status, 0);
  EXPECT_TRUE(is_one_line(r.err));
  EXPECT_TRUE(contains(r.err, "type_mismatch.vvp:11:")) << r.err;
  EXPECT_TRUE(contains(r.err, "error")) << r.err;
  EXPECT_FALSE(contains(r.err, "vvc generated")) << r.err;
  EXPECT_FALSE(contains(r.err, "model.cpp")) << r.err;
  // No vvlib header (whatever the checkout's own path is called).
  EXPECT_FALSE(contains(r.err, "/vvlib/")) << r.err;
  EXPECT_FALSE(contains(r.err, ".hpp")) << r.err;
}

// Requirement 4: the same compile error in a model whose file name contains
// the word "error" (models/compile_error.vvp): still the .vvp line.
TEST(Errors, CompileErrorNamesTheVvpLineWhateverTheFileName) {
  test_run::result r = vvi({"--batch", test_model("compile_error.vvp")});
  EXPECT_NE(r.status, 0);
  EXPECT_TRUE(is_one_line(r.err));
  EXPECT_TRUE(contains(r.err, "compile_error.vvp:11:")) << r.err;
}

// Requirement 4: a run-time algebra error in step 2 (models/step2_error.vvp,
// line 20: make with a duplicate) names the .vvp line and step 2; step 1
// alone succeeds.
TEST(Errors, RunTimeErrorNamesTheLineAndTheStep) {
  const std::string dir = fresh_dir("run_time_error");
  ASSERT_NO_FATAL_FAILURE(batch_ok({"--steps", "1", test_model("step2_error.vvp")}));
  test_run::result r = vvi({"--batch", "--steps", "3", "--export", dir + "out.vvm", test_model("step2_error.vvp")});
  EXPECT_NE(r.status, 0);
  EXPECT_TRUE(is_one_line(r.err));
  EXPECT_TRUE(contains(r.err, "step2_error.vvp:20")) << r.err;
  EXPECT_TRUE(contains(r.err, "step 2")) << r.err;
  EXPECT_TRUE(files_in(dir).empty()) << "nothing is exported after a failed step";
}

// Requirement 4: start reads a .vvm file that does not exist
// (models/missing_input.vvp, line 8): the message names that line and the
// missing file.
TEST(Errors, MissingInputFileNamesTheReadLineAndTheFile) {
  test_run::result r = vvi({"--batch", test_model("missing_input.vvp")});
  EXPECT_NE(r.status, 0);
  EXPECT_TRUE(is_one_line(r.err));
  EXPECT_TRUE(contains(r.err, "missing_input.vvp:8")) << r.err;
  EXPECT_TRUE(contains(r.err, "no_such_input.vvm")) << r.err;
}

// Requirement 4: a model file that does not exist.
TEST(Errors, MissingModelFileIsNamed) {
  const std::string missing = fresh_dir("missing_model") + "no_such_model.vvp";
  test_run::result r = vvi({"--batch", missing});
  EXPECT_NE(r.status, 0);
  EXPECT_TRUE(is_one_line(r.err));
  EXPECT_TRUE(contains(r.err, missing)) << r.err;
}

// Requirement 4: --export to an unknown extension fails naming the file,
// and writes nothing.
TEST(Errors, ExportToUnknownExtensionFails) {
  const std::string dir = fresh_dir("unknown_extension");
  test_run::result r = vvi({"--batch", "--export", dir + "out.xyz", loop_vvp});
  EXPECT_NE(r.status, 0);
  EXPECT_TRUE(is_one_line(r.err));
  EXPECT_TRUE(contains(r.err, "out.xyz")) << r.err;
  EXPECT_TRUE(files_in(dir).empty());
}

// Requirement 4: --export into a folder that does not exist fails naming
// the file; the folder is not created and nothing half-written is left.
TEST(Errors, ExportIntoMissingFolderFailsAndLeavesNothing) {
  const std::string dir = fresh_dir("missing_folder");
  for (const std::string ext : {".vvm", ".obj", ".stl"}) {
    SCOPED_TRACE(ext);
    const std::string target = dir + "no_such_folder/out" + ext;
    test_run::result r = vvi({"--batch", "--export", target, loop_vvp});
    EXPECT_NE(r.status, 0);
    EXPECT_TRUE(is_one_line(r.err));
    EXPECT_TRUE(contains(r.err, "no_such_folder")) << r.err;
    EXPECT_TRUE(files_in(dir).empty());
  }
}

// Requirement 4: usage errors exit with status 2 and print the usage text.
TEST(Usage, UnknownOptionExitsTwoWithUsage) {
  test_run::result r = vvi({"--batch", "--no-such-option", loop_vvp});
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "--no-such-option")) << r.err;
  EXPECT_TRUE(contains(r.err, "usage: vvinterpreter")) << r.err;
}

TEST(Usage, ZeroSizeExitsTwoWithUsage) {
  const std::string dir = fresh_dir("zero_size");
  test_run::result r = vvi({"--batch", "--screenshot", dir + "x.png", "--size", "0x5", loop_vvp});
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "--size")) << r.err;
  EXPECT_TRUE(contains(r.err, "usage: vvinterpreter")) << r.err;
  EXPECT_TRUE(files_in(dir).empty());
}

TEST(Usage, NoModelExitsTwoWithUsage) {
  test_run::result r = vvi({"--batch", "--steps", "1"});
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(contains(r.err, "usage: vvinterpreter")) << r.err;
}

// ===========================================================================
// 5. --compile-only, the model cache, plugins
// ===========================================================================

//! The plugin path --compile-only prints (its last line of output).
std::string last_line(const std::string& out) {
  std::string s = out;
  while (!s.empty() && s.back() == '\n') s.pop_back();
  std::size_t nl = s.rfind('\n');
  return nl == std::string::npos ? s : s.substr(nl + 1);
}

const std::string cache_line = "compiled model found in the cache";

// Requirement 5: --compile-only prints the plugin's path and exits 0; again,
// it says the model came from the cache and builds nothing (the plugin file
// is the same, untouched).
TEST(CompileOnly, PrintsPluginPathThenFindsItInTheCache) {
  test_run::result first = vvi({"--compile-only", loop_vvp});
  ASSERT_EQ(first.status, 0) << first.err;
  const std::string plugin = last_line(first.out);
  EXPECT_EQ(fs::path(plugin).extension(), ".so") << first.out;
  EXPECT_TRUE(fs::is_regular_file(plugin)) << plugin;

  const auto built_at = fs::last_write_time(plugin);
  test_run::result again = vvi({"--compile-only", loop_vvp});
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_TRUE(contains(again.out, cache_line)) << again.out;
  EXPECT_FALSE(contains(again.out, "compiled in")) << again.out;
  EXPECT_EQ(last_line(again.out), plugin);
  EXPECT_TRUE(fs::last_write_time(plugin) == built_at) << "a cached model was compiled again";
}

// Requirement 5: the plugin of examples/loop.vvp, loaded directly, runs
// (its input, ../models/pyramid.vvm, is relative to the .vvp's folder).
TEST(CompileOnly, PluginLoadsDirectly) {
  const std::string dir = fresh_dir("plugin_direct");
  test_run::result c = vvi({"--compile-only", loop_vvp});
  ASSERT_EQ(c.status, 0) << c.err;
  const std::string plugin = last_line(c.out);
  ASSERT_NO_FATAL_FAILURE(batch_ok({"--steps", "1", "--export", dir + "direct.vvm", plugin}));
  ASSERT_NO_FATAL_FAILURE(export_loop(1, dir + "from_vvp.vvm"));
  EXPECT_EQ(read_with_vvlib(dir + "direct.vvm").positions.size(), 18u);
  EXPECT_EQ(slurp(dir + "direct.vvm"), slurp(dir + "from_vvp.vvm"));
}

// Requirement 5: the same with a model whose input path is absolute (so the
// plugin does not depend on where it is loaded from).
TEST(CompileOnly, PluginWithAbsoluteInputPathLoadsDirectly) {
  const std::string dir = fresh_dir("plugin_direct_absolute");
  const std::string model = loop_copy(dir);
  test_run::result c = vvi({"--compile-only", model});
  ASSERT_EQ(c.status, 0) << c.err;
  const std::string plugin = last_line(c.out);
  ASSERT_NO_FATAL_FAILURE(batch_ok({"--steps", "1", "--export", dir + "direct.vvm", plugin}));
  const read_back r = read_with_vvlib(dir + "direct.vvm");
  EXPECT_EQ(r.positions.size(), 18u);
  EXPECT_EQ(r.triangles(), 32u);
}

// Requirement 5: a shared library that is not a vv model fails with one line
// naming the missing entry point.
TEST(CompileOnly, SharedLibraryThatIsNotAModelNamesTheMissingEntryPoint) {
  const std::string dir = fresh_dir("not_a_model");
  const std::string so = dir + "libpugixml.so";
  fs::copy_file(VV_PUGIXML_LIBRARY, so);
  test_run::result r = vvi({"--batch", so});
  EXPECT_NE(r.status, 0);
  EXPECT_TRUE(is_one_line(r.err));
  EXPECT_TRUE(contains(r.err, "vv_plugin_")) << r.err;
  EXPECT_TRUE(contains(r.err, "missing")) << r.err;
}

// Requirement 5: the same, given the system's versioned file name
// (libpugixml.so.1) as the brief does.
TEST(CompileOnly, VersionedSharedLibraryNamesTheMissingEntryPoint) {
  // The library's versioned name beside the one CMake links (wherever the
  // system keeps its libraries).
  std::string versioned;
  for (const auto& e : fs::directory_iterator(fs::path(VV_PUGIXML_LIBRARY).parent_path()))
    if (e.path().filename().string().rfind("libpugixml.so.", 0) == 0) versioned = e.path().string();
  ASSERT_FALSE(versioned.empty()) << "no libpugixml.so.N beside " << VV_PUGIXML_LIBRARY;
  test_run::result r = vvi({"--batch", versioned});
  EXPECT_NE(r.status, 0);
  EXPECT_TRUE(is_one_line(r.err));
  EXPECT_TRUE(contains(r.err, "vv_plugin_")) << r.err;
}

// Requirement: a plugin built for another ABI is refused with one line
// naming the file and both versions (not a crash). A plugin from before the
// descriptor exports vv_plugin_abi_version instead.
const std::string this_abi = "this interpreter loads ABI " + std::to_string(VV_PLUGIN_ABI_VERSION);

test_run::result load_built(const std::string& dir, const std::string& source) {
  std::ofstream(dir + "other.cpp") << source;
  test_run::result c = test_run::run({VV_CXX, "-shared", "-fPIC", dir + "other.cpp", "-o", dir + "other.so"});
  EXPECT_EQ(c.status, 0) << c.err;
  return vvi({"--batch", dir + "other.so"});
}

TEST(CompileOnly, PluginOfAnotherAbiIsRefused) {
  const std::string dir = fresh_dir("other_abi");
  test_run::result r = load_built(dir, "extern \"C\" int vv_plugin_abi_version() { return 999; }\n");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(dir + "other.so: error: the model was built for plugin ABI 999, " + this_abi), std::string::npos)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(CompileOnly, PluginOfTheAbiBeforeTheDescriptorIsRefused) {
  const std::string dir = fresh_dir("abi_4");
  test_run::result r = load_built(dir, "extern \"C\" int vv_plugin_abi_version() { return 4; }\n"
                                       "extern \"C\" const char* vv_plugin_start() { return 0; }\n");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(dir + "other.so: error: the model was built for plugin ABI 4, " + this_abi + "; rebuild it"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

// A descriptor of another version: only its first member (the version) is read.
TEST(CompileOnly, DescriptorOfAnotherAbiIsRefused) {
  const std::string dir = fresh_dir("other_descriptor");
  test_run::result r = load_built(dir,
                                  "struct later { int abi_version; void* entries[40]; };\n"
                                  "extern \"C\" const later vv_plugin_descriptor;\n"
                                  "extern \"C\" const later vv_plugin_descriptor = {"
                                  + std::to_string(VV_PLUGIN_ABI_VERSION + 1) + ", {}};\n");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(dir + "other.so: error: the model was built for plugin ABI " +
                       std::to_string(VV_PLUGIN_ABI_VERSION + 1) + ", " + this_abi),
            std::string::npos)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

// A model of ABI 5 (its descriptor held a C++ vv::proxy*) is refused before
// any member past the version is read.
TEST(CompileOnly, DescriptorOfAbi5IsRefusedNamingBothVersions) {
  const std::string dir = fresh_dir("abi_5");
  test_run::result r = load_built(dir,
                                  "struct abi5 { int abi_version; void* entries[20]; };\n"
                                  "extern \"C\" const abi5 vv_plugin_descriptor;\n"
                                  "extern \"C\" const abi5 vv_plugin_descriptor = {5, {}};\n");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(dir + "other.so: error: the model was built for plugin ABI 5, this interpreter loads ABI " +
                       std::to_string(VV_PLUGIN_ABI_VERSION) + "; rebuild it"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

// Requirement 5: editing the .vvp (a scratch copy) rebuilds it (no cache
// line) and changes the output: here every position doubles.
TEST(CompileOnly, EditingTheModelRebuildsItAndChangesTheOutput) {
  const std::string dir = fresh_dir("edit_rebuilds");
  const std::string model = loop_copy(dir, "edited.vvp");
  test_run::result before = vvi({"--compile-only", model});
  ASSERT_EQ(before.status, 0) << before.err;
  ASSERT_NO_FATAL_FAILURE(batch_ok({"--export", dir + "before.vvm", model}));

  spit(model, replaced(slurp(model), "proxy.steps = 4;",
                       "proxy.steps = 4;\n  forall v in S { v$pos = v$pos * 2.0; }"));
  test_run::result after = vvi({"--compile-only", model});
  ASSERT_EQ(after.status, 0) << after.err;
  EXPECT_FALSE(contains(after.out, cache_line)) << after.out;
  EXPECT_TRUE(contains(after.out, "compiled in")) << after.out;
  EXPECT_NE(last_line(after.out), last_line(before.out));
  ASSERT_NO_FATAL_FAILURE(batch_ok({"--export", dir + "after.vvm", model}));

  const read_back old_run = read_with_vvlib(dir + "before.vvm"), new_run = read_with_vvlib(dir + "after.vvm");
  ASSERT_EQ(old_run.positions.size(), 6u);
  ASSERT_EQ(new_run.positions.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i)
    for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(new_run.positions[i][k], 2 * old_run.positions[i][k]) << i;
}

// ===========================================================================
// 6. --version and --help
// ===========================================================================

// Requirement 6: --version exits 0 and names the program.
TEST(CommandLine, VersionExitsZero) {
  test_run::result r = vvi({"--version"});
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out.rfind("vvinterpreter ", 0), 0u) << r.out;
  EXPECT_TRUE(is_one_line(r.out));
  EXPECT_TRUE(r.err.empty()) << r.err;
}

// Requirement 6: --help exits 0 and prints the usage text on stdout.
TEST(CommandLine, HelpExitsZero) {
  test_run::result r = vvi({"--help"});
  EXPECT_EQ(r.status, 0);
  EXPECT_TRUE(contains(r.out, "usage: vvinterpreter")) << r.out;
  EXPECT_TRUE(contains(r.out, "--batch")) << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;
}

}  // namespace
