// Geometry helpers of vv 1.1 (constants, clamping, angles and the planar
// tools used by 2D models). "Planar" functions look only at x and y.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include "point.hpp"

namespace util {

constexpr double pi = 3.14159265358979323846;
constexpr double two_pi = 2.0 * pi;

namespace detail {
// Keeps a parameter out of template deduction, so `planar_rotation(p, 0.5)`
// works for Point<float> too (std::type_identity is C++20).
template <class T>
struct identity {
  using type = T;
};
template <class T>
using identity_t = typename identity<T>::type;

// z component of the cross product of the xy projections.
template <class T>
T cross_z(const Point<T>& a, const Point<T>& b) {
  return a.x() * b.y() - a.y() * b.x();
}
}  // namespace detail

// Mixed argument types are common in old programs (`clamp(x, 0, 1)` with a
// double x); everything is compared in the common type to stay exact and
// free of sign-compare surprises.
template <class X, class L, class H>
constexpr std::common_type_t<X, L, H> clamp(X x, L lo, H hi) {
  using C = std::common_type_t<X, L, H>;
  const C v = static_cast<C>(x);
  const C l = static_cast<C>(lo);
  const C h = static_cast<C>(hi);
  return v < l ? l : (h < v ? h : v);
}

// True iff lo <= x <= hi (note vv 1.1's argument order: the value is last).
template <class L, class H, class X>
constexpr bool range_closed(L lo, H hi, X x) {
  using C = std::common_type_t<L, H, X>;
  return static_cast<C>(lo) <= static_cast<C>(x) && static_cast<C>(x) <= static_cast<C>(hi);
}

// Unsigned angle in [0, pi]. atan2 of |a x b| and a.b stays accurate near
// 0 and pi where acos of the normalised dot product loses digits, and it
// yields 0 for a zero vector without dividing by its length.
template <class T>
T angle(const Point<T>& a, const Point<T>& b) {
  if (a.length_sq() == T(0) || b.length_sq() == T(0)) return T(0);
  return static_cast<T>(std::atan2(a.cross(b).length(), a * b));
}

// Signed area of triangle abc projected on the xy plane; positive when
// a, b, c turn counter-clockwise.
template <class T>
T planar_triangle_area(const Point<T>& a, const Point<T>& b, const Point<T>& c) {
  return detail::cross_z(b - a, c - a) / T(2);
}

// Intersects the lines a1a2 and b1b2 in the xy plane. On success sets ia and
// ib so that a1 + ia*(a2-a1) == b1 + ib*(b2-b1). Parallel or degenerate lines
// return false and leave ia, ib untouched.
template <class T>
bool planar_line_intersection(const Point<T>& a1, const Point<T>& a2, const Point<T>& b1,
                              const Point<T>& b2, T& ia, T& ib) {
  const Point<T> da = a2 - a1;
  const Point<T> db = b2 - b1;
  const Point<T> w = b1 - a1;
  const T denom = detail::cross_z(da, db);
  // denom = |da||db| sin(theta): comparing against the lengths makes the
  // parallel test independent of scale. For integer T the tolerance is 0.
  const T tol = std::numeric_limits<T>::epsilon() * T(8);
  const T la = std::sqrt(da.x() * da.x() + da.y() * da.y());
  const T lb = std::sqrt(db.x() * db.x() + db.y() * db.y());
  if (std::abs(denom) <= tol * la * lb) return false;
  ia = detail::cross_z(w, db) / denom;
  ib = detail::cross_z(w, da) / denom;
  return true;
}

// vv 1.1's form: the point where the lines a1a2 and b1b2 cross in the
// xy-plane (z = 0). ia tells whether it lies on the segment a1-a2, ends
// included; ib the same for b1-b2. Parallel (or degenerate) lines give
// Point() with both false.
template <class T>
Point<T> planar_line_intersection(const Point<T>& a1, const Point<T>& a2, const Point<T>& b1,
                                  const Point<T>& b2, bool& ia, bool& ib) {
  T sa = 0, sb = 0;
  if (!planar_line_intersection(a1, a2, b1, b2, sa, sb)) {
    ia = ib = false;
    return Point<T>();
  }
  // An end point computed through a division may land a rounding error
  // outside [0, 1]: ends are included all the same.
  const T tol = std::numeric_limits<T>::epsilon() * T(8);
  ia = sa >= -tol && sa <= T(1) + tol;
  ib = sb >= -tol && sb <= T(1) + tol;
  return Point<T>(a1.x() + sa * (a2.x() - a1.x()), a1.y() + sa * (a2.y() - a1.y()), T(0));
}

// v rotated counter-clockwise by theta radians about the z axis.
template <class T>
Point<T> planar_rotation(const Point<T>& v, detail::identity_t<T> theta) {
  const T c = std::cos(theta);
  const T s = std::sin(theta);
  return Point<T>(v.x() * c - v.y() * s, v.x() * s + v.y() * c, v.z());
}

}  // namespace util
