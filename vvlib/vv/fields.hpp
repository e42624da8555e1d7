// Property structs as named fields, and property values as text.
//
// A property struct lists its fields through a member template
//     template <class F> void vv_fields(F&& f) { f("pos", pos); f("c", c); }
// (the translator generates it; C++ users write it). Files (.vvm) and the
// mesh exporters find fields by these names. A struct may also name the
// fields the program computes itself, which a file need not give (reading
// a file without them says nothing):
//     static constexpr const char* vv_computed_fields[] = {"c"};
// (a .vvp writes `computed double c;` in the block).
//
// Values are written with the type's `<<` and read with its `>>`, except
// that floating-point numbers (alone or as the coordinates of a point-like
// type with x(), y(), z()) are written in the shortest form that reads back
// exactly, and strings are taken whole.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>

namespace vv {

namespace detail {

// Accepts any field type, for the detection above.
struct any_field {
  template <class V>
  void operator()(const char*, V&) const noexcept {}
};
template <class T, class = void>
struct has_fields : std::false_type {};
template <class T>
struct has_fields<T, std::void_t<decltype(std::declval<T&>().vv_fields(any_field{}))>>
    : std::true_type {};

template <class T, class = void>
struct has_computed_fields : std::false_type {};
template <class T>
struct has_computed_fields<T, std::void_t<decltype(T::vv_computed_fields)>> : std::true_type {};

template <class T, class = void>
struct is_point_like : std::false_type {};
template <class T>
struct is_point_like<T, std::void_t<decltype(std::declval<const T&>().x()),
                                    decltype(std::declval<const T&>().y()),
                                    decltype(std::declval<const T&>().z())>>
    : std::is_floating_point<std::decay_t<decltype(std::declval<const T&>().x())>> {};

template <class T>
void write_float(std::string& out, T v) {
  char buf[64];
  auto res = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, res.ptr);
}

// Reads one number at `at` (after blanks) and moves past it. Everything
// to_chars writes comes back exactly, nan and inf included; a literal past
// the type's range is read as an infinity (as strtod does), whatever its
// exponent.
template <class T>
bool read_float(const char*& at, T& v) {
  char* end = nullptr;
  T x;
  if constexpr (std::is_same_v<T, float>) x = std::strtof(at, &end);
  else if constexpr (std::is_same_v<T, double>) x = std::strtod(at, &end);
  else x = std::strtold(at, &end);
  if (end == at) return false;
  at = end;
  v = x;
  return true;
}

inline bool only_space_left(std::istream& is) {
  is >> std::ws;
  return is.eof();
}

}  // namespace detail

//! Calls f(name, field) for every field of a property struct (none when it
//! declares no vv_fields).
template <class P, class F>
void for_each_field(P& props, F&& f) {
  using mutable_p = std::remove_const_t<P>;
  // vv_fields is usually not const-qualified; reading through it is safe.
  if constexpr (detail::has_fields<mutable_p>::value) const_cast<mutable_p&>(props).vv_fields(f);
}

//! Whether the program computes the field `name` of P itself (P lists it
//! in vv_computed_fields), so that a file need not give it.
template <class P>
bool is_computed_field(const char* name) {
  if constexpr (detail::has_computed_fields<P>::value) {
    for (const char* field : P::vv_computed_fields)
      if (std::strcmp(field, name) == 0) return true;
  }
  return false;
}

//! A property value as file text.
template <class T>
std::string value_to_text(const T& v) {
  std::string out;
  if constexpr (std::is_same_v<T, bool>) {
    out = v ? "1" : "0";
  } else if constexpr (std::is_floating_point_v<T>) {
    detail::write_float(out, v);
  } else if constexpr (std::is_convertible_v<const T&, std::string>) {
    out = std::string(v);
  } else if constexpr (detail::is_point_like<T>::value) {
    detail::write_float(out, v.x());
    out += ' ';
    detail::write_float(out, v.y());
    out += ' ';
    detail::write_float(out, v.z());
  } else {
    std::ostringstream os;
    os << std::setprecision(std::numeric_limits<double>::max_digits10) << v;
    out = os.str();
  }
  return out;
}

//! Parses file text into a property value; false when the text is not a
//! complete value of the type (the value is then unspecified).
template <class T>
bool text_to_value(const std::string& text, T& v) {
  if constexpr (std::is_same_v<T, bool>) {
    if (text == "1" || text == "true") return v = true, true;
    if (text == "0" || text == "false") return v = false, true;
    return false;
  } else if constexpr (std::is_floating_point_v<T>) {
    const char* end = text.c_str();
    if (!detail::read_float(end, v)) return false;
    while (*end == ' ' || *end == '\t' || *end == '\n' || *end == '\r') ++end;
    return *end == '\0';
  } else if constexpr (detail::is_point_like<T>::value) {
    // Three numbers, read as the scalars are (so nan and inf come back).
    using S = std::decay_t<decltype(std::declval<const T&>().x())>;
    S c[3];
    const char* at = text.c_str();
    for (S& x : c)
      if (!detail::read_float(at, x)) return false;
    while (*at == ' ' || *at == '\t' || *at == '\n' || *at == '\r') ++at;
    if (*at != '\0') return false;
    v = T(c[0], c[1], c[2]);
    return true;
  } else if constexpr (std::is_same_v<T, std::string>) {
    v = text;
    return true;
  } else {
    std::istringstream is(text);
    is >> v;
    return !is.fail() && detail::only_space_left(is);
  }
}

}  // namespace vv
