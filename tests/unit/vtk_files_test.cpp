// VTK files for ParaView (.vtp meshes, .pvd series), read back by VTK
// itself (python3-vtk9, through tests/unit/read_vtk.py): exact points,
// cells and point data of an icosahedron with hand-known properties, a
// curve, a mesh without faces; the series listing its files by step; the
// same bytes from two writes; and failures that name the file and leave
// what was there.
#include <vv/vv.hpp>
#include <vv/io/mesh_io.hpp>
#include <vv/io/vtk_files.hpp>

#include <util/point.hpp>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include "test_files.hpp"
#include "vtk_read_back.hpp"

using test_files::scratch_dir;
using test_files::slurp;
using vtk_read_back::read_back;
using vtk_read_back::read_with_vtk;

// A property type needs text for .vvm files; a program with GLM vectors
// in its properties gives them these.
namespace glm {
std::ostream& operator<<(std::ostream& os, const ivec3& v) { return os << v.x << ' ' << v.y << ' ' << v.z; }
std::istream& operator>>(std::istream& is, ivec3& v) { return is >> v.x >> v.y >> v.z; }
}  // namespace glm

namespace {

using Pt = util::Point<double>;

struct VP {
  Pt pos;
  double height = 0;         // Float64: the z of pos
  int index = 0;             // Int32: the vertex's place in the input list
  unsigned long long big = 0;  // UInt64
  bool upper = false;        // UInt8: y > 0
  float half = 0;            // Float32
  Pt normal;                 // 3 x Float64: pos / |pos|
  glm::ivec3 cell{0, 0, 0};  // 3 x Int32 (a GLM vector)
  util::Point<float> rgb;    // 3 x Float32
  double odd = 0;            // values only binary keeps: nan, inf, -0, subnormal
  std::string name;          // no VTK array: left out
  template <class F>
  void vv_fields(F&& f) {
    f("height", height);
    f("pos", pos);
    f("index", index);
    f("big", big);
    f("upper", upper);
    f("half", half);
    f("normal", normal);
    f("cell", cell);
    f("rgb", rgb);
    f("odd", odd);
    f("name", name);
  }
};
struct NoPos {
  double x = 0;
  template <class F>
  void vv_fields(F&& f) {
    f("x", x);
  }
};
using G = vv::graph<VP>;
using Mesh = G::mesh;

const double phi = (1 + std::sqrt(5.0)) / 2;

// The icosahedron, faces counter-clockwise seen from outside.
const std::vector<std::array<double, 3>> ico_points = {
    {-1, phi, 0}, {1, phi, 0}, {-1, -phi, 0}, {1, -phi, 0}, {0, -1, phi}, {0, 1, phi},
    {0, -1, -phi}, {0, 1, -phi}, {phi, 0, -1}, {phi, 0, 1}, {-phi, 0, -1}, {-phi, 0, 1}};
const std::vector<std::vector<std::size_t>> ico_faces = {
    {0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
    {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
    {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};

const double odd_values[4] = {std::nan(""), -HUGE_VAL, -0.0, 4.9406564584124654e-324};

// The icosahedron with its properties set from each vertex's position and
// input index (the values the read-back is checked against).
void build_icosahedron(Mesh& m) {
  std::vector<std::vector<std::uint32_t>> faces;
  for (const auto& f : ico_faces) faces.emplace_back(f.begin(), f.end());
  vv::build_from_faces(m, ico_points, faces, "icosahedron");
  std::size_t i = 0;
  for (auto v : m) {
    // build_from_faces adds the points in input order.
    const auto& p = ico_points[i];
    EXPECT_EQ(v->pos, Pt(p[0], p[1], p[2]));
    v->height = p[2];
    v->index = -static_cast<int>(i);
    v->big = (1ull << 40) + i;
    v->upper = p[1] > 0;
    v->half = static_cast<float>(i) / 2;
    double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    v->normal = Pt(p[0] / r, p[1] / r, p[2] / r);
    v->cell = glm::ivec3(int(i), -int(i), 7);
    v->rgb = util::Point<float>(0.25f, 0.5f, static_cast<float>(i) / 12);
    v->odd = i < 4 ? odd_values[i] : static_cast<double>(i);
    v->name = "v" + std::to_string(i);
    ++i;
  }
}

// A polygon as a cyclic sequence: rotated to start at its smallest index.
std::vector<std::size_t> canonical(std::vector<std::size_t> cell) {
  std::rotate(cell.begin(), std::min_element(cell.begin(), cell.end()), cell.end());
  return cell;
}

std::set<std::vector<std::size_t>> canonical_set(const std::vector<std::vector<std::size_t>>& cells) {
  std::set<std::vector<std::size_t>> out;
  for (const auto& c : cells) out.insert(canonical(c));
  return out;
}

bool same_double(double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return a == b && std::signbit(a) == std::signbit(b);
}

TEST(Vtp, IcosahedronReadByVtkHasItsPointsFacesAndProperties) {
  G::context ctx;
  Mesh m(ctx);
  build_icosahedron(m);
  const std::string path = scratch_dir() + "ico.vtp";
  vv::write_mesh(m, path);
  read_back r = read_with_vtk(path);

  ASSERT_EQ(r.points.size(), 12u);
  for (std::size_t i = 0; i < 12; ++i) EXPECT_EQ(r.points[i], ico_points[i]) << "point " << i;
  EXPECT_EQ(r.cells["verts"].size(), 0u);
  EXPECT_EQ(r.cells["lines"].size(), 0u);
  ASSERT_EQ(r.cells["polys"].size(), 20u);
  EXPECT_EQ(canonical_set(r.cells["polys"]), canonical_set(ico_faces));
  // Counter-clockwise seen from outside: each face's normal points away
  // from the centre.
  for (const auto& f : r.cells["polys"]) {
    const auto &a = r.points[f[0]], &b = r.points[f[1]], &c = r.points[f[2]];
    double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    EXPECT_GT(n[0] * a[0] + n[1] * a[1] + n[2] * a[2], 0) << "face " << f[0] << " " << f[1] << " " << f[2];
  }

  // Every numeric and 3-vector property but pos, in declaration order,
  // with VTK's type for it; the string is left out.
  std::vector<std::string> names, types;
  std::vector<unsigned> components;
  for (const auto& a : r.arrays) names.push_back(a.name), types.push_back(a.type), components.push_back(a.components);
  EXPECT_EQ(names, (std::vector<std::string>{"height", "index", "big", "upper", "half", "normal", "cell", "rgb", "odd"}));
  EXPECT_EQ(types, (std::vector<std::string>{"double", "int", "unsigned_long_long", "unsigned_char", "float",
                                             "double", "int", "float", "double"}));
  EXPECT_EQ(components, (std::vector<unsigned>{1, 1, 1, 1, 1, 3, 3, 3, 1}));
  ASSERT_EQ(r.arrays.size(), 9u);
  for (const auto& a : r.arrays) ASSERT_EQ(a.values.size(), 12u) << a.name;
  for (std::size_t i = 0; i < 12; ++i) {
    const auto& p = ico_points[i];
    double radius = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    EXPECT_EQ(r.arrays[0].values[i], std::vector<double>{p[2]}) << i;
    EXPECT_EQ(r.arrays[1].values[i], std::vector<double>{-double(i)}) << i;
    EXPECT_EQ(r.arrays[2].values[i], std::vector<double>{double((1ull << 40) + i)}) << i;
    EXPECT_EQ(r.arrays[3].values[i], std::vector<double>{p[1] > 0 ? 1.0 : 0.0}) << i;
    EXPECT_EQ(r.arrays[4].values[i], std::vector<double>{double(i) / 2}) << i;
    EXPECT_EQ(r.arrays[5].values[i], (std::vector<double>{p[0] / radius, p[1] / radius, p[2] / radius})) << i;
    EXPECT_EQ(r.arrays[6].values[i], (std::vector<double>{double(i), -double(i), 7})) << i;
    EXPECT_EQ(r.arrays[7].values[i], (std::vector<double>{0.25, 0.5, double(static_cast<float>(i) / 12)})) << i;
    ASSERT_EQ(r.arrays[8].values[i].size(), 1u);
    double odd = i < 4 ? odd_values[i] : double(i);
    EXPECT_TRUE(same_double(r.arrays[8].values[i][0], odd)) << i << ": " << r.arrays[8].values[i][0];
  }
}

TEST(Vtp, CurveIsPolylinesAndALoneVertexAVertexCell) {
  G::context ctx;
  Mesh m(ctx);
  // A closed square 0-1-2-3, an open chain 4-5-6 and vertex 7 alone.
  std::vector<G::vertex> v;
  for (int i = 0; i < 8; ++i) {
    v.push_back(ctx.new_vertex());
    v.back()->pos = Pt(i, i % 2, 0);
    m.add(v.back());
  }
  vv::make_nb(v[0], {v[1], v[3]});
  vv::make_nb(v[1], {v[2], v[0]});
  vv::make_nb(v[2], {v[3], v[1]});
  vv::make_nb(v[3], {v[0], v[2]});
  vv::make_nb(v[4], {v[5]});
  vv::make_nb(v[5], {v[4], v[6]});
  vv::make_nb(v[6], {v[5]});
  const std::string path = scratch_dir() + "curve.vtp";
  vv::write_mesh(m, path);
  read_back r = read_with_vtk(path);
  EXPECT_EQ(r.points.size(), 8u);
  EXPECT_EQ(r.cells["polys"].size(), 0u);
  EXPECT_EQ(r.cells["verts"], (std::vector<std::vector<std::size_t>>{{7}}));
  // The open chain from an end; the closed one ends where it starts.
  ASSERT_EQ(r.cells["lines"].size(), 2u);
  EXPECT_EQ(r.cells["lines"][0], (std::vector<std::size_t>{4, 5, 6}));
  std::vector<std::size_t> square = r.cells["lines"][1];
  ASSERT_EQ(square.size(), 5u);
  EXPECT_EQ(square.front(), square.back());
  square.pop_back();
  EXPECT_EQ(std::set<std::size_t>(square.begin(), square.end()), (std::set<std::size_t>{0, 1, 2, 3}));
  for (std::size_t i = 0; i < 4; ++i)  // consecutive corners are neighbours
    EXPECT_EQ((square[i] + 1) % 4 == square[(i + 1) % 4] || (square[(i + 1) % 4] + 1) % 4 == square[i], true);
}

TEST(Vtp, SurfaceWithoutFacesWithinMaxFaceGivesItsEdgesAsLines) {
  G::context ctx;
  Mesh m(ctx);
  build_icosahedron(m);
  const std::string path = scratch_dir() + "edges.vtp";
  vv::write_mesh(m, path, vv::export_options{2});
  read_back r = read_with_vtk(path);
  EXPECT_EQ(r.cells["polys"].size(), 0u);
  EXPECT_EQ(r.cells["verts"].size(), 0u);
  std::set<std::pair<std::size_t, std::size_t>> expected, found;
  for (const auto& f : ico_faces)
    for (std::size_t k = 0; k < 3; ++k) expected.insert(std::minmax(f[k], f[(k + 1) % 3]));
  ASSERT_EQ(expected.size(), 30u);
  for (const auto& l : r.cells["lines"]) {
    ASSERT_EQ(l.size(), 2u);
    found.insert(std::minmax(l[0], l[1]));
  }
  EXPECT_EQ(r.cells["lines"].size(), 30u);
  EXPECT_EQ(found, expected);
}

TEST(Vtp, TwoWritesGiveTheSameBytes) {
  G::context ctx1, ctx2;
  Mesh a(ctx1), b(ctx2);
  build_icosahedron(a);
  build_icosahedron(b);
  const std::string p1 = scratch_dir() + "same1.vtp", p2 = scratch_dir() + "same2.vtp";
  vv::write_mesh(a, p1);
  vv::write_mesh(b, p2);
  std::string first = slurp(p1);
  EXPECT_GT(first.size(), 1000u);
  EXPECT_EQ(first, slurp(p2));
  vv::write_mesh(a, p2);
  EXPECT_EQ(first, slurp(p2));
}

TEST(Vtp, MeshWithoutPosIsRefusedAndNothingIsWritten) {
  vv::graph<NoPos>::context ctx;
  vv::graph<NoPos>::mesh m(ctx);
  m.add(ctx.new_vertex());
  const std::string path = scratch_dir() + "nopos.vtp";
  try {
    vv::write_mesh(m, path);
    ADD_FAILURE() << "no error";
  } catch (const vv::error& e) {
    EXPECT_EQ(std::string(e.what()),
              path + ": the vertices have no 'pos' property, so a vtp file cannot hold them (.vvm can)");
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(Vtp, UnwritablePathNamesTheFileAndLeavesNothing) {
  G::context ctx;
  Mesh m(ctx);
  build_icosahedron(m);
  const std::string folder = scratch_dir() + "no-such-folder";
  const std::string path = folder + "/ico.vtp";
  try {
    vv::write_mesh(m, path);
    ADD_FAILURE() << "no error";
  } catch (const vv::error& e) {
    EXPECT_EQ(std::string(e.what()), path + ": cannot write file: No such file or directory");
  }
  EXPECT_FALSE(std::filesystem::exists(folder));
}

TEST(Vtp, FailedWriteLeavesThePreviousFile) {
  const std::string path = scratch_dir() + "kept.vtp";
  vv::vtp_polydata good;
  good.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  good.polys = {{0, 1, 2}};
  vv::write_vtp_file(path, good);
  const std::string before = slurp(path);
  vv::vtp_polydata bad = good;
  bad.polys = {{0, 1, 3}};
  try {
    vv::write_vtp_file(path, bad);
    ADD_FAILURE() << "no error";
  } catch (const vv::error& e) {
    EXPECT_EQ(std::string(e.what()), path + ": a polygon names point 3 of 3");
  }
  EXPECT_EQ(slurp(path), before);
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(scratch_dir())) ++files;
  bad = good;
  bad.point_data.push_back({"short", vv::vtk_number::float64, 1, std::string(16, '\0')});
  EXPECT_THROW(vv::write_vtp_file(path, bad), vv::error);
  EXPECT_EQ(slurp(path), before);
  std::size_t after = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(scratch_dir())) ++after;
  EXPECT_EQ(after, files) << "a temporary was left";
}

TEST(Vtp, ReadingAVtpFileSaysVvOnlyWritesThem) {
  G::context ctx;
  Mesh m(ctx);
  build_icosahedron(m);
  const std::string path = scratch_dir() + "back.vtp";
  vv::write_mesh(m, path);
  Mesh n(ctx);
  try {
    vv::read_mesh(n, path);
    ADD_FAILURE() << "no error";
  } catch (const vv::error& e) {
    EXPECT_EQ(std::string(e.what()),
              path + ": vv writes .vtp files (for ParaView) but does not read them; it reads .vvm .obj .off .ply .stl");
  }
  EXPECT_TRUE(n.empty());
}

// ---- .pvd series ----

TEST(Pvd, SeriesListsItsFilesByStepAndVtkReadsEach) {
  const std::string dir = scratch_dir() + "series/";
  std::filesystem::create_directories(dir + "frames");
  G::context ctx;
  Mesh m(ctx);
  build_icosahedron(m);
  vv::pvd_series series(dir + "mesh.pvd");
  // Added out of order, and step 10 twice: listed by step, the last file
  // of a step kept.
  for (unsigned step : {0u, 20u, 10u}) {
    const std::string file = dir + "frames/mesh-" + std::to_string(step) + ".vtp";
    vv::write_mesh(m, file);
    series.add(step, file);
  }
  Mesh small(ctx);
  small.add(*m.begin());  // one vertex of it
  vv::write_mesh(small, dir + "frames/mesh-10b.vtp");
  series.add(10, dir + "frames/mesh-10b.vtp");

  read_back r = read_with_vtk(dir + "mesh.pvd");
  EXPECT_EQ(r.datasets, (std::vector<std::string>{"0 frames/mesh-0.vtp 12", "10 frames/mesh-10b.vtp 1",
                                                  "20 frames/mesh-20.vtp 12"}));
  std::vector<vv::pvd_entry> listed = vv::read_pvd(dir + "mesh.pvd");
  ASSERT_EQ(listed.size(), 3u);
  EXPECT_EQ(listed[1].step, 10u);
  EXPECT_EQ(listed[1].file, "frames/mesh-10b.vtp");

  // Going on with it in another run.
  vv::pvd_series more = vv::pvd_series::resume(dir + "mesh.pvd");
  more.add(30, dir + "frames/mesh-20.vtp");
  EXPECT_EQ(read_with_vtk(dir + "mesh.pvd").datasets.size(), 4u);
  EXPECT_EQ(more.entries().back().step, 30u);
}

TEST(Pvd, CollectionNameComesFromTheExportPattern) {
  EXPECT_EQ(vv::pvd_path_for("out/mesh-{step}.vtp"), "out/mesh.pvd");
  EXPECT_EQ(vv::pvd_path_for("mesh_{step}.vtp"), "mesh.pvd");
  EXPECT_EQ(vv::pvd_path_for("mesh.{step}.vtp"), "mesh.pvd");
  EXPECT_EQ(vv::pvd_path_for("{step}.vtp"), "series.pvd");
  EXPECT_EQ(vv::pvd_path_for("a/{step}-cells.vtp"), "a/cells.pvd");
  EXPECT_EQ(vv::pvd_path_for("runs/step{step}/m.vtp"), "runs/m.pvd");
  EXPECT_EQ(vv::pvd_path_for("mesh.vtp"), "mesh.pvd");
}

TEST(Pvd, FailedAddLeavesFileAndSeriesAsTheyWere) {
  const std::string dir = scratch_dir() + "pvd-fail/";
  std::filesystem::create_directories(dir);
  vv::pvd_series series(dir + "s.pvd");
  series.add(0, dir + "a.vtp");
  const std::string before = slurp(dir + "s.pvd");
  // The .pvd's folder goes: the next write cannot be made.
  std::filesystem::rename(dir, scratch_dir() + "pvd-moved");
  try {
    series.add(1, dir + "b.vtp");
    ADD_FAILURE() << "no error";
  } catch (const vv::error& e) {
    EXPECT_EQ(std::string(e.what()), dir + "s.pvd: cannot write file: No such file or directory");
  }
  EXPECT_EQ(series.entries().size(), 1u);
  EXPECT_EQ(slurp(scratch_dir() + "pvd-moved/s.pvd"), before);
}

TEST(Pvd, KilledWhileWritingLeavesACompleteCollection) {
  const std::string path = scratch_dir() + "killed.pvd";
  const std::string long_name = std::string(200, 'x') + ".vtp";
  for (int round = 0; round < 5; ++round) {
    pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      // Thousands of ever longer rewrites, until killed; the child never
      // returns into the test runner.
      try {
        vv::pvd_series s(path);
        for (std::uint64_t step = 0;; ++step) s.add(step, scratch_dir() + long_name);
      } catch (...) {
      }
      ::_exit(1);
    }
    ::usleep(static_cast<useconds_t>(30000 + 20000 * round));
    ::kill(child, SIGKILL);
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status));
    if (!std::filesystem::exists(path)) continue;  // killed before the first write
    std::vector<vv::pvd_entry> listed = vv::read_pvd(path);
    for (std::size_t i = 0; i < listed.size(); ++i) ASSERT_EQ(listed[i].step, i) << "round " << round;
    EXPECT_EQ(slurp(path), vv::pvd_text(listed));
  }
}

TEST(Pvd, ReadingSomethingElseIsAClearError) {
  const std::string path = test_files::write_scratch("not.pvd", "<VTKFile type=\"PolyData\"/>");
  try {
    vv::read_pvd(path);
    ADD_FAILURE() << "no error";
  } catch (const vv::error& e) {
    EXPECT_EQ(std::string(e.what()),
              path + ": not a ParaView collection (no <VTKFile type=\"Collection\"><Collection>)");
  }
}

}  // namespace
