// Polygon formats (read_mesh / write_mesh: .obj .off .ply .stl) and
// OpenMesh conversion: round trips keep vertices, positions and faces (as
// cyclic sequences), faces keep their counter-clockwise orientation
// (LANGUAGE.md section 1: outward normals), writing is deterministic, and
// errors name the file.
// OpenMesh's VectorT leaves its coordinates uninitialised by design; GCC 12
// at -O1 and above then warns inside OpenMesh's property containers
// (Property.hh push_back), which -Werror would turn into an error.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

#include <vv/vv.hpp>
#include <vv/io/mesh_io.hpp>
#include <vv/io/openmesh.hpp>

#include <util/point.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include <unistd.h>

#include "positions_graph.hpp"
#include "test_files.hpp"

#ifndef VV_SOURCE_DIR
#error "compile with -DVV_SOURCE_DIR='\"/path/to/source\"'"
#endif

using test_files::scratch_dir;
using test_files::slurp;

namespace {

using Pt = util::Point<double>;

using G = positions_graph::graph;
using V = G::vertex;
using Mesh = G::mesh;

const std::string pyramid_path = VV_SOURCE_DIR "/models/pyramid.vvm";
const std::string cube_path = VV_SOURCE_DIR "/models/cube.obj";

using Key = std::array<double, 3>;
using Cycle = std::vector<Key>;

// ---- helpers ----



void spit(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

bool exists(const std::string& path) { return std::filesystem::exists(path); }

Key key(const Pt& p) { return {p.x(), p.y(), p.z()}; }
// A double rounded to float. The volatile is needed: GCC 12.2 at -O2 and
// above vectorises double(float(a)), double(float(b)) pairs into a plain
// copy, losing the rounding (a miscompilation, not a library matter).
double through_float(double d) {
  volatile float f = static_cast<float>(d);
  return static_cast<double>(f);
}
Key float_key(const Pt& p) {
  return {through_float(p.x()), through_float(p.y()), through_float(p.z())};
}

// A cycle rotated to start at its smallest element: equal cycles compare equal.
Cycle canonical(Cycle c) {
  if (!c.empty()) std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
  return c;
}

std::vector<V> members(const Mesh& m) {
  std::vector<V> out;
  for (V v : m) out.push_back(v);
  return out;
}

std::vector<Key> positions(const Mesh& m) {
  std::vector<Key> out;
  for (V v : m) out.push_back(key(v->pos));
  return out;
}

// The closed face orbits of m as canonical cycles of positions, sorted.
std::vector<Cycle> face_set(const Mesh& m,
                            std::size_t max_face = std::numeric_limits<std::size_t>::max()) {
  std::vector<V> vs = members(m);
  std::vector<Cycle> out;
  for (const auto& f : vv::face_orbits(m, max_face)) {
    Cycle c;
    for (std::uint32_t i : f) c.push_back(key(vs[i]->pos));
    out.push_back(canonical(c));
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Every member's neighbourhood as a canonical cycle of positions, listed by
// the member's own position (sorted).
std::vector<std::pair<Key, Cycle>> rotation_set(const Mesh& m) {
  std::vector<std::pair<Key, Cycle>> out;
  for (V v : m) {
    Cycle c;
    for (V x : vv::each(v)) c.push_back(key(x->pos));
    out.emplace_back(key(v->pos), canonical(c));
  }
  std::sort(out.begin(), out.end());
  return out;
}

Pt newell_normal(const std::vector<Pt>& poly) {
  Pt n(0, 0, 0);
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Pt& a = poly[i];
    const Pt& b = poly[(i + 1) % poly.size()];
    n += Pt((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
            (a.x() - b.x()) * (a.y() + b.y()));
  }
  return n;
}

// Faces whose normal points towards the origin (for convex solids around it).
int inward_faces(const Mesh& m) {
  std::vector<V> vs = members(m);
  int inward = 0;
  for (const auto& f : vv::face_orbits(m)) {
    std::vector<Pt> poly;
    Pt centroid(0, 0, 0);
    for (std::uint32_t i : f) {
      poly.push_back(vs[i]->pos);
      centroid += vs[i]->pos;
    }
    centroid /= static_cast<double>(f.size());
    if (newell_normal(poly) * centroid <= 0) ++inward;
  }
  return inward;
}

// A minimal OBJ reader for the hand-written reference file.
struct Polygons {
  std::vector<Pt> points;
  std::vector<std::vector<int>> faces;  // 0-based
};
Polygons parse_obj(const std::string& text) {
  Polygons p;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    if (tag == "v") {
      double x, y, z;
      ls >> x >> y >> z;
      p.points.emplace_back(x, y, z);
    } else if (tag == "f") {
      std::vector<int> f;
      int i;
      while (ls >> i) f.push_back(i - 1);
      p.faces.push_back(f);
    }
  }
  return p;
}
std::vector<Cycle> face_set(const Polygons& p) {
  std::vector<Cycle> out;
  for (const auto& f : p.faces) {
    Cycle c;
    for (int i : f) c.push_back(key(p.points[static_cast<std::size_t>(i)]));
    out.push_back(canonical(c));
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::size_t count_lines_starting(const std::string& text, const std::string& prefix) {
  std::size_t n = 0;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line))
    if (line.compare(0, prefix.size(), prefix) == 0) ++n;
  return n;
}

std::vector<Cycle> pyramid_faces() {
  G::context ctx;
  Mesh M(ctx);
  vv::read_vvm(M, pyramid_path);
  return face_set(M);
}

// Reads, writes, reads back and writes again a polygon format; checks
// vertices, edges, faces, positions and the writer's determinism.
void polygon_round_trip(const std::string& source, const std::string& ext) {
  SCOPED_TRACE(source + " via " + ext);
  G::context ctx;
  Mesh M(ctx), N(ctx);
  vv::read_mesh(M, source);
  const std::string a = scratch_dir() + "round_a" + ext, b = scratch_dir() + "round_b" + ext;
  vv::write_mesh(M, a);
  vv::read_mesh(N, a);
  EXPECT_EQ(N.size(), M.size());
  EXPECT_EQ(vv::edge_count(N), vv::edge_count(M));
  EXPECT_EQ(vv::face_orbits(N).size(), vv::face_orbits(M).size());
  EXPECT_EQ(positions(N), positions(M));
  EXPECT_EQ(face_set(N), face_set(M));
  EXPECT_EQ(rotation_set(N), rotation_set(M));
  EXPECT_EQ(vv::euler_characteristic(N), 2);
  EXPECT_EQ(inward_faces(N), 0);
  EXPECT_NO_THROW(vv::check_invariants(N, {true, true}));
  vv::write_mesh(N, b);
  EXPECT_EQ(slurp(a), slurp(b)) << "the second written file differs from the first";
}

// =====================================================================
// The cube (OBJ, quads)
// =====================================================================

TEST(CubeObj, ReferenceFileIsACounterClockwiseCube) {
  Polygons p = parse_obj(slurp(cube_path));
  ASSERT_EQ(p.points.size(), 8u);
  ASSERT_EQ(p.faces.size(), 6u);
  for (const Pt& q : p.points) {
    EXPECT_EQ(std::abs(q.x()), 1.0);
    EXPECT_EQ(std::abs(q.y()), 1.0);
    EXPECT_EQ(std::abs(q.z()), 1.0);
  }
  for (const auto& f : p.faces) {
    ASSERT_EQ(f.size(), 4u);
    std::vector<Pt> poly;
    Pt centroid(0, 0, 0);
    for (int i : f) {
      poly.push_back(p.points[static_cast<std::size_t>(i)]);
      centroid += poly.back();
    }
    Pt n = newell_normal(poly);
    EXPECT_EQ(n.length(), 8.0);  // twice the area (4) of an outward face
    EXPECT_GT(n * centroid, 0);
  }
}

TEST(CubeObj, ReadGivesEightVerticesTwelveEdgesSixQuads) {
  G::context ctx;
  Mesh M(ctx);
  unsigned before = ctx.new_vertex().label();
  vv::read_mesh(M, cube_path);
  Polygons p = parse_obj(slurp(cube_path));
  ASSERT_EQ(M.size(), 8u);
  EXPECT_EQ(vv::edge_count(M), 12u);
  auto faces = vv::face_orbits(M);
  ASSERT_EQ(faces.size(), 6u);
  for (const auto& f : faces) EXPECT_EQ(f.size(), 4u);
  EXPECT_EQ(vv::euler_characteristic(M), 2);
  // Vertices in file order, with exact positions.
  std::vector<V> vs = members(M);
  for (std::size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(vs[i]->pos, p.points[i]) << i;
    EXPECT_EQ(vs[i].label(), before + 1 + i);
    EXPECT_EQ(vv::valence(vs[i]), 3u);
  }
  // The faces are the file's faces, with the file's orientation.
  EXPECT_EQ(face_set(M), face_set(p));
  EXPECT_NO_THROW(vv::check_invariants(M, {true, true}));
}

TEST(CubeObj, EveryFaceReadFromObjHasAnOutwardNormal) {
  G::context ctx;
  Mesh M(ctx);
  vv::read_mesh(M, cube_path);
  std::vector<V> vs = members(M);
  auto faces = vv::face_orbits(M);
  ASSERT_EQ(faces.size(), 6u);
  for (const auto& f : faces) {
    std::vector<Pt> poly;
    for (std::uint32_t i : f) poly.push_back(vs[i]->pos);
    Pt n = newell_normal(poly) / 8.0;  // unit normal of a 2x2 face
    Pt centroid = (poly[0] + poly[1] + poly[2] + poly[3]) / 4;
    // The centroid of each face is its outward unit normal.
    EXPECT_EQ(n, centroid);
  }
  EXPECT_EQ(inward_faces(M), 0);
}

TEST(CubeObj, RoundTrip) { polygon_round_trip(cube_path, ".obj"); }

TEST(CubeObj, WrittenBackUnchanged) {
  G::context ctx;
  Mesh M(ctx);
  vv::read_mesh(M, cube_path);
  const std::string out = scratch_dir() + "cube_back.obj";
  vv::write_mesh(M, out);
  Polygons original = parse_obj(slurp(cube_path));
  Polygons written = parse_obj(slurp(out));
  EXPECT_EQ(written.points, original.points);
  EXPECT_EQ(face_set(written), face_set(original));
}

TEST(CubeObj, OtherPolygonFormatsRoundTrip) {
  polygon_round_trip(cube_path, ".off");
  polygon_round_trip(cube_path, ".ply");
}

TEST(CubeStl, QuadsBecomeTriangles) {
  G::context ctx;
  Mesh M(ctx), N(ctx);
  vv::read_mesh(M, cube_path);
  const std::string out = scratch_dir() + "cube.stl";
  vv::write_mesh(M, out);
  vv::read_mesh(N, out);
  EXPECT_EQ(N.size(), 8u);
  EXPECT_EQ(vv::edge_count(N), 18u);  // 12 sides and 6 diagonals
  auto faces = vv::face_orbits(N);
  EXPECT_EQ(faces.size(), 12u);
  for (const auto& f : faces) EXPECT_EQ(f.size(), 3u);
  EXPECT_EQ(vv::euler_characteristic(N), 2);
  EXPECT_EQ(inward_faces(N), 0);
  std::vector<Key> a = positions(M), b = positions(N);
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  EXPECT_EQ(a, b);  // +-1 is exact in float
}

// =====================================================================
// The double pyramid in every polygon format
// =====================================================================

TEST(PyramidObj, RoundTripFromVvm) {
  G::context ctx;
  Mesh P(ctx), M(ctx), N(ctx);
  vv::read_vvm(P, pyramid_path);
  const std::string a = scratch_dir() + "pyr_a.obj", b = scratch_dir() + "pyr_b.obj";
  vv::write_mesh(P, a);
  vv::read_mesh(M, a);
  ASSERT_EQ(M.size(), 6u);
  EXPECT_EQ(vv::edge_count(M), 12u);
  EXPECT_EQ(vv::face_orbits(M).size(), 8u);
  EXPECT_EQ(positions(M), positions(P));  // 1.4142 exactly
  EXPECT_EQ(members(M)[4]->pos.y(), 1.4142);
  EXPECT_EQ(face_set(M), face_set(P));
  EXPECT_EQ(rotation_set(M), rotation_set(P));
  EXPECT_EQ(inward_faces(M), 0);
  vv::write_mesh(M, b);
  vv::read_mesh(N, b);
  EXPECT_EQ(positions(N), positions(P));
  EXPECT_EQ(face_set(N), face_set(P));
  EXPECT_EQ(slurp(a), slurp(b));
  EXPECT_EQ(count_lines_starting(slurp(a), "v "), 6u);
  EXPECT_EQ(count_lines_starting(slurp(a), "f "), 8u);
}

TEST(PyramidObj, ObjRoundTrip) {
  const std::string src = scratch_dir() + "pyr_src.obj";
  {
    G::context ctx;
    Mesh P(ctx);
    vv::read_vvm(P, pyramid_path);
    vv::write_mesh(P, src);
  }
  polygon_round_trip(src, ".obj");
}

// The pyramid through a polygon format and back: same vertices, faces and
// rotations; the file starts with the format's magic word.
void pyramid_format_round_trip(const std::string& ext, const std::string& magic) {
  G::context ctx;
  Mesh P(ctx), M(ctx);
  vv::read_vvm(P, pyramid_path);
  const std::string a = scratch_dir() + "pyr" + ext;
  vv::write_mesh(P, a);
  EXPECT_EQ(slurp(a).rfind(magic, 0), 0u);
  vv::read_mesh(M, a);
  EXPECT_EQ(M.size(), 6u);
  EXPECT_EQ(vv::edge_count(M), 12u);
  EXPECT_EQ(positions(M), positions(P));
  EXPECT_EQ(face_set(M), pyramid_faces());
  EXPECT_EQ(rotation_set(M), rotation_set(P));
  polygon_round_trip(a, ext);
}

TEST(PyramidOff, RoundTrip) { pyramid_format_round_trip(".off", "OFF"); }

TEST(PyramidPly, RoundTrip) { pyramid_format_round_trip(".ply", "ply"); }

TEST(PyramidStl, TrianglesWithFloatPositions) {
  G::context ctx;
  Mesh P(ctx), M(ctx), N(ctx);
  vv::read_vvm(P, pyramid_path);
  const std::string a = scratch_dir() + "pyr_a.stl", b = scratch_dir() + "pyr_b.stl";
  vv::write_mesh(P, a);
  vv::read_mesh(M, a);
  ASSERT_EQ(M.size(), 6u);
  EXPECT_EQ(vv::edge_count(M), 12u);
  auto faces = vv::face_orbits(M);
  EXPECT_EQ(faces.size(), 8u);
  for (const auto& f : faces) EXPECT_EQ(f.size(), 3u);
  EXPECT_EQ(vv::euler_characteristic(M), 2);
  EXPECT_EQ(inward_faces(M), 0);
  // STL stores floats: positions are the originals rounded to float.
  std::vector<Key> want, got = positions(M);
  for (V v : P) want.push_back(float_key(v->pos));
  std::sort(want.begin(), want.end());
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, want);
  EXPECT_NE(through_float(1.4142), 1.4142);  // the rounding is visible
  std::vector<Cycle> want_faces;
  {
    std::vector<V> ps = members(P);
    for (const auto& f : vv::face_orbits(P)) {
      Cycle c;
      for (std::uint32_t i : f) c.push_back(float_key(ps[i]->pos));
      want_faces.push_back(canonical(c));
    }
    std::sort(want_faces.begin(), want_faces.end());
  }
  EXPECT_EQ(face_set(M), want_faces);
  EXPECT_NO_THROW(vv::check_invariants(M, {true, true}));
  // Float positions survive further round trips unchanged, byte for byte.
  vv::write_mesh(M, b);
  vv::read_mesh(N, b);
  std::vector<Key> again = positions(N);
  std::sort(again.begin(), again.end());
  EXPECT_EQ(again, want);
  EXPECT_EQ(face_set(N), want_faces);
  EXPECT_EQ(slurp(a).size(), slurp(b).size());
}

TEST(PyramidFormats, VvmThroughWriteMeshIsTheVvmWriter) {
  G::context ctx;
  Mesh P(ctx), M(ctx);
  vv::read_mesh(P, pyramid_path);
  EXPECT_EQ(P.size(), 6u);
  const std::string a = scratch_dir() + "through.vvm";
  vv::write_mesh(P, a);
  EXPECT_EQ(slurp(a), slurp(pyramid_path));
  vv::read_mesh(M, a);
  EXPECT_EQ(positions(M), positions(P));
}

// =====================================================================
// max_face
// =====================================================================

// A hexagonal fan around the origin in the plane z = 0, counter-clockwise
// seen from +z: 6 triangles and one boundary orbit of length 6.
struct Fan {
  V centre;
  std::vector<V> ring;
};
Fan make_fan(G::context& ctx, Mesh& M) {
  Fan fan{ctx.new_vertex(), {}};
  const double xs[6] = {2, 1, -1, -2, -1, 1}, ys[6] = {0, 2, 2, 0, -2, -2};
  for (int i = 0; i < 6; ++i) {
    fan.ring.push_back(ctx.new_vertex());
    fan.ring.back()->pos = Pt(xs[i], ys[i], 0);
  }
  vv::make_nb_from(fan.centre, fan.ring);
  for (std::size_t i = 0; i < 6; ++i)
    vv::make_nb(fan.ring[i], {fan.ring[(i + 1) % 6], fan.centre, fan.ring[(i + 5) % 6]});
  M.add(fan.centre);
  for (const V& v : fan.ring) M.add(v);
  return fan;
}

TEST(MaxFace, LongerOrbitsAreLeftOut) {
  G::context ctx;
  Mesh M(ctx);
  make_fan(ctx, M);
  ASSERT_NO_THROW(vv::check_invariants(M, {true, false}));
  EXPECT_EQ(vv::orbits(M).faces.size(), 7u);
  EXPECT_EQ(vv::orbits(M, 3).faces.size(), 6u);
  EXPECT_EQ(vv::orbits(M, 3).long_orbits, 1u);
  for (const auto& f : vv::face_orbits(M, 3)) {
    std::vector<Pt> poly;
    for (std::uint32_t i : f) poly.push_back(members(M)[i]->pos);
    EXPECT_GT(newell_normal(poly).z(), 0) << "triangles face +z";
  }

  const std::string all = scratch_dir() + "fan_all.obj", tri = scratch_dir() + "fan_tri.obj";
  vv::write_mesh(M, all);
  vv::write_mesh(M, tri, vv::export_options{3});
  EXPECT_EQ(count_lines_starting(slurp(all), "f "), 7u);
  EXPECT_EQ(count_lines_starting(slurp(tri), "f "), 6u);
  EXPECT_EQ(count_lines_starting(slurp(tri), "v "), 7u);

  // The open patch reads back with the same triangles and neighbourhoods.
  Mesh N(ctx);
  vv::read_mesh(N, tri);
  EXPECT_EQ(N.size(), 7u);
  EXPECT_EQ(vv::edge_count(N), 12u);
  EXPECT_EQ(positions(N), positions(M));
  EXPECT_EQ(face_set(N, 3), face_set(M, 3));
  EXPECT_EQ(vv::orbits(N, 3).long_orbits, 1u);
  EXPECT_EQ(rotation_set(N), rotation_set(M));
}

// Curves (issue 9, item 5): a mesh whose vertices have at most two
// neighbours is written as polylines, not as the two sides of a polygon.
// A closed square x0..x3 and, beside it, an open path y0-y1-y2 (given with
// its middle vertex first, so the walk must start from an end).
TEST(Curves, OBJHoldsClosedAndOpenPolylinesAsLLines) {
  G::context ctx;
  Mesh M(ctx);
  std::vector<V> x, y;
  const double xs[4] = {0, 1, 1, 0}, ys[4] = {0, 0, 1, 1};
  for (int i = 0; i < 4; ++i) {
    x.push_back(ctx.new_vertex());
    x.back()->pos = Pt(xs[i], ys[i], 0.5);
  }
  for (int i = 0; i < 3; ++i) {
    y.push_back(ctx.new_vertex());
    y.back()->pos = Pt(3 + i, 0.25, 0);
  }
  for (std::size_t i = 0; i < 4; ++i) vv::make_nb(x[i], {x[(i + 3) % 4], x[(i + 1) % 4]});
  vv::make_nb(y[0], {y[1]});
  vv::make_nb(y[1], {y[0], y[2]});
  vv::make_nb(y[2], {y[1]});
  M.add(y[1]);
  for (const V& v : x) M.add(v);
  M.add(y[0]);
  M.add(y[2]);
  EXPECT_TRUE(vv::is_curve(M));
  const std::string path = scratch_dir() + "curves.obj";
  vv::write_mesh(M, path);
  // Positions in iteration order: y1 x0 x1 x2 x3 y0 y2.
  EXPECT_EQ(slurp(path),
            "v 4 0.25 0\nv 0 0 0.5\nv 1 0 0.5\nv 1 1 0.5\nv 0 1 0.5\nv 3 0.25 0\nv 5 0.25 0\n"
            "l 6 1 7\nl 2 5 4 3 2\n");
  // Formats without lines refuse, and leave no file.
  const std::string off = scratch_dir() + "curves.off";
  std::remove(off.c_str());
  try {
    vv::write_mesh(M, off);
    ADD_FAILURE() << "a curve was written to OFF";
  } catch (const vv::error& e) {
    EXPECT_EQ(std::string(e.what()), off + ": a curve (no vertex has more than two neighbours) is written as "
                                           "lines, which off files cannot hold; write .obj (l lines) or .vvm");
  }
  EXPECT_FALSE(std::ifstream(off).good());
}

TEST(Curves, ASurfaceIsNoCurveAndKeepsItsFaces) {
  G::context ctx;
  Mesh M(ctx);
  make_fan(ctx, M);
  EXPECT_FALSE(vv::is_curve(M));
  const std::string path = scratch_dir() + "fan_faces.obj";
  vv::write_mesh(M, path);
  EXPECT_EQ(count_lines_starting(slurp(path), "f "), 7u);
  EXPECT_EQ(count_lines_starting(slurp(path), "l "), 0u);
}

TEST(MaxFace, QuadsAreLeftOutBelowFour) {
  G::context ctx;
  Mesh M(ctx);
  vv::read_mesh(M, cube_path);
  const std::string out = scratch_dir() + "cube_max3.off";
  vv::write_mesh(M, out, vv::export_options{3});
  std::istringstream in(slurp(out));
  std::string magic;
  std::size_t nv = 0, nf = 0;
  in >> magic >> nv >> nf;
  EXPECT_EQ(magic, "OFF");
  EXPECT_EQ(nv, 8u);
  EXPECT_EQ(nf, 0u);
  vv::write_mesh(M, out, vv::export_options{4});
  in = std::istringstream(slurp(out));
  in >> magic >> nv >> nf;
  EXPECT_EQ(nf, 6u);
}

// =====================================================================
// Errors
// =====================================================================

TEST(FormatErrors, UnknownExtension) {
  G::context ctx;
  Mesh M(ctx);
  vv::read_vvm(M, pyramid_path);
  const std::vector<Key> before = positions(M);
  const unsigned next_label = ctx.new_vertex().label() + 1;
  const std::string out = scratch_dir() + "mesh.xyz";
  std::filesystem::remove(out);
  try {
    vv::write_mesh(M, out);
    ADD_FAILURE() << "wrote an unknown format";
  } catch (const vv::error& e) {
    std::string msg = e.what();
    EXPECT_EQ(msg.rfind(out + ": ", 0), 0u) << msg;
    EXPECT_NE(msg.find("unknown mesh format"), std::string::npos) << msg;
    EXPECT_NE(msg.find(".xyz"), std::string::npos) << msg;
  }
  EXPECT_FALSE(exists(out));
  spit(out, "1 2 3\n");
  try {
    vv::read_mesh(M, out);
    ADD_FAILURE() << "read an unknown format";
  } catch (const vv::error& e) {
    std::string msg = e.what();
    EXPECT_EQ(msg.rfind(out + ": ", 0), 0u) << msg;
    EXPECT_NE(msg.find("unknown mesh format"), std::string::npos) << msg;
  }
  const std::string bare = scratch_dir() + "no_extension";
  std::filesystem::remove(bare);
  EXPECT_THROW(vv::write_mesh(M, bare), vv::error);
  EXPECT_FALSE(exists(bare));
  EXPECT_EQ(positions(M), before);
  EXPECT_EQ(ctx.new_vertex().label(), next_label);
}

TEST(FormatErrors, MissingFile) {
  G::context ctx;
  Mesh M(ctx);
  vv::read_vvm(M, pyramid_path);
  const std::vector<Key> before = positions(M);
  const unsigned next_label = ctx.new_vertex().label() + 1;
  for (const char* ext : {".obj", ".off", ".ply", ".stl", ".vvm"}) {
    const std::string path = scratch_dir() + "absent" + ext;
    try {
      vv::read_mesh(M, path);
      ADD_FAILURE() << "read a missing file " << path;
    } catch (const vv::error& e) {
      std::string msg = e.what();
      EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
      EXPECT_NE(msg.find("cannot open"), std::string::npos) << msg;
    }
  }
  EXPECT_EQ(positions(M), before);
  EXPECT_EQ(M.size(), 6u);
  EXPECT_EQ(ctx.new_vertex().label(), next_label);
}

TEST(FormatErrors, UnreadableContents) {
  G::context ctx;
  Mesh M(ctx);
  vv::read_vvm(M, pyramid_path);
  const std::vector<Key> before = positions(M);
  const std::vector<Cycle> faces_before = face_set(M);
  const unsigned next_label = ctx.new_vertex().label() + 1;
  struct Case {
    const char* name;
    const char* text;
  } cases[] = {
      {"garbage.off", "hello world\n"},
      {"short.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n"},
      {"truncated.ply", "ply\nformat ascii 1.0\nelement vertex 2\n"},
      {"bad_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"},
  };
  // Each names the file, and the line where the format has lines (the
  // messages themselves: polygon_readers_test.cpp).
  for (const Case& c : cases) {
    const std::string path = scratch_dir() + c.name;
    spit(path, c.text);
    try {
      vv::read_mesh(M, path);
      ADD_FAILURE() << "read " << c.name;
    } catch (const vv::error& e) {
      std::string msg = e.what();
      EXPECT_EQ(msg.rfind(path + ":", 0), 0u) << msg;
      EXPECT_EQ(e.file(), path);
    }
  }
  EXPECT_EQ(positions(M), before);
  EXPECT_EQ(face_set(M), faces_before);
  EXPECT_EQ(ctx.new_vertex().label(), next_label);
}

TEST(FormatErrors, NonManifoldFacesAreReported) {
  // Two triangles sharing an edge with the same orientation.
  G::context ctx;
  Mesh M(ctx);
  const std::string path = scratch_dir() + "nonmanifold.obj";
  spit(path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 1 2 4\n");
  try {
    vv::read_mesh(M, path);
    ADD_FAILURE() << "read a non-manifold mesh";
  } catch (const vv::error& e) {
    std::string msg = e.what();
    EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
    EXPECT_NE(msg.find("manifold"), std::string::npos) << msg;
  }
  EXPECT_EQ(M.size(), 0u);
}

// =====================================================================
// OpenMesh
// =====================================================================

TEST(OpenMesh, PyramidRoundTripIsEqual) {
  G::context ctx;
  Mesh P(ctx), M(ctx);
  vv::read_vvm(P, pyramid_path);
  vv::openmesh_mesh om = vv::to_openmesh(P);
  EXPECT_EQ(om.n_vertices(), 6u);
  EXPECT_EQ(om.n_edges(), 12u);
  EXPECT_EQ(om.n_faces(), 8u);
  std::vector<V> ps = members(P);
  for (auto v : om.vertices()) {
    const auto& q = om.point(v);
    const Pt& want = ps[static_cast<std::size_t>(v.idx())]->pos;
    EXPECT_EQ(q[0], want.x());
    EXPECT_EQ(q[1], want.y());
    EXPECT_EQ(q[2], want.z());
  }
  // OpenMesh's own face normals point outwards too.
  for (auto f : om.faces()) {
    std::vector<Pt> poly;
    for (auto v : om.fv_ccw_range(f)) {
      const auto& q = om.point(v);
      poly.emplace_back(q[0], q[1], q[2]);
    }
    ASSERT_EQ(poly.size(), 3u);
    Pt centroid = (poly[0] + poly[1] + poly[2]) / 3;
    EXPECT_GT(newell_normal(poly) * centroid, 0);
  }
  vv::from_openmesh(M, om);
  EXPECT_EQ(positions(M), positions(P));
  EXPECT_EQ(vv::edge_count(M), 12u);
  EXPECT_EQ(face_set(M), face_set(P));
  EXPECT_EQ(rotation_set(M), rotation_set(P));
  EXPECT_NO_THROW(vv::check_invariants(M, {true, true}));
}

TEST(OpenMesh, CubeRoundTripIsEqual) {
  G::context ctx;
  Mesh C(ctx), M(ctx);
  vv::read_mesh(C, cube_path);
  vv::openmesh_mesh om = vv::to_openmesh(C);
  EXPECT_EQ(om.n_vertices(), 8u);
  EXPECT_EQ(om.n_edges(), 12u);
  EXPECT_EQ(om.n_faces(), 6u);
  for (auto f : om.faces()) EXPECT_EQ(om.valence(f), 4u);
  vv::from_openmesh(M, om);
  EXPECT_EQ(positions(M), positions(C));
  EXPECT_EQ(face_set(M), face_set(C));
  EXPECT_EQ(rotation_set(M), rotation_set(C));
  EXPECT_EQ(inward_faces(M), 0);
  // And once more: the round trip is stable.
  vv::openmesh_mesh again = vv::to_openmesh(M);
  EXPECT_EQ(again.n_faces(), 6u);
  Mesh N(ctx);
  vv::from_openmesh(N, again);
  EXPECT_EQ(face_set(N), face_set(C));
}

TEST(OpenMesh, OpenPatchKeepsItsBoundary) {
  G::context ctx;
  Mesh M(ctx), N(ctx);
  make_fan(ctx, M);
  vv::openmesh_mesh om = vv::to_openmesh(M, 3);
  EXPECT_EQ(om.n_vertices(), 7u);
  EXPECT_EQ(om.n_faces(), 6u);
  EXPECT_EQ(om.n_edges(), 12u);
  std::size_t boundary = 0;
  for (auto e : om.edges()) boundary += om.is_boundary(e) ? 1 : 0;
  EXPECT_EQ(boundary, 6u);
  vv::from_openmesh(N, om);
  EXPECT_EQ(positions(N), positions(M));
  EXPECT_EQ(face_set(N, 3), face_set(M, 3));
  EXPECT_EQ(rotation_set(N), rotation_set(M));
}

// =====================================================================
// Determinism
// =====================================================================

TEST(Determinism, SameMeshWrittenTwiceIsByteIdentical) {
  G::context ctx;
  Mesh M(ctx);
  vv::read_vvm(M, pyramid_path);
  for (const char* ext : {".vvm", ".obj", ".off", ".ply", ".stl"}) {
    const std::string a = scratch_dir() + "det_a" + ext, b = scratch_dir() + "det_b" + ext;
    vv::write_mesh(M, a);
    vv::write_mesh(M, b);
    EXPECT_EQ(slurp(a), slurp(b)) << ext;
    EXPECT_FALSE(slurp(a).empty()) << ext;
  }
  // The same mesh read into another context writes the same files.
  G::context other;
  Mesh N(other);
  vv::read_vvm(N, pyramid_path);
  for (const char* ext : {".vvm", ".obj"}) {
    const std::string a = scratch_dir() + "det_a" + ext, c = scratch_dir() + "det_c" + ext;
    vv::write_mesh(N, c);
    EXPECT_EQ(slurp(a), slurp(c)) << ext;
  }
}

TEST(Determinism, WritingLeavesNoTemporaryFiles) {
  G::context ctx;
  Mesh M(ctx);
  vv::read_vvm(M, pyramid_path);
  const std::string a = scratch_dir() + "tmpcheck.obj";
  std::filesystem::remove(a);
  vv::write_mesh(M, a);
  EXPECT_TRUE(exists(a));
  for (const auto& e : std::filesystem::directory_iterator(scratch_dir()))
    EXPECT_EQ(e.path().filename().string().find(".vvtmp"), std::string::npos) << e.path();
}

}  // namespace
