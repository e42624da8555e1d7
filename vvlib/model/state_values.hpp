// The values of a model's saved state (model/state.hpp): one walk over a
// value that saves it, restores it, or checks that it can be saved, chosen
// by the walk's mode. What it knows:
//
//   numbers, bool, enums, std::string; util::Point and GLM vectors and
//   matrices; std::array, C arrays, std::vector, std::deque, std::list,
//   std::map, std::multimap, std::set, std::multiset, std::pair,
//   std::tuple, std::optional of what it knows; vertex handles (by their
//   slot: the context is restored first, slot for slot); meshes (their
//   members in order and their properties); generators and distributions
//   of <random> (their text form, which the standard makes exact); structs
//   that list their fields (vv_state_fields, which vvc writes for property
//   blocks, or vv_fields), among them the file objects util::Function,
//   Contour, Palette and Materials (their file's name and their contents,
//   which the program may have changed); util::Colour; classes without
//   data (algorithms::Insert).
//
// Anything else cannot be saved (a pointer, a std::function, an unordered
// container, whose order a restore cannot promise, a struct that does not
// list its fields): the check names it and why.
#pragma once

#include <cxxabi.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <deque>
#include <functional>
#include <limits>
#include <list>
#include <locale>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <type_traits>
#include <typeinfo>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include <util/colour.hpp>
#include <util/point.hpp>
#include <vv/context.hpp>
#include <vv/mesh.hpp>
#include <vv/vertex.hpp>

#include "state_stream.hpp"

namespace vv::model {

enum class state_mode { save, load, check };

//! Saving: values to bytes. Every vertex handle met is counted against its
//! slot, so that the save can tell a vertex held by something it did not
//! see (its count would not come back).
template <class Tr>
struct state_saving {
  static constexpr state_mode mode = state_mode::save;
  state_writer& out;
  context<Tr>& ctx;
  std::vector<std::uint32_t>& handles;
};

template <class Tr>
struct state_loading {
  static constexpr state_mode mode = state_mode::load;
  state_reader& in;
  context<Tr>& ctx;
};

//! Checking: the first thing that cannot be saved, and why ("" when all can).
struct state_checking {
  static constexpr state_mode mode = state_mode::check;
  std::string problem;
};

namespace state_detail {

//! A type's name as C++ spells it (demangled), for messages.
template <class T>
std::string type_name() {
  int status = 0;
  char* name = abi::__cxa_demangle(typeid(T).name(), nullptr, nullptr, &status);
  std::string out = name ? name : typeid(T).name();
  std::free(name);
  return out;
}

template <class T, template <class...> class Of>
struct is_instance : std::false_type {};
template <template <class...> class Of, class... A>
struct is_instance<Of<A...>, Of> : std::true_type {};

template <class T>
struct is_std_array : std::false_type {};
template <class T, std::size_t N>
struct is_std_array<std::array<T, N>> : std::true_type {};

template <class T>
struct is_glm_vec : std::false_type {};
template <glm::length_t L, class S, glm::qualifier Q>
struct is_glm_vec<glm::vec<L, S, Q>> : std::true_type {};
template <class T>
struct is_glm_mat : std::false_type {};
template <glm::length_t C, glm::length_t R, class S, glm::qualifier Q>
struct is_glm_mat<glm::mat<C, R, S, Q>> : std::true_type {};

template <class T>
struct is_vertex : std::false_type {};
template <class Tr>
struct is_vertex<vertex<Tr>> : std::true_type {};
template <class T>
struct is_mesh : std::false_type {};
template <class Tr>
struct is_mesh<mesh<Tr>> : std::true_type {};

// Generators and distributions of <random>: a result type and the stream
// operators, which the standard makes exact for them.
template <class T, class = void>
struct is_random_object : std::false_type {};
template <class T>
struct is_random_object<T, std::void_t<typename T::result_type,
                                        decltype(std::declval<std::ostream&>() << std::declval<const T&>()),
                                        decltype(std::declval<std::istream&>() >> std::declval<T&>())>>
    : std::true_type {};

template <class T>
constexpr bool is_sequence = is_instance<T, std::vector>::value || is_instance<T, std::deque>::value ||
                             is_instance<T, std::list>::value;
template <class T>
constexpr bool is_ordered_map = is_instance<T, std::map>::value || is_instance<T, std::multimap>::value;
template <class T>
constexpr bool is_ordered_set = is_instance<T, std::set>::value || is_instance<T, std::multiset>::value;
template <class T>
constexpr bool is_unordered = is_instance<T, std::unordered_map>::value ||
                              is_instance<T, std::unordered_multimap>::value ||
                              is_instance<T, std::unordered_set>::value ||
                              is_instance<T, std::unordered_multiset>::value;

template <class T, class = void>
struct has_state_fields : std::false_type {};
struct any_state_field {
  template <class V>
  void operator()(const char*, V&, int) const noexcept {}
};
template <class T>
struct has_state_fields<T, std::void_t<decltype(std::declval<T&>().vv_state_fields(any_state_field{}))>>
    : std::true_type {};

//! Guards the check of a type that contains itself (a tree of nodes).
template <class T>
struct being_checked {
  static bool& flag() {
    static thread_local bool on = false;
    return on;
  }
};

//! A number as its bytes, little-endian; long double by its 64-bit
//! significand and exponent (the rest of its storage is padding).
template <class A, class T>
void number(A& a, T& v) {
  if constexpr (A::mode == state_mode::check) {
    (void)&a, (void)&v;  // unused here (v may be volatile: no read)
  } else if constexpr (std::is_floating_point_v<T> && sizeof(T) > 8) {
    static_assert(std::numeric_limits<T>::digits == 64, "long double is the x87 80-bit format");
    unsigned char bytes[sizeof(T)] = {};
    if constexpr (A::mode == state_mode::save) {
      std::memcpy(bytes, &v, 10);
      for (int i = 0; i < 10; ++i) a.out.u8(bytes[i]);
    } else {
      for (int i = 0; i < 10; ++i) bytes[i] = a.in.u8("a number");
      std::memcpy(&v, bytes, sizeof(T));
    }
  } else if constexpr (std::is_floating_point_v<T>) {
    if constexpr (A::mode == state_mode::save) a.out.f64(static_cast<double>(v));
    else v = static_cast<T>(a.in.f64("a number"));
  } else {
    // An integer in as many bytes as its type has.
    if constexpr (A::mode == state_mode::save) {
      const auto bits = static_cast<std::uint64_t>(v);
      for (std::size_t i = 0; i < sizeof(T); ++i) a.out.u8(static_cast<std::uint8_t>(bits >> (8 * i)));
    } else {
      std::uint64_t bits = 0;
      for (std::size_t i = 0; i < sizeof(T); ++i) bits |= std::uint64_t(a.in.u8("a number")) << (8 * i);
      v = static_cast<T>(bits);
    }
  }
}

template <class A>
void size(A& a, std::size_t n) {
  if constexpr (A::mode == state_mode::save) a.out.u64(n);
}
template <class A>
std::size_t read_size(A& a) {
  return static_cast<std::size_t>(a.in.count("a size"));
}

}  // namespace state_detail

template <class A, class T>
void state_value(A& a, T& v);

//! A struct's fields (vv_state_fields, else vv_fields), in their order.
template <class A, class T>
void state_fields(A& a, T& object) {
  auto one = [&a](const char* name, auto& field, int line = 0) {
    if constexpr (A::mode == state_mode::check) {
      if (!a.problem.empty()) return;
      state_value(a, field);
      if (!a.problem.empty())
        a.problem = "field " + std::string(name) + (line ? " (line " + std::to_string(line) + ")" : std::string()) +
                    " of " + state_detail::type_name<T>() + ": " + a.problem;
    } else {
      state_value(a, field);
    }
  };
  if constexpr (state_detail::has_state_fields<T>::value) object.vv_state_fields(one);
  else object.vv_fields(one);
}

namespace state_detail {

template <class A, class T>
void cannot(A& a, const std::string& why) {
  if constexpr (A::mode == state_mode::check) {
    if (a.problem.empty()) a.problem = type_name<T>() + ": " + why;
  } else {
    throw state_error(type_name<T>() + ": " + why);
  }
}

//! A check of T through a value made for it (the element type of an empty
//! container); a type that holds itself is checked once.
template <class T>
void check_type(state_checking& a) {
  using U = std::remove_const_t<T>;
  if (!a.problem.empty() || being_checked<U>::flag()) return;
  if constexpr (!std::is_default_constructible_v<U>) {
    cannot<state_checking, U>(a, "it has no default constructor, which a restore needs");
  } else {
    being_checked<U>::flag() = true;
    try {
      U sample{};
      state_value(a, sample);
    } catch (const std::exception& e) {
      a.problem = type_name<U>() + ": " + e.what();
    }
    being_checked<U>::flag() = false;
  }
}

template <class A, class Tr>
void handle(A& a, vertex<Tr>& v) {
  if constexpr (A::mode == state_mode::check) {
    (void)&a, (void)&v;  // unused here (v may be volatile: no read)
  } else if constexpr (!std::is_same_v<vertex<Tr>, vertex<typename std::remove_reference_t<decltype(a.ctx)>::traits_type>>) {
    cannot<A, vertex<Tr>>(a, "a vertex of another kind of model");
  } else if constexpr (A::mode == state_mode::save) {
    if (v && v.ctx() != &a.ctx) throw state_error(name_of(v) + " belongs to another context than the model's");
    a.out.u32(v.slot());
    if (v.slot()) ++a.handles[v.slot()];
  } else {
    std::uint32_t id = a.in.u32("a vertex");
    if (id && !a.ctx.is_live(id)) throw state_error("a vertex of slot " + std::to_string(id) + ", which holds none");
    v = vertex<Tr>::from_slot(&a.ctx, id);
  }
}

template <class A, class Tr>
void members(A& a, mesh<Tr>& m) {
  using props = typename Tr::mesh_props;
  if constexpr (A::mode == state_mode::check) {
    state_fields(a, static_cast<props&>(m));
  } else if constexpr (A::mode == state_mode::save) {
    if (m.ctx() && m.ctx() != &a.ctx) throw state_error("a mesh of another context than the model's");
    a.out.u64(m.size());
    for (std::uint32_t id : m.slots())
      if (id) {
        a.out.u32(id);
        ++a.handles[id];
      }
    state_fields(a, static_cast<props&>(m));
  } else {
    std::size_t n = read_size(a);
    m.clear();
    for (std::size_t i = 0; i < n; ++i) {
      std::uint32_t id = a.in.u32("a mesh member");
      if (!a.ctx.is_live(id)) throw state_error("a mesh member of slot " + std::to_string(id) + ", which holds none");
      m.add(vertex<Tr>::from_slot(&a.ctx, id), where{});
    }
    state_fields(a, static_cast<props&>(m));
  }
}

template <class A, class T>
void sequence(A& a, T& s) {
  using E = typename T::value_type;
  if constexpr (A::mode == state_mode::check) {
    check_type<E>(a);
  } else if constexpr (A::mode == state_mode::save) {
    size(a, s.size());
    for (auto& e : s) state_value(a, e);
  } else if constexpr (!std::is_default_constructible_v<E>) {
    cannot<A, T>(a, "its elements have no default constructor, which a restore needs");
  } else {
    s.clear();
    s.resize(read_size(a));
    for (auto& e : s) state_value(a, e);
  }
}

template <class A>
void bits(A& a, std::vector<bool>& s) {
  if constexpr (A::mode == state_mode::save) {
    size(a, s.size());
    for (bool b : s) a.out.u8(b ? 1 : 0);
  } else if constexpr (A::mode == state_mode::load) {
    s.assign(read_size(a), false);
    for (std::size_t i = 0; i < s.size(); ++i) s[i] = a.in.u8("a bool") != 0;
  }
}

template <class A, class T>
void ordered(A& a, T& c) {
  using K = std::remove_const_t<typename T::key_type>;
  if constexpr (A::mode == state_mode::check) {
    check_type<K>(a);
    if constexpr (is_ordered_map<T>) check_type<typename T::mapped_type>(a);
  } else if constexpr (A::mode == state_mode::save) {
    size(a, c.size());
    for (auto& e : c) {
      if constexpr (is_ordered_map<T>) {
        K key = e.first;  // a key is const in the map
        state_value(a, key);
        state_value(a, e.second);
      } else {
        K key = e;
        state_value(a, key);
      }
    }
  } else {
    c.clear();
    std::size_t n = read_size(a);
    for (std::size_t i = 0; i < n; ++i) {
      K key{};
      state_value(a, key);
      if constexpr (is_ordered_map<T>) {
        typename T::mapped_type value{};
        state_value(a, value);
        c.emplace_hint(c.end(), std::move(key), std::move(value));
      } else {
        c.emplace_hint(c.end(), std::move(key));
      }
    }
  }
}

template <class A, class T>
void random_object(A& a, T& r) {
  if constexpr (A::mode == state_mode::save) {
    std::ostringstream os;
    os.imbue(std::locale::classic());
    os << r;
    a.out.text(os.str());
  } else if constexpr (A::mode == state_mode::load) {
    std::istringstream is(a.in.text("a random generator"));
    is.imbue(std::locale::classic());
    is >> r;
    if (is.fail()) throw state_error(type_name<T>() + ": its saved state does not read back");
  }
}

template <class A, class T, std::size_t... I>
void tuple_items(A& a, T& t, std::index_sequence<I...>) {
  (state_value(a, std::get<I>(t)), ...);
}

}  // namespace state_detail

//! Saves, restores or checks one value (see the top of this file).
template <class A, class T>
void state_value(A& a, T& v) {
  using namespace state_detail;
  using U = std::remove_const_t<T>;
  if constexpr (std::is_arithmetic_v<U>) {
    number(a, v);
  } else if constexpr (std::is_enum_v<U>) {
    auto n = static_cast<std::underlying_type_t<U>>(v);
    number(a, n);
    if constexpr (A::mode == state_mode::load) v = static_cast<U>(n);
  } else if constexpr (std::is_pointer_v<U> || std::is_member_pointer_v<U>) {
    cannot<A, U>(a, "a pointer (what it points at cannot be saved)");
  } else if constexpr (std::is_same_v<U, std::string>) {
    if constexpr (A::mode == state_mode::save) a.out.text(v);
    else if constexpr (A::mode == state_mode::load) v = a.in.text("a string");
  } else if constexpr (is_vertex<U>::value) {
    handle(a, v);
  } else if constexpr (is_mesh<U>::value) {
    members(a, v);
  } else if constexpr (is_instance<U, util::Point>::value) {
    state_value(a, v.glm());
  } else if constexpr (is_instance<U, util::Colour>::value) {
    for (int i = 0; i < 4; ++i) state_value(a, v.data()[i]);
  } else if constexpr (is_glm_vec<U>::value) {
    for (glm::length_t i = 0; i < U::length(); ++i) state_value(a, v[i]);
  } else if constexpr (is_glm_mat<U>::value) {
    for (glm::length_t i = 0; i < U::length(); ++i) state_value(a, v[i]);
  } else if constexpr (std::is_array_v<U>) {
    for (auto& e : v) state_value(a, e);
  } else if constexpr (is_std_array<U>::value) {
    for (auto& e : v) state_value(a, e);
  } else if constexpr (std::is_same_v<U, std::vector<bool>>) {
    bits(a, v);
  } else if constexpr (is_sequence<U>) {
    sequence(a, v);
  } else if constexpr (is_ordered_map<U> || is_ordered_set<U>) {
    ordered(a, v);
  } else if constexpr (is_unordered<U>) {
    cannot<A, U>(a, "an unordered container (a restore cannot promise its order; use std::map or std::set)");
  } else if constexpr (is_instance<U, std::pair>::value) {
    state_value(a, v.first);
    state_value(a, v.second);
  } else if constexpr (is_instance<U, std::tuple>::value) {
    tuple_items(a, v, std::make_index_sequence<std::tuple_size_v<U>>());
  } else if constexpr (is_instance<U, std::optional>::value) {
    if constexpr (A::mode == state_mode::check) {
      check_type<typename U::value_type>(a);
    } else if constexpr (A::mode == state_mode::save) {
      a.out.u8(v ? 1 : 0);
      if (v) state_value(a, *v);
    } else {
      v.reset();
      if (a.in.u8("an optional")) state_value(a, v.emplace());
    }
  } else if constexpr (is_instance<U, std::function>::value) {
    cannot<A, U>(a, "a function object (what it calls cannot be saved)");
  } else if constexpr (is_random_object<U>::value) {
    random_object(a, v);
  } else if constexpr (has_state_fields<U>::value || vv::detail::has_fields<U>::value) {
    state_fields(a, v);
  } else if constexpr (std::is_empty_v<U>) {
    // No data: nothing to save (algorithms::Insert and the like).
  } else {
    cannot<A, U>(a, "a type whose fields the checkpoint does not know; give it "
                    "template <class F> void vv_fields(F&& f) { f(\"name\", name); ... }");
  }
}

//! Why a value cannot be saved, or "" when it can.
template <class T>
std::string why_unsaveable(T& v) {
  state_checking a;
  try {
    state_value(a, v);
  } catch (const std::exception& e) {
    a.problem = e.what();
  }
  return a.problem;
}

}  // namespace vv::model
