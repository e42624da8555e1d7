// Helpers for checking the examples against independent implementations
// (OpenMesh's and CGAL's subdividers) on the same input.
//
//   std::string model = oracle::input_vvm("cow", oracle::cgal_mesh_file("cow.off"));
//   oracle::polygons ours = oracle::run_example("examples/loop.vvp", model, 2);
//   oracle::polygons theirs = oracle::openmesh_loop(oracle::read_polygons(model), 2);
//   oracle::expect_same_points(ours.points, theirs.points, 1e-9);
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <util/point.hpp>
#include <vv/io/mesh_io.hpp>
#include <vv/vv.hpp>

#include "run_interpreter.hpp"
#include "test_files.hpp"
#include "positions_graph.hpp"

namespace oracle {

using point = std::array<double, 3>;

struct polygons {
  std::vector<point> points;
  std::vector<std::vector<std::uint32_t>> faces;
};

using graph = positions_graph::graph;

//! A mesh file as points and counter-clockwise faces (any format vvlib reads).
inline polygons read_polygons(const std::string& path) {
  graph::context ctx;
  graph::mesh m(ctx);
  vv::read_mesh(m, path);
  polygons p;
  for (graph::vertex v : vv::each(m)) p.points.push_back({v->pos.x(), v->pos.y(), v->pos.z()});
  for (const auto& f : vv::face_orbits(m))
    if (f.size() >= 3) p.faces.push_back(f);
  return p;
}

//! A mesh of the project's models/ folder, e.g. model("cube.vvm").
inline std::string model(const std::string& name) { return std::string(VV_SOURCE_DIR) + "/models/" + name; }

//! Where the CGAL demo data lives (Debian's libcgal-demo): extracts one
//! mesh (e.g. "cow.off") into the scratch folder and gives its path.
inline std::string cgal_mesh_file(const std::string& name) {
  std::string out = test_files::scratch_dir() + name;
  if (std::filesystem::exists(out)) return out;
  std::string archive = "/usr/share/doc/libcgal-dev/data.tar.gz";
  test_run::result r = test_run::run({"tar", "xzf", archive, "-C", test_files::scratch_dir(),
                                      "--strip-components=2", "data/meshes/" + name});
  EXPECT_EQ(r.status, 0) << "cannot extract " << name << " from " << archive << " (libcgal-demo): " << r.err;
  return out;
}

//! The mesh in a file converted to a .vvm (in the scratch folder), for
//! examples that read their input with readXMLFile.
inline std::string input_vvm(const std::string& name, const std::string& mesh_file) {
  std::string out = test_files::scratch_dir() + name + ".vvm";
  graph::context ctx;
  graph::mesh m(ctx);
  vv::read_mesh(m, mesh_file);
  vv::write_vvm(m, out);
  return out;
}

//! An example as the cross-checks run it: its copy that reads its input
//! from the file the environment variable VV_ORACLE_INPUT names (the
//! argument of its first readXMLFile call is replaced), and the file it read
//! itself (absolute). Its text and folder are the same for every test and
//! input, so the interpreter's cache compiles it once for all the
//! cross-checks, whatever they feed it (each test process has a scratch
//! folder of its own, and a copy there was compiled again by every test).
//! Written whole or not at all: tests running at once may write it
//! together (a model a test wrote is copied into the test's scratch
//! folder). An example that reads no file is run as it is (own_input
//! empty).
struct runnable_example {
  std::string model, own_input;
};
inline runnable_example example_reading(const std::string& example) {
  const std::string source = example.front() == '/' ? example : std::string(VV_SOURCE_DIR) + "/" + example;
  std::string text = test_files::slurp(source);
  std::regex first_read(R"re(readXMLFile\(\s*"([^"]*)"\s*\))re");
  std::smatch m;
  if (!std::regex_search(text, m, first_read)) return {source, ""};
  std::filesystem::path own = m[1].str();
  if (own.is_relative()) own = std::filesystem::path(source).parent_path() / own;
  text = "#include <cstdlib>\n" + m.prefix().str() + "readXMLFile(std::getenv(\"VV_ORACLE_INPUT\"))" +
         m.suffix().str();
  // A model a test wrote (an absolute path) has a copy of the test's own.
  const std::string folder = example.front() == '/' ? test_files::scratch_dir() : std::string(VV_ORACLE_MODELS);
  std::filesystem::create_directories(folder);
  const std::string stem = std::filesystem::path(example).stem().string();
  const std::string out = folder + "/" + stem + "_reading_its_input.vvp";
  if (!std::filesystem::exists(out) || test_files::slurp(out) != text) {
    const std::string temporary = out + ".tmp-" + std::to_string(getpid());
    std::ofstream(temporary, std::ios::binary) << text;
    std::filesystem::rename(temporary, out);
  }
  return {out, own.lexically_normal().string()};
}

//! Where run_example(example, input, steps) writes its export.
inline std::string export_of(const std::string& example, unsigned steps) {
  return test_files::scratch_dir() + std::filesystem::path(example).stem().string() + "_" + std::to_string(steps) +
         ".vvm";
}

//! Runs an example (a .vvp path relative to the source tree, or absolute)
//! on `input` (a .vvm; empty: the file it reads itself) for `steps` steps
//! and gives the exported mesh; extra arguments go to the interpreter.
inline polygons run_example(const std::string& example, const std::string& input, unsigned steps,
                            const std::vector<std::string>& extra = {}) {
  runnable_example run = example_reading(example);
  const std::string out = export_of(example, steps);
  std::vector<std::string> args = {"--batch", "--quiet", "--steps", std::to_string(steps), "--export", out};
  args.insert(args.end(), extra.begin(), extra.end());
  args.push_back(run.model);
  EXPECT_TRUE(input.empty() || !run.own_input.empty()) << example << " reads no file: it cannot be given " << input;
  const std::string read = input.empty() ? run.own_input : std::filesystem::absolute(input).string();
  if (!read.empty()) setenv("VV_ORACLE_INPUT", read.c_str(), 1);
  test_run::result r = test_run::run(test_run::interpreter(args), 600);
  unsetenv("VV_ORACLE_INPUT");
  EXPECT_EQ(r.status, 0) << run.model << ": " << r.err;
  if (r.status != 0) return {};
  return read_polygons(out);
}

//! The diagonal of the points' bounding box (tolerances scale with it).
inline double size_of(const std::vector<point>& pts) {
  if (pts.empty()) return 0;
  point lo = pts[0], hi = pts[0];
  for (const point& p : pts)
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                   (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

//! The same points in any order: every point of `a` has one in `b` within
//! tol (absolute), and the counts match.
inline void expect_same_points(std::vector<point> a, std::vector<point> b, double tol) {
  ASSERT_EQ(a.size(), b.size()) << "different numbers of points";
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  auto close = [&](const point& p, const point& q) {
    return std::fabs(p[0] - q[0]) <= tol && std::fabs(p[1] - q[1]) <= tol && std::fabs(p[2] - q[2]) <= tol;
  };
  std::size_t unmatched = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (close(a[i], b[i])) continue;
    // Rounding can reorder points that tie in x: search near i in x.
    auto lo = std::lower_bound(b.begin(), b.end(), point{a[i][0] - tol, -1e300, -1e300});
    bool found = false;
    for (auto it = lo; it != b.end() && (*it)[0] <= a[i][0] + tol && !found; ++it) found = close(a[i], *it);
    if (!found && ++unmatched <= 5)
      ADD_FAILURE() << "no match for (" << a[i][0] << ", " << a[i][1] << ", " << a[i][2] << ")";
  }
  EXPECT_EQ(unmatched, 0u) << "of " << a.size() << " points";
}

//! Faces as cyclic sequences of positions, in any order and rotation:
//! compares connectivity of two meshes whose vertices may be numbered
//! differently (positions must be unique within tol).
inline void expect_same_faces(const polygons& a, const polygons& b, double tol) {
  ASSERT_EQ(a.faces.size(), b.faces.size()) << "different numbers of faces";
  auto key = [&](const polygons& p) {
    std::vector<std::vector<point>> out;
    for (const auto& f : p.faces) {
      std::vector<point> face;
      for (std::uint32_t i : f) {
        point q = p.points[i];
        for (double& c : q) c = std::round(c / tol) * tol;  // snap: equal within tol compares equal
        face.push_back(q);
      }
      std::rotate(face.begin(), std::min_element(face.begin(), face.end()), face.end());
      out.push_back(face);
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  EXPECT_TRUE(key(a) == key(b)) << "the faces differ";
}

//! V, E, F of a closed polygon mesh (each edge borders two faces).
struct counts {
  std::size_t v, e, f;
};
inline counts counts_of(const polygons& p) {
  std::size_t corners = 0;
  for (const auto& face : p.faces) corners += face.size();
  return {p.points.size(), corners / 2, p.faces.size()};
}
inline void expect_counts(const polygons& p, counts c) {
  counts got = counts_of(p);
  EXPECT_EQ(got.v, c.v);
  EXPECT_EQ(got.e, c.e);
  EXPECT_EQ(got.f, c.f);
}
//! Catmull-Clark's (and 4-8's) counts after `levels` levels: a vertex per
//! old vertex, edge and face; every face becomes quads.
inline counts catmull_clark_counts(counts c, unsigned levels) {
  for (unsigned i = 0; i < levels; ++i) c = {c.v + c.e + c.f, 2 * c.e + 4 * c.f, 4 * c.f};
  return c;
}
//! Doo-Sabin's counts after `levels` levels: a vertex for each corner of
//! each face (2E), four edges for each old edge, a face for each old face,
//! edge and vertex.
inline counts doo_sabin_counts(counts c, unsigned levels) {
  for (unsigned i = 0; i < levels; ++i) c = {2 * c.e, 4 * c.e, c.f + c.e + c.v};
  return c;
}

}  // namespace oracle
