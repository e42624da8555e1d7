// examples/sierpinski.vvp against the gasket computed here from a list of
// triangles (each split into its three corner triangles per step): the
// corners and markers, the three faces around each marker, and the holes.
#include <set>

#include "oracle.hpp"

namespace {

using oracle::point;
using triangle = std::array<point, 3>;  // counter-clockwise

point mid(const point& a, const point& b) { return {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])}; }

point centre(const triangle& t) {
  point c;
  for (int i = 0; i < 3; ++i) c[i] = (t[0][i] + t[1][i] + t[2][i]) / 3.0;
  return c;
}

std::vector<triangle> gasket(const triangle& start, unsigned steps) {
  std::vector<triangle> t{start};
  for (unsigned s = 0; s < steps; ++s) {
    std::vector<triangle> next;
    for (const triangle& x : t) {
      point ab = mid(x[0], x[1]), bc = mid(x[1], x[2]), ca = mid(x[2], x[0]);
      next.push_back({x[0], ab, ca});
      next.push_back({ab, x[1], bc});
      next.push_back({ca, bc, x[2]});
    }
    t = next;
  }
  return t;
}

std::size_t power3(unsigned k) { return k == 0 ? 1 : 3 * power3(k - 1); }

}  // namespace

TEST(SierpinskiOracle, TriangleEqualsListOfTriangles) {
  const unsigned k = 5;
  oracle::polygons base = oracle::read_polygons(std::string(VV_SOURCE_DIR) + "/models/triangle.vvm");
  ASSERT_EQ(base.points.size(), 3u);
  oracle::polygons ours = oracle::run_example("examples/sierpinski.vvp", "", k);
  std::vector<triangle> kept = gasket({base.points[0], base.points[1], base.points[2]}, k);
  ASSERT_EQ(kept.size(), power3(k));

  // The expected vertices: every corner once, and a marker per triangle;
  // the expected faces: the three triangles around each marker.
  oracle::polygons theirs;
  std::set<point> corners;
  for (const triangle& t : kept) corners.insert(t.begin(), t.end());
  ASSERT_EQ(corners.size(), (3 * power3(k) + 3) / 2);
  theirs.points.assign(corners.begin(), corners.end());
  auto index = [&](const point& p) {
    return static_cast<std::uint32_t>(std::lower_bound(theirs.points.begin(), theirs.points.end(), p) -
                                      theirs.points.begin());
  };
  std::vector<std::uint32_t> corner_of[3];
  for (const triangle& t : kept)
    for (int i = 0; i < 3; ++i) corner_of[i].push_back(index(t[i]));
  for (std::size_t j = 0; j < kept.size(); ++j) {
    std::uint32_t m = static_cast<std::uint32_t>(theirs.points.size());
    theirs.points.push_back(centre(kept[j]));
    for (int i = 0; i < 3; ++i) theirs.faces.push_back({corner_of[i][j], corner_of[(i + 1) % 3][j], m});
  }
  double tol = 1e-9 * oracle::size_of(base.points);
  oracle::expect_same_points(ours.points, theirs.points, tol);

  // Our faces around markers are those; the others are the holes, one per
  // removed triangle ((3^k - 1) / 2), and the back of the triangle, and
  // they have corners only.
  std::vector<point> markers(theirs.points.begin() + long(corners.size()), theirs.points.end());
  auto is_marker = [&](const point& p) {
    for (const point& q : markers)
      if (std::fabs(p[0] - q[0]) <= tol && std::fabs(p[1] - q[1]) <= tol && std::fabs(p[2] - q[2]) <= tol)
        return true;
    return false;
  };
  oracle::polygons fans{ours.points, {}};
  std::size_t others = 0;
  for (const auto& f : ours.faces) {
    bool around_marker = std::any_of(f.begin(), f.end(), [&](std::uint32_t i) { return is_marker(ours.points[i]); });
    if (around_marker) fans.faces.push_back(f);
    else ++others;
  }
  oracle::expect_same_faces(fans, theirs, tol);
  EXPECT_EQ(others, (power3(k) - 1) / 2 + 1);
}
