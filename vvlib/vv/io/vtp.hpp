// A mesh as VTK XML PolyData (.vtp) for ParaView: the members (in iteration
// order) as points at their `pos`, cells from the connectivity, and every
// numeric and 3-vector vertex property as point data.
//
// Cells: a curve (vv/polylines.hpp) gives its polylines; another mesh its
// face orbits of at least three and at most max_face corners as polygons,
// or, when it has none, its edges as two-point lines. A member on no cell
// is a vertex cell, so that ParaView shows it.
//
// Point data: each vertex property that is a number (bool as 0/1 UInt8,
// integers as VTK integers of their size and sign, float as Float32,
// double as Float64) or a 3-vector of numbers (x(), y(), z() as util::Point,
// or a GLM vec3), in declaration order, under its name. `pos`
// is the points themselves and is not repeated. Other properties (strings,
// vertex handles, lists) have no VTK array and are left out.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "../faces.hpp"
#include "../fields.hpp"
#include "../polylines.hpp"
#include "positions.hpp"
#include "vtk_files.hpp"

namespace vv {

namespace detail {

// The VTK number type a property's number is written as.
template <class T>
constexpr vtk_number vtk_number_of() {
  if constexpr (std::is_same_v<T, bool>) return vtk_number::uint8;
  else if constexpr (std::is_floating_point_v<T>) return sizeof(T) == 4 ? vtk_number::float32 : vtk_number::float64;
  else if constexpr (std::is_signed_v<T>)
    return sizeof(T) == 1 ? vtk_number::int8 : sizeof(T) == 2 ? vtk_number::int16
         : sizeof(T) == 4 ? vtk_number::int32 : vtk_number::int64;
  else
    return sizeof(T) == 1 ? vtk_number::uint8 : sizeof(T) == 2 ? vtk_number::uint16
         : sizeof(T) == 4 ? vtk_number::uint32 : vtk_number::uint64;
}

// Numbers VTK has an array type for (no 128-bit integers).
template <class T>
constexpr bool is_vtk_number = std::is_arithmetic_v<T> && (std::is_floating_point_v<T> || sizeof(T) <= 8);

// Appends one number as its VTK type, in the machine's byte order.
template <class T>
void append_vtk_number(std::string& bytes, T v) {
  auto put = [&](auto fixed) { bytes.append(reinterpret_cast<const char*>(&fixed), sizeof fixed); };
  constexpr vtk_number type = vtk_number_of<T>();
  if constexpr (std::is_same_v<T, bool>) put(std::uint8_t(v ? 1 : 0));
  else if constexpr (type == vtk_number::float32) put(static_cast<float>(v));
  else if constexpr (type == vtk_number::float64) put(static_cast<double>(v));
  else if constexpr (std::is_signed_v<T>)
    put(static_cast<std::conditional_t<sizeof(T) == 1, std::int8_t,
                    std::conditional_t<sizeof(T) == 2, std::int16_t,
                    std::conditional_t<sizeof(T) == 4, std::int32_t, std::int64_t>>>>(v));
  else
    put(static_cast<std::conditional_t<sizeof(T) == 1, std::uint8_t,
                    std::conditional_t<sizeof(T) == 2, std::uint16_t,
                    std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>>>(v));
}

// A 3-vector of numbers: its component type and components. util::Point
// and the like by x(), y(), z(); GLM vectors by their static length() of 3.
template <class T, class = void>
struct vector3 : std::false_type {};
template <class T>
struct vector3<T, std::enable_if_t<is_vtk_number<std::decay_t<decltype(std::declval<const T&>().x())>>>>
    : std::true_type {
  using component = std::decay_t<decltype(std::declval<const T&>().x())>;
  static std::array<component, 3> parts(const T& v) { return {v.x(), v.y(), v.z()}; }
};
template <class T>
struct vector3<T, std::enable_if_t<std::integral_constant<int, int(T::length())>::value == 3 &&
                                   is_vtk_number<typename T::value_type>>> : std::true_type {
  using component = typename T::value_type;
  static std::array<component, 3> parts(const T& v) { return {v[0], v[1], v[2]}; }
};

// Whether a property becomes point data.
template <class T>
constexpr bool is_point_data = is_vtk_number<T> || vector3<T>::value;

}  // namespace detail

//! The points, cells and point data of m as a .vtp file holds them (see
//! the top of this file); vv::error naming `path` when the vertices have
//! no `pos`.
template <class Tr>
vtp_polydata vtp_data_of(const mesh<Tr>& m, const std::string& path,
                         std::size_t max_face = std::numeric_limits<std::size_t>::max()) {
  using VP = typename Tr::vertex_props;
  vtp_polydata data;
  if constexpr (!detail::has_pos<VP>::value) {
    throw error(path, 0, "the vertices have no 'pos' property, so a vtp file cannot hold them (.vvm can)");
  } else {
    context<Tr>* ctx = m.ctx();
    std::vector<std::uint32_t> members;
    for (std::uint32_t id : m.slots())
      if (id) members.push_back(id);
    for (std::uint32_t id : members) data.points.push_back(detail::xyz_of(ctx->props(id).pos));

    // Point data: one array per property, filled vertex by vertex in the
    // order for_each_field gives the properties.
    VP probe{};
    for_each_field(probe, [&](const char* name, const auto& value) {
      using T = std::decay_t<decltype(value)>;
      if constexpr (detail::is_point_data<T>) {
        if (std::string(name) == "pos") return;
        vtp_point_array a;
        a.name = name;
        if constexpr (detail::vector3<T>::value) {
          a.type = detail::vtk_number_of<typename detail::vector3<T>::component>();
          a.components = 3;
        } else {
          a.type = detail::vtk_number_of<T>();
        }
        a.bytes.reserve(members.size() * a.components * vtk_number_size(a.type));
        data.point_data.push_back(std::move(a));
      }
    });
    for (std::uint32_t id : members) {
      std::size_t k = 0;
      for_each_field(ctx->props(id), [&](const char* name, const auto& value) {
        using T = std::decay_t<decltype(value)>;
        if constexpr (detail::is_point_data<T>) {
          if (std::string(name) == "pos") return;
          std::string& bytes = data.point_data[k++].bytes;
          if constexpr (detail::vector3<T>::value) {
            for (auto c : detail::vector3<T>::parts(value)) detail::append_vtk_number(bytes, c);
          } else {
            detail::append_vtk_number(bytes, value);
          }
        }
      });
    }

    if (is_curve(m)) {
      data.lines = polylines(m);
    } else {
      for (const auto& orbit : orbits(m, max_face).faces)
        if (orbit.size() >= 3) data.polys.emplace_back(orbit.begin(), orbit.end());
    }
    if (data.polys.empty() && data.lines.empty()) {
      // No faces: the edges, each once (a one-way neighbour too).
      std::vector<std::uint32_t> at = member_positions(m);
      constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
      for (std::size_t i = 0; i < members.size(); ++i)
        for (const auto& e : ctx->nb(members[i])) {
          std::uint32_t b = detail::entry_id(e);
          if (b >= at.size() || at[b] == none) continue;
          if (at[b] > i || detail::find(ctx->nb(b), members[i]) < 0) data.lines.push_back({i, at[b]});
        }
    }
    std::vector<char> on_cell(members.size(), 0);
    for (const auto* cells : {&data.lines, &data.polys})
      for (const auto& cell : *cells)
        for (std::size_t i : cell) on_cell[i] = 1;
    for (std::size_t i = 0; i < members.size(); ++i)
      if (!on_cell[i]) data.verts.push_back(i);
  }
  return data;
}

//! Writes m to a .vtp file, atomically; nothing is written on failure.
template <class Tr>
void write_vtp(const mesh<Tr>& m, const std::string& path,
               std::size_t max_face = std::numeric_limits<std::size_t>::max()) {
  write_vtp_file(path, vtp_data_of(m, path, max_face));
}

}  // namespace vv
