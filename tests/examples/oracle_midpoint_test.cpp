// examples/midpoint.vvp against a plain 1-to-4 split of triangles written
// here and against CGAL's primal triangle quadrisection (PTQ) with a linear
// mask (edge points at midpoints, vertices unchanged), on the double pyramid
// and on a scanned mesh (CGAL's cow): points and faces.
//
// OpenMesh's Uniform::MidpointT is a different scheme: it replaces the
// vertices by the edge midpoints and makes a face of the midpoints around
// each old face and each old vertex (a triangle becomes one triangle, the
// old vertices disappear), so it is not used here.
#include <map>

#include "oracle.hpp"
#include "peers.hpp"

namespace {

// Each triangle (a, b, c) becomes (a, ab, ca), (ab, b, bc), (ca, bc, c)
// and (ab, bc, ca), with new points at the edge midpoints.
oracle::polygons split(oracle::polygons p, unsigned steps) {
  for (unsigned s = 0; s < steps; ++s) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> middle;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      auto key = std::minmax(a, b);
      auto found = middle.find(key);
      if (found != middle.end()) return found->second;
      const oracle::point &pa = p.points[a], &pb = p.points[b];
      p.points.push_back({0.5 * (pa[0] + pb[0]), 0.5 * (pa[1] + pb[1]), 0.5 * (pa[2] + pb[2])});
      std::uint32_t m = static_cast<std::uint32_t>(p.points.size() - 1);
      middle.emplace(key, m);
      return m;
    };
    std::vector<std::vector<std::uint32_t>> faces;
    for (const auto& f : p.faces) {
      EXPECT_EQ(f.size(), 3u) << "not a triangle";
      std::uint32_t a = f[0], b = f[1], c = f[2];
      std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      faces.push_back({a, ab, ca});
      faces.push_back({ab, b, bc});
      faces.push_back({ca, bc, c});
      faces.push_back({ab, bc, ca});
    }
    p.faces = faces;
  }
  return p;
}

void check(const oracle::polygons& base, const oracle::polygons& ours, unsigned steps) {
  // Each step adds a vertex per edge and makes four triangles of each.
  std::size_t v = base.points.size(), e = 3 * base.faces.size() / 2, f = base.faces.size();
  for (unsigned i = 0; i < steps; ++i) v += e, e = 2 * e + 3 * f, f *= 4;
  ASSERT_EQ(ours.points.size(), v);
  ASSERT_EQ(ours.faces.size(), f);
  double tol = 1e-9 * oracle::size_of(base.points);
  oracle::polygons plain = split(base, steps), cgal = peers::cgal_midpoint(base, steps);
  oracle::expect_same_points(ours.points, plain.points, tol);
  oracle::expect_same_faces(ours, plain, tol);
  oracle::expect_same_points(ours.points, cgal.points, tol);
  oracle::expect_same_faces(ours, cgal, tol);
  // The old vertices do not move: the export lists them first.
  for (std::size_t i = 0; i < base.points.size(); ++i) EXPECT_EQ(ours.points[i], base.points[i]) << "vertex " << i;
}

}  // namespace

TEST(MidpointOracle, PyramidEqualsPlainSplitAndCgal) {
  oracle::polygons base = oracle::read_polygons(std::string(VV_SOURCE_DIR) + "/models/pyramid.vvm");
  oracle::polygons ours = oracle::run_example("examples/midpoint.vvp", "", 3);
  check(base, ours, 3);
}

TEST(MidpointOracle, ScannedCowEqualsPlainSplitAndCgal) {
  std::string input = oracle::input_vvm("cow", oracle::cgal_mesh_file("cow.off"));
  oracle::polygons base = oracle::read_polygons(input);
  oracle::polygons ours = oracle::run_example("examples/midpoint.vvp", input, 2);
  check(base, ours, 2);
}
