// The dual stellar schemes: examples/stellar_doo_sabin.vvp against CGAL's
// DooSabin_subdivision (equal where every face is a quad, measured where
// it is not), and examples/stellar_peters.vvp against positions worked out
// by hand on the cube.

#include "oracle.hpp"
#include "peers.hpp"

#include <map>

namespace {

using oracle::counts;
using oracle::counts_of;
using oracle::doo_sabin_counts;
using oracle::expect_counts;

using oracle::model;

using peers::cgal_doo_sabin;

double distance(const oracle::point& p, const oracle::point& q) {
  return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
}

// Faces as cyclic sequences of point numbers, each starting at its least.
std::vector<std::vector<std::uint32_t>> cyclic_faces(std::vector<std::vector<std::uint32_t>> faces) {
  for (auto& f : faces) std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
  std::sort(faces.begin(), faces.end());
  return faces;
}

// The largest distance between corresponding points of two meshes with the
// same connectivity but other positions. Each of ours is paired with the
// nearest of theirs; the pairing counts only when it is one-to-one and
// takes every face of ours to a face of theirs (then it is the
// correspondence, not a near miss), else the result is infinite.
double largest_difference(const oracle::polygons& ours, const oracle::polygons& theirs) {
  if (ours.points.size() != theirs.points.size()) return INFINITY;
  std::vector<std::uint32_t> partner(ours.points.size());
  std::vector<bool> taken(theirs.points.size(), false);
  double largest = 0;
  for (std::size_t i = 0; i < ours.points.size(); ++i) {
    std::size_t best = 0;
    for (std::size_t j = 1; j < theirs.points.size(); ++j)
      if (distance(ours.points[i], theirs.points[j]) < distance(ours.points[i], theirs.points[best])) best = j;
    if (taken[best]) return INFINITY;
    taken[best] = true;
    partner[i] = static_cast<std::uint32_t>(best);
    largest = std::max(largest, distance(ours.points[i], theirs.points[best]));
  }
  std::vector<std::vector<std::uint32_t>> mapped = ours.faces;
  for (auto& f : mapped)
    for (std::uint32_t& i : f) i = partner[i];
  if (cyclic_faces(mapped) != cyclic_faces(theirs.faces)) return INFINITY;
  return largest;
}

// How many faces have each number of corners.
std::map<std::size_t, std::size_t> face_sizes(const oracle::polygons& p) {
  std::map<std::size_t, std::size_t> sizes;
  for (const auto& f : p.faces) ++sizes[f.size()];
  return sizes;
}

// Every signed permutation of (a, b, c), a, b, c >= 0, once (-0 == 0).
std::vector<oracle::point> signed_permutations(double a, double b, double c) {
  std::vector<oracle::point> out;
  std::array<double, 3> v{a, b, c};
  std::sort(v.begin(), v.end());
  do
    for (int s = 0; s < 8; ++s) {
      oracle::point p{v[0], v[1], v[2]};
      for (int i = 0; i < 3; ++i)
        if (s & (1 << i)) p[i] = -p[i];
      if (std::find(out.begin(), out.end(), p) == out.end()) out.push_back(p);
    }
  while (std::next_permutation(v.begin(), v.end()));
  return out;
}

}  // namespace

TEST(StellarDooSabinOracle, QuadTorusEqualsCgalAtEveryLevel) {
  // Every face a quad and every vertex of valence 4: the average of the
  // quad (corner, midpoint, centroid, midpoint) is Doo-Sabin's 9/16, 3/16,
  // 3/16, 1/16, and the mesh stays all quads.
  std::string input = model("torus_quad.vvm");
  oracle::polygons base = oracle::read_polygons(input);
  double tol = 1e-9 * oracle::size_of(base.points);
  counts expected = counts_of(base);
  for (unsigned level = 1; level <= 3; ++level) {
    SCOPED_TRACE("level " + std::to_string(level));
    expected = doo_sabin_counts(expected, 1);
    oracle::polygons ours = oracle::run_example("examples/stellar_doo_sabin.vvp", input, level);
    expect_counts(ours, expected);
    oracle::polygons theirs = cgal_doo_sabin(base, level);
    oracle::expect_same_points(ours.points, theirs.points, tol);
    oracle::expect_same_faces(ours, theirs, tol);
  }
}

TEST(StellarDooSabinOracle, CubeCountsAndFirstLevelEqualCgal) {
  oracle::polygons base = oracle::read_polygons(model("cube.vvm"));
  // 8/12/6 -> 24/48/26 -> 96/192/98 -> 384/768/386.
  counts expected[] = {{24, 48, 26}, {96, 192, 98}, {384, 768, 386}};
  for (unsigned level = 1; level <= 3; ++level) {
    SCOPED_TRACE("level " + std::to_string(level));
    expect_counts(oracle::run_example("examples/stellar_doo_sabin.vvp", "", level), expected[level - 1]);
  }
  // The cube's faces are quads: its first level is Doo-Sabin's.
  oracle::polygons ours = oracle::run_example("examples/stellar_doo_sabin.vvp", "", 1);
  oracle::polygons theirs = cgal_doo_sabin(base, 1);
  double tol = 1e-9 * oracle::size_of(base.points);
  oracle::expect_same_points(ours.points, theirs.points, tol);
  oracle::expect_same_faces(ours, theirs, tol);
}

TEST(StellarDooSabinOracle, CubeDiffersFromCgalOnlyByTheMeasuredBound) {
  // From the second level on, the cube's corners are triangles. There the
  // stellar rule, the average of corner, two edge midpoints and centroid,
  // gives the corner 7/12 and each other corner 5/24, where Doo-Sabin's
  // gives 2/3 and 1/6. On the cube of side 2 (diagonal 3.46), after two
  // levels, by hand: the first level's triangle at the corner (1, 1, 1) is
  // (1, 1/2, 1/2) and its two rotations; its corner (1, 1/2, 1/2) goes to
  // (19/24, 29/48, 29/48) by the stellar rule and to (5/6, 7/12, 7/12) by
  // Doo-Sabin's, sqrt(6)/48 = 0.0510310 apart, and nothing differs more.
  // After three levels, measured: 0.0446522 (1.3% of the diagonal). The
  // bounds bracket those figures.
  oracle::polygons base = oracle::read_polygons(model("cube.vvm"));
  const double by_hand = std::sqrt(6.0) / 48;
  const double low[] = {0, 0, by_hand - 1e-9, 0.04465}, high[] = {0, 0, by_hand + 1e-9, 0.04466};
  for (unsigned level = 2; level <= 3; ++level) {
    SCOPED_TRACE("level " + std::to_string(level));
    oracle::polygons ours = oracle::run_example("examples/stellar_doo_sabin.vvp", "", level);
    double difference = largest_difference(ours, cgal_doo_sabin(base, level));
    std::printf("stellar vs CGAL Doo-Sabin, cube, %u levels: largest difference %.6g\n", level, difference);
    EXPECT_LT(difference, high[level]);
    EXPECT_GT(difference, low[level]);  // the schemes do differ there
  }
}

TEST(StellarPetersByHand, CubeOneLevelIsTheCuboctahedron) {
  // The cube's corners are (+-1, +-1, +-1). One level puts a vertex at the
  // middle of each of its 12 edges: two coordinates +-1, the third 0. Each
  // old face becomes the square of its four edge midpoints, each old
  // corner the triangle of its three: 12 vertices, 24 edges (each has
  // valence 4), 6 + 8 faces.
  oracle::polygons ours = oracle::run_example("examples/stellar_peters.vvp", "", 1);
  expect_counts(ours, {12, 24, 14});
  oracle::expect_same_points(ours.points, signed_permutations(1, 1, 0), 1e-12);
  EXPECT_EQ(face_sizes(ours), (std::map<std::size_t, std::size_t>{{3, 8}, {4, 6}}));
}

TEST(StellarPetersByHand, CubeTwoLevels) {
  // The second level's vertices are the middles of the cuboctahedron's
  // 24 edges. An edge joins two midpoints of cube edges at one cube
  // corner, e.g. (1, 1, 0) and (1, 0, 1): its middle is (1, 1/2, 1/2).
  // So the 24 vertices are the signed permutations of (1, 1/2, 1/2).
  // Faces: 6 + 8 from the cuboctahedron's faces (4 and 3 corners) and 12
  // from its vertices (valence 4): 8 triangles, 18 quads; V = 24,
  // E = 2 * 24 = 48, F = 26 (the counts of one Doo-Sabin level).
  oracle::polygons ours = oracle::run_example("examples/stellar_peters.vvp", "", 2);
  expect_counts(ours, {24, 48, 26});
  oracle::expect_same_points(ours.points, signed_permutations(1, 0.5, 0.5), 1e-12);
  EXPECT_EQ(face_sizes(ours), (std::map<std::size_t, std::size_t>{{3, 8}, {4, 18}}));
}

TEST(StellarPetersByHand, QuadTorusCounts) {
  // A level: V = E, E = 2E (valence 4), F = F + V.
  std::string input = model("torus_quad.vvm");
  counts c = counts_of(oracle::read_polygons(input));
  for (unsigned level = 1; level <= 2; ++level) {
    SCOPED_TRACE("level " + std::to_string(level));
    c = {c.e, 2 * c.e, c.f + c.v};
    expect_counts(oracle::run_example("examples/stellar_peters.vvp", input, level), c);
  }
}
