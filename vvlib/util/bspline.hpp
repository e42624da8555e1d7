// The cubic B-splines VLAB's editors draw over a control polygon:
//
// * clamped: knots 0,0,0,0, 1, 2, ..., n-3, n-2,n-2,n-2,n-2 over the
//   points P_0..P_n; the curve starts at P_0 and ends at P_n. Functions
//   and endpoint-interpolating contours use it (funcedit, cuspy).
// * uniform: the segments of the uniform cubic B-spline, one per four
//   consecutive points; a closed contour repeats its first three points at
//   the end, so the curve closes smoothly. The other contours use it.
#pragma once

#include <algorithm>
#include <vector>

#include "point.hpp"

namespace util::bspline {

//! A control point as the editors save it: a point of multiplicity m
//! stands m times in the polygon, pulling the curve towards it.
struct control_point {
  Point<double> pos;
  unsigned multiplicity = 1;

  //! The fields, for a model's checkpoint (model/state_values.hpp).
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos);
    f("multiplicity", multiplicity);
  }

  friend bool operator==(const control_point& a, const control_point& b) {
    return a.pos == b.pos && a.multiplicity == b.multiplicity;
  }
  friend bool operator!=(const control_point& a, const control_point& b) { return !(a == b); }
};

//! The polygon the spline is built on: each point repeated by its multiplicity.
inline std::vector<Point<double>> expand(const std::vector<control_point>& points) {
  std::vector<Point<double>> polygon;
  for (const control_point& p : points) polygon.insert(polygon.end(), p.multiplicity, p.pos);
  return polygon;
}

//! The parameter range of the clamped spline over `polygon`: u in [0, n-2].
inline double clamped_end(const std::vector<Point<double>>& polygon) {
  return static_cast<double>(polygon.size()) - 3.0;
}

//! The clamped spline at u in [0, clamped_end(polygon)] (de Boor's
//! algorithm); needs at least four points.
inline Point<double> clamped(const std::vector<Point<double>>& polygon, double u) {
  const int n = static_cast<int>(polygon.size()) - 1;
  u = std::clamp(u, 0.0, static_cast<double>(n - 2));
  const int span = std::min(static_cast<int>(u), n - 3);  // u in [span, span + 1]
  auto knot = [n](int j) { return static_cast<double>(std::clamp(j - 3, 0, n - 2)); };
  Point<double> d[4] = {polygon[span], polygon[span + 1], polygon[span + 2], polygon[span + 3]};
  for (int r = 1; r <= 3; ++r)
    for (int j = 3; j >= r; --j) {
      const int g = span + j;  // d[j] stands for P_g
      const double a = (u - knot(g)) / (knot(g + 4 - r) - knot(g));
      d[j] = (1.0 - a) * d[j - 1] + a * d[j];
    }
  return d[3];
}

//! One segment of the uniform cubic B-spline over g[0..3] at p in [0, 1].
inline Point<double> uniform_segment(const Point<double>* g, double p) {
  const double q = 1.0 - p;
  const double b0 = q * q * q / 6.0;
  const double b1 = (3.0 * p * p * p - 6.0 * p * p + 4.0) / 6.0;
  const double b2 = (-3.0 * p * p * p + 3.0 * p * p + 3.0 * p + 1.0) / 6.0;
  const double b3 = p * p * p / 6.0;
  return b0 * g[0] + b1 * g[1] + b2 * g[2] + b3 * g[3];
}

//! The uniform spline over `polygon` (at least four points; a closed
//! curve's polygon already ends with its first three points again) at t in
//! [0, 1]: the segments share [0, 1] equally.
inline Point<double> uniform(const std::vector<Point<double>>& polygon, double t) {
  const int segments = static_cast<int>(polygon.size()) - 3;
  const double u = std::clamp(t, 0.0, 1.0) * segments;
  const int s = std::min(static_cast<int>(u), segments - 1);
  return uniform_segment(&polygon[static_cast<std::size_t>(s)], u - s);
}

}  // namespace util::bspline
