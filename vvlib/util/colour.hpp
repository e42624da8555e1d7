// util::Colour<T>: the vv 1.1 RGBA colour. Stored as a plain array so that
// c_data() can go straight to glColor4fv / glColor4dv.
#pragma once

#include <cstddef>
#include <istream>
#include <ostream>
#include <type_traits>

namespace util {

template <class T>
class Colour {
  // Scalar operators accept plain numbers only, never another colour.
  template <class S>
  using if_scalar = std::enable_if_t<std::is_arithmetic_v<S>, int>;

 public:
  using value_type = T;

  // Opaque black: alpha defaults to 1 everywhere, as in vv 1.1.
  Colour() : c_{T(0), T(0), T(0), T(1)} {}
  Colour(T r, T g, T b, T a = T(1)) : c_{r, g, b, a} {}

  const T& r() const { return c_[0]; }
  const T& g() const { return c_[1]; }
  const T& b() const { return c_[2]; }
  const T& a() const { return c_[3]; }

  Colour& r(T v) { c_[0] = v; return *this; }
  Colour& g(T v) { c_[1] = v; return *this; }
  Colour& b(T v) { c_[2] = v; return *this; }
  Colour& a(T v) { c_[3] = v; return *this; }

  const T& operator[](std::size_t i) const { return c_[i]; }
  T& operator[](std::size_t i) { return c_[i]; }

  const T* c_data() const { return c_; }
  T* data() { return c_; }
  const T* data() const { return c_; }

  // Linear interpolation of all four channels: t = 0 gives *this, t = 1
  // gives `other`. Written as a weighted sum so both ends are exact.
  Colour blend(const Colour& other, T t) const { return *this * (T(1) - t) + other * t; }

  // Arithmetic treats the colour as a 4-vector, alpha included, so that
  // sums of weighted colours (averaging) stay consistent.
  Colour& operator+=(const Colour& o) {
    for (std::size_t i = 0; i < 4; ++i) c_[i] += o.c_[i];
    return *this;
  }
  Colour& operator-=(const Colour& o) {
    for (std::size_t i = 0; i < 4; ++i) c_[i] -= o.c_[i];
    return *this;
  }
  template <class S, if_scalar<S> = 0>
  Colour& operator*=(S s) {
    for (std::size_t i = 0; i < 4; ++i) c_[i] = static_cast<T>(c_[i] * s);
    return *this;
  }
  template <class S, if_scalar<S> = 0>
  Colour& operator/=(S s) {
    for (std::size_t i = 0; i < 4; ++i) c_[i] = static_cast<T>(c_[i] / s);
    return *this;
  }

  friend Colour operator+(Colour x, const Colour& y) { return x += y; }
  friend Colour operator-(Colour x, const Colour& y) { return x -= y; }
  template <class S, if_scalar<S> = 0>
  friend Colour operator*(Colour c, S s) { return c *= s; }
  template <class S, if_scalar<S> = 0>
  friend Colour operator*(S s, Colour c) { return c *= s; }
  template <class S, if_scalar<S> = 0>
  friend Colour operator/(Colour c, S s) { return c /= s; }

  friend bool operator==(const Colour& x, const Colour& y) {
    for (std::size_t i = 0; i < 4; ++i)
      if (!(x.c_[i] == y.c_[i])) return false;
    return true;
  }
  friend bool operator!=(const Colour& x, const Colour& y) { return !(x == y); }

  friend std::ostream& operator<<(std::ostream& os, const Colour& c) {
    return os << c.r() << ' ' << c.g() << ' ' << c.b() << ' ' << c.a();
  }
  friend std::istream& operator>>(std::istream& is, Colour& c) {
    return is >> c.c_[0] >> c.c_[1] >> c.c_[2] >> c.c_[3];
  }

 private:
  T c_[4];
};

}  // namespace util
