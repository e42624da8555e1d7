// `vvinterpreter --batch --export FILE.vtp`: the model writes the file
// (its properties are known only inside it), read back by VTK itself
// (python3-vtk9, tests/unit/read_vtk.py): the icosahedron with properties
// set from the positions; the union of two meshes with and without
// --max-face; a path that cannot be written; the viewer's `export` script
// command.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "run_interpreter.hpp"
#include "test_files.hpp"
#include "vtk_read_back.hpp"

using test_files::scratch_dir;
using vtk_read_back::read_back;
using vtk_read_back::read_with_vtk;

namespace fs = std::filesystem;

namespace {

std::string test_model(const std::string& name) { return VV_TESTS_DIR "/models/" + name; }

std::string fresh_dir(const std::string& name) {
  std::string dir = scratch_dir() + name;
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir);
  return dir + "/";
}

test_run::result batch(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {"--batch"};
  argv.insert(argv.end(), args.begin(), args.end());
  return test_run::run(test_run::interpreter(argv), 280);
}

void batch_ok(const std::vector<std::string>& args) {
  test_run::result r = batch(args);
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.status, 0) << "stderr: " << r.err << "\nstdout: " << r.out;
}

TEST(VtpExport, ModelPropertiesArePointDataOfTheIcosahedron) {
  const std::string dir = fresh_dir("vtp_properties");
  ASSERT_NO_FATAL_FAILURE(batch_ok({"--export", dir + "ico.vtp", test_model("vtp_properties.vvp")}));
  read_back r = read_with_vtk(dir + "ico.vtp");

  // The icosahedron: 12 points, each with one coordinate 0, one +-1 and
  // one +-phi; 20 triangles, counter-clockwise seen from outside.
  const double phi = (1 + std::sqrt(5.0)) / 2;
  ASSERT_EQ(r.points.size(), 12u);
  for (const auto& p : r.points) {
    std::vector<double> sizes = {std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2])};
    std::sort(sizes.begin(), sizes.end());
    EXPECT_EQ(sizes[0], 0.0);
    EXPECT_EQ(sizes[1], 1.0);
    EXPECT_NEAR(sizes[2], phi, 1e-15);
  }
  EXPECT_EQ(r.cells["verts"].size(), 0u);
  EXPECT_EQ(r.cells["lines"].size(), 0u);
  ASSERT_EQ(r.cells["polys"].size(), 20u);
  for (const auto& f : r.cells["polys"]) {
    ASSERT_EQ(f.size(), 3u);
    const auto &a = r.points[f[0]], &b = r.points[f[1]], &c = r.points[f[2]];
    double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    EXPECT_GT(n[0] * a[0] + n[1] * a[1] + n[2] * a[2], 0);
  }

  // Every numeric and 3-vector property but pos, in declaration order; the
  // string is left out. Each value belongs to its own point.
  ASSERT_EQ(r.arrays.size(), 4u);
  EXPECT_EQ(r.arrays[0].name + " " + r.arrays[0].type, "height double");
  EXPECT_EQ(r.arrays[1].name + " " + r.arrays[1].type, "sign int");
  EXPECT_EQ(r.arrays[2].name + " " + r.arrays[2].type, "upper unsigned_char");
  EXPECT_EQ(r.arrays[3].name + " " + r.arrays[3].type + " " + std::to_string(r.arrays[3].components),
            "normal double 3");
  for (const auto& a : r.arrays) ASSERT_EQ(a.values.size(), 12u) << a.name;
  for (std::size_t i = 0; i < 12; ++i) {
    const auto& p = r.points[i];
    EXPECT_EQ(r.arrays[0].values[i], std::vector<double>{p[2]});
    EXPECT_EQ(r.arrays[1].values[i], std::vector<double>{p[0] > 0 ? 1.0 : p[0] < 0 ? -1.0 : 0.0});
    EXPECT_EQ(r.arrays[2].values[i], std::vector<double>{p[1] > 0 ? 1.0 : 0.0});
    double radius = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    ASSERT_EQ(r.arrays[3].values[i].size(), 3u);
    for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(r.arrays[3].values[i][k], p[k] / radius) << i;
  }
}

// two_meshes.vvp: Fan, an open hexagonal fan (7 vertices, six triangles
// and a boundary orbit of six) and Pyramid, the double pyramid (6
// vertices, 8 triangles).
TEST(VtpExport, UnionOfTwoMeshesKeepsMaxFace) {
  const std::string dir = fresh_dir("vtp_union");
  ASSERT_NO_FATAL_FAILURE(
      batch_ok({"--mesh", "Fan,Pyramid", "--export", dir + "all.vtp", test_model("two_meshes.vvp")}));
  ASSERT_NO_FATAL_FAILURE(batch_ok({"--mesh", "Fan,Pyramid", "--max-face", "3", "--export", dir + "tri.vtp",
                                    test_model("two_meshes.vvp")}));
  read_back all = read_with_vtk(dir + "all.vtp"), tri = read_with_vtk(dir + "tri.vtp");
  EXPECT_EQ(all.points.size(), 13u);
  EXPECT_EQ(tri.points.size(), 13u);
  std::vector<std::size_t> sizes;
  for (const auto& f : all.cells["polys"]) sizes.push_back(f.size());
  std::sort(sizes.begin(), sizes.end());
  std::vector<std::size_t> expected(14, 3u);
  expected.push_back(6);
  EXPECT_EQ(sizes, expected);  // control: the boundary orbit is there
  sizes.clear();
  for (const auto& f : tri.cells["polys"]) sizes.push_back(f.size());
  EXPECT_EQ(sizes, std::vector<std::size_t>(14, 3u));
  EXPECT_EQ(tri.cells["verts"].size(), 0u);
}

TEST(VtpExport, IntoAMissingFolderFailsNamingItAndLeavesNothing) {
  const std::string dir = fresh_dir("vtp_missing_folder");
  test_run::result r = batch({"--export", dir + "no_such_folder/ico.vtp", test_model("vtp_properties.vvp")});
  EXPECT_NE(r.status, 0);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(dir + "no_such_folder/ico.vtp"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(VtpExport, ViewerScriptExportCommandWritesVtp) {
  const std::string dir = fresh_dir("vtp_viewer");
  {
    std::ofstream script(dir + "s.txt");
    script << "export S " << dir << "ico.vtp\nquit\n";
  }
  test_run::result r = test_run::run(
      test_run::in_virtual_display(test_run::interpreter({"--script", dir + "s.txt", test_model("vtp_properties.vvp")})),
      280);
  ASSERT_FALSE(r.timed_out);
  ASSERT_EQ(r.status, 0) << "stderr: " << r.err << "\nstdout: " << r.out;
  EXPECT_NE(r.out.find("wrote " + dir + "ico.vtp"), std::string::npos) << r.out;
  read_back back = read_with_vtk(dir + "ico.vtp");
  EXPECT_EQ(back.points.size(), 12u);
  EXPECT_EQ(back.cells["polys"].size(), 20u);
  std::vector<std::string> names;
  for (const auto& a : back.arrays) names.push_back(a.name);
  EXPECT_EQ(names, (std::vector<std::string>{"height", "sign", "upper", "normal"}));
}

}  // namespace
