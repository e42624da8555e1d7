// util::Point<T>: the vv 1.1 3-vector, kept source-compatible with programs
// written against vv 1.1 (member names, `*` as dot product, scalar operators
// on either side) while storing its coordinates as a GLM vector.
#pragma once

#include <cmath>
#include <cstddef>
#include <istream>
#include <ostream>
#include <type_traits>

#include <glm/glm.hpp>

#include "first_room_vector.hpp"

namespace util {

namespace detail {
// Restricts the scalar operator templates to plain numbers, so that
// `p * q` between two points can only mean the dot product.
template <class S>
using if_scalar = std::enable_if_t<std::is_arithmetic_v<S>, int>;
}  // namespace detail

template <class T>
class Point {
 public:
  using value_type = T;
  // Spelled with a leading :: because the member function glm() hides the
  // namespace name inside the class.
  using vec_type = ::glm::vec<3, T>;

  // GLM leaves a default-constructed vector uninitialised; vv 1.1 zeroed it.
  Point() : v_(T(0)) {}
  //! A point of the xy-plane (z = 0), as vv 1.1 programs write 2D points.
  Point(T x, T y) : v_(x, y, T(0)) {}
  Point(T x, T y, T z) : v_(x, y, z) {}
  explicit Point(const vec_type& v) : v_(v) {}
  template <class U>
  explicit Point(const Point<U>& o) : v_(o.glm()) {}

  const vec_type& glm() const { return v_; }
  vec_type& glm() { return v_; }

  const T& x() const { return v_.x; }
  const T& y() const { return v_.y; }
  const T& z() const { return v_.z; }
  // Non-const getters let old code write `p.x() += d`.
  T& x() { return v_.x; }
  T& y() { return v_.y; }
  T& z() { return v_.z; }

  Point& x(T v) { v_.x = v; return *this; }
  Point& y(T v) { v_.y = v; return *this; }
  Point& z(T v) { v_.z = v; return *this; }

  Point& set(T x, T y, T z) {
    v_ = vec_type(x, y, z);
    return *this;
  }
  Point& zero() { return set(T(0), T(0), T(0)); }

  const T& operator[](std::size_t i) const { return v_[static_cast<::glm::length_t>(i)]; }
  T& operator[](std::size_t i) { return v_[static_cast<::glm::length_t>(i)]; }

  // GLM keeps x, y, z adjacent with no padding (checked by the
  // static_assert at the end), which glVertex3dv-style callers rely on.
  const T* c_data() const { return &v_.x; }
  T* data() { return &v_.x; }
  const T* data() const { return &v_.x; }

  // Hand-written rather than glm::dot/length/cross, which only accept
  // floating-point types; vv 1.1 also allowed Point<int>.
  T length_sq() const { return *this * *this; }
  T length() const { return static_cast<T>(std::sqrt(length_sq())); }
  T distance(const Point& p) const { return (*this - p).length(); }

  Point cross(const Point& p) const {
    return Point(y() * p.z() - z() * p.y(), z() * p.x() - x() * p.z(),
                 x() * p.y() - y() * p.x());
  }

  // A zero vector has no direction; leaving it zero avoids NaNs spreading
  // through a simulation.
  Point& normalise() {
    const T len = length();
    if (len > T(0)) *this /= len;
    return *this;
  }
  Point& normalize() { return normalise(); }

  Point& operator+=(const Point& p) {
    v_ += p.v_;
    return *this;
  }
  Point& operator-=(const Point& p) {
    v_ -= p.v_;
    return *this;
  }
  // Each product is formed in the usual arithmetic type of T and S, then
  // narrowed back: the point type never changes with the scalar's type.
  template <class S, detail::if_scalar<S> = 0>
  Point& operator*=(S s) {
    for (std::size_t i = 0; i < 3; ++i) (*this)[i] = static_cast<T>((*this)[i] * s);
    return *this;
  }
  template <class S, detail::if_scalar<S> = 0>
  Point& operator/=(S s) {
    for (std::size_t i = 0; i < 3; ++i) (*this)[i] = static_cast<T>((*this)[i] / s);
    return *this;
  }

  Point operator-() const { return Point(-x(), -y(), -z()); }

  friend Point operator+(Point a, const Point& b) { return a += b; }
  friend Point operator-(Point a, const Point& b) { return a -= b; }

  // vv 1.1 semantics: the product of two points is their dot product.
  friend T operator*(const Point& a, const Point& b) {
    return a.x() * b.x() + a.y() * b.y() + a.z() * b.z();
  }

  template <class S, detail::if_scalar<S> = 0>
  friend Point operator*(Point p, S s) { return p *= s; }
  template <class S, detail::if_scalar<S> = 0>
  friend Point operator*(S s, Point p) { return p *= s; }
  template <class S, detail::if_scalar<S> = 0>
  friend Point operator/(Point p, S s) { return p /= s; }

  // Component-wise and exact, as in vv 1.1.
  friend bool operator==(const Point& a, const Point& b) {
    return a.x() == b.x() && a.y() == b.y() && a.z() == b.z();
  }
  friend bool operator!=(const Point& a, const Point& b) { return !(a == b); }

  // Each coordinate goes through the stream as-is, so precision and other
  // flags set by the caller apply.
  friend std::ostream& operator<<(std::ostream& os, const Point& p) {
    return os << p.x() << ' ' << p.y() << ' ' << p.z();
  }
  friend std::istream& operator>>(std::istream& is, Point& p) {
    return is >> p.x() >> p.y() >> p.z();
  }

 private:
  vec_type v_;
  static_assert(sizeof(vec_type) == 3 * sizeof(T), "c_data() needs packed coordinates");
};

}  // namespace util

//! A vector of points (a face's corner positions, a contour's) makes room
//! for four at its first push (util/first_room_vector.hpp).
template <class T>
class std::vector<util::Point<T>, std::allocator<util::Point<T>>>
    : public util::detail::first_room_vector<util::Point<T>, util::detail::own_allocator<util::Point<T>>, 4> {
  using base = util::detail::first_room_vector<util::Point<T>, util::detail::own_allocator<util::Point<T>>, 4>;

 public:
  // Its own default, copy and move members are the implicit ones.
  using base::base;
  using base::operator=;
};

// vv 1.1 programs include only <util/point.hpp> yet call the geometry
// helpers; the include sits last so Point is complete when they are seen.
#include "geometry.hpp"
