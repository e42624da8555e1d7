// examples/bspline_curve.vvp, four_point.vvp and chaikin.vvp against the
// same masks applied to plain arrays of points, on the hexagon and on the
// square; and two properties of the schemes: the B-spline polygons approach
// the limit points 1/6 (a + 4 v + b) of the control polygon, and the
// four-point scheme keeps the control points exactly.
#include "oracle.hpp"

namespace {

using oracle::point;
using curve = std::vector<point>;  // a closed polygon, in order

point mix(double wa, const point& a, double wb, const point& b) {
  return {wa * a[0] + wb * b[0], wa * a[1] + wb * b[1], wa * a[2] + wb * b[2]};
}

point add(const point& a, const point& b) { return mix(1, a, 1, b); }

bool close(const point& a, const point& b, double tol) {
  return std::fabs(a[0] - b[0]) <= tol && std::fabs(a[1] - b[1]) <= tol && std::fabs(a[2] - b[2]) <= tol;
}

// Uniform cubic B-spline: vertex 3/4 v + 1/8 (a + b), edge midpoint.
curve bspline(curve c, unsigned steps) {
  for (unsigned s = 0; s < steps; ++s) {
    std::size_t n = c.size();
    curve out(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
      const point &a = c[(i + n - 1) % n], &v = c[i], &b = c[(i + 1) % n];
      out[2 * i] = mix(0.75, v, 0.125, add(a, b));
      out[2 * i + 1] = mix(0.5, v, 0.5, b);
    }
    c = out;
  }
  return c;
}

// Dyn-Levin-Gregory: old points stay, edge a-b gets 9/16 (a + b) - 1/16 (c + d).
curve four_point(curve c, unsigned steps) {
  for (unsigned s = 0; s < steps; ++s) {
    std::size_t n = c.size();
    curve out(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
      const point &c0 = c[(i + n - 1) % n], &a = c[i], &b = c[(i + 1) % n], &d = c[(i + 2) % n];
      out[2 * i] = a;
      out[2 * i + 1] = mix(9.0 / 16, add(a, b), -1.0 / 16, add(c0, d));
    }
    c = out;
  }
  return c;
}

// Chaikin: edge a-b gives 3/4 a + 1/4 b and 1/4 a + 3/4 b; old points go.
curve chaikin(curve c, unsigned steps) {
  for (unsigned s = 0; s < steps; ++s) {
    std::size_t n = c.size();
    curve out(2 * n);
    for (std::size_t i = 0; i < n; ++i) {
      const point &a = c[i], &b = c[(i + 1) % n];
      out[2 * i] = mix(0.75, a, 0.25, b);
      out[2 * i + 1] = mix(0.25, a, 0.75, b);
    }
    c = out;
  }
  return c;
}

// The polygon of an exported curve: its two face orbits are the same
// cycle walked both ways; the first gives the order.
curve cycle_of(const oracle::polygons& p) {
  curve c;
  EXPECT_EQ(p.faces.size(), 2u) << "a closed polygon has two face orbits";
  if (p.faces.empty()) return c;
  EXPECT_EQ(p.faces[0].size(), p.points.size()) << "the polygon is not one cycle";
  for (std::uint32_t i : p.faces[0]) c.push_back(p.points[i]);
  return c;
}

// The same closed polygon: equal point by point from some starting point,
// in one direction or the other.
void expect_same_cycle(const curve& ours, const curve& theirs, double tol) {
  ASSERT_EQ(ours.size(), theirs.size());
  std::size_t n = ours.size();
  for (int dir : {1, -1})
    for (std::size_t r = 0; r < n; ++r) {
      std::size_t i = 0;
      auto at = [&](std::size_t k) { return dir > 0 ? (r + k) % n : (r + n - k) % n; };
      while (i < n && close(ours[at(i)], theirs[i], tol)) ++i;
      if (i == n) return;
    }
  ADD_FAILURE() << "no rotation or reflection of the example's polygon matches the expected one";
}

std::string model(const std::string& name) { return oracle::model(name + ".vvm"); }

const char* const inputs[] = {"hexagon", "square"};
constexpr unsigned steps = 5;
constexpr double tol = 1e-12;

void check_against_arrays(const std::string& example, curve (*scheme)(curve, unsigned)) {
  for (const char* name : inputs) {
    SCOPED_TRACE(example + " on " + name);
    oracle::polygons base = oracle::read_polygons(model(name));
    curve control = cycle_of(base);
    oracle::polygons ours = oracle::run_example(example, model(name), steps);
    ASSERT_EQ(ours.points.size(), control.size() << steps);
    curve expected = scheme(control, steps);
    oracle::expect_same_points(ours.points, expected, tol);
    expect_same_cycle(cycle_of(ours), expected, tol);
  }
}

}  // namespace

TEST(CurvesOracle, BsplineEqualsArrayMasks) { check_against_arrays("examples/bspline_curve.vvp", bspline); }

TEST(CurvesOracle, FourPointEqualsArrayMasks) { check_against_arrays("examples/four_point.vvp", four_point); }

TEST(CurvesOracle, ChaikinEqualsArrayMasks) { check_against_arrays("examples/chaikin.vvp", chaikin); }

// An old vertex of the B-spline scheme converges to its limit point
// 1/6 (a + 4 v + b): v - L = -(a - 2 v + b) / 6 is a second difference,
// which each step divides by 4 (the local subdivision matrix's eigenvalues
// are 1, 1/2, 1/4), and the limit point computed from the refined polygon
// stays the same at every level.
TEST(CurvesOracle, BsplineApproachesLimitPoints) {
  const unsigned k = 10;
  for (const char* name : inputs) {
    SCOPED_TRACE(name);
    oracle::polygons base = oracle::read_polygons(model(name));
    oracle::polygons ours = oracle::run_example("examples/bspline_curve.vvp", model(name), k);
    ASSERT_EQ(ours.points.size(), base.points.size() << k);
    // The example keeps the old vertices first in its mesh, new ones after:
    // the first points of the export are the control vertices, in file order.
    curve refined = cycle_of(ours);
    std::vector<std::size_t> at(ours.points.size());  // place of each point on the cycle
    for (std::size_t i = 0; i < ours.faces[0].size(); ++i) at[ours.faces[0][i]] = i;
    std::size_t n = base.points.size(), m = refined.size();
    for (std::size_t i = 0; i < n; ++i) {
      // The control vertex's neighbours in the control polygon.
      std::size_t j = 0;
      while (base.faces[0][j] != i) ++j;
      const point& a = base.points[base.faces[0][(j + n - 1) % n]];
      const point& b = base.points[base.faces[0][(j + 1) % n]];
      point limit = mix(1.0 / 6, add(a, b), 4.0 / 6, base.points[i]);
      double size = oracle::size_of(base.points);
      EXPECT_TRUE(close(ours.points[i], limit, size * std::pow(0.25, k)))
          << "vertex " << i << " is not within " << size * std::pow(0.25, k) << " of its limit point";
      // Exactly: v_k - L = 4^-k (v_0 - L), the second difference shrinking by 4.
      point expected = mix(1, limit, std::pow(0.25, k), mix(1, base.points[i], -1, limit));
      EXPECT_TRUE(close(ours.points[i], expected, tol)) << "vertex " << i << " does not converge at rate 1/4";
      // The limit point of the refined polygon at the same vertex.
      std::size_t c = at[i];
      point again = mix(1.0 / 6, add(refined[(c + m - 1) % m], refined[(c + 1) % m]), 4.0 / 6, ours.points[i]);
      EXPECT_TRUE(close(again, limit, tol)) << "vertex " << i << ": the limit point moved";
    }
  }
}

// The four-point scheme interpolates: every control point is in the
// refined polygon, unchanged to the last bit.
TEST(CurvesOracle, FourPointKeepsControlPoints) {
  for (const char* name : inputs) {
    SCOPED_TRACE(name);
    oracle::polygons base = oracle::read_polygons(model(name));
    oracle::polygons ours = oracle::run_example("examples/four_point.vvp", model(name), steps);
    for (std::size_t i = 0; i < base.points.size(); ++i) {
      EXPECT_EQ(ours.points[i], base.points[i]) << "control point " << i << " moved";
      EXPECT_NE(std::find(ours.points.begin(), ours.points.end(), base.points[i]), ours.points.end());
    }
  }
}
