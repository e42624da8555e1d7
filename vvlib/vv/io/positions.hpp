// Where a vertex's position is: the property named `pos`, of any type with
// x(), y(), z() (util::Point) or with [0..2] (GLM vectors, arrays).
#pragma once

#include <array>
#include <type_traits>
#include <utility>

namespace vv::detail {

template <class P, class = void>
struct has_pos : std::false_type {};
template <class P>
struct has_pos<P, std::void_t<decltype(std::declval<P&>().pos)>> : std::true_type {};

template <class T, class = void>
struct indexable3 : std::false_type {};
template <class T>
struct indexable3<T, std::void_t<decltype(double(std::declval<T&>()[0]))>> : std::true_type {};

template <class T>
std::array<double, 3> xyz_of(const T& p) {
  if constexpr (indexable3<T>::value)
    return {double(p[0]), double(p[1]), double(p[2])};
  else
    return {double(p.x()), double(p.y()), double(p.z())};
}

template <class T>
void set_xyz(T& p, const std::array<double, 3>& xyz) {
  if constexpr (indexable3<T>::value) {
    using C = std::decay_t<decltype(p[0])>;
    p[0] = C(xyz[0]), p[1] = C(xyz[1]), p[2] = C(xyz[2]);
  } else {
    using C = std::decay_t<decltype(p.x())>;
    p.x(C(xyz[0])), p.y(C(xyz[1])), p.z(C(xyz[2]));
  }
}

}  // namespace vv::detail
