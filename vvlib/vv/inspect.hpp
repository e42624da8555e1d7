// Looking inside a model from its host: one vertex described as text (its
// properties, its neighbourhood in rotation order with the flag, its
// half-edge records, the meshes that hold it), and a numeric vertex
// property read out per vertex for colouring.
#pragma once

#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "fields.hpp"
#include "mesh.hpp"

namespace vv {

namespace detail {

template <class P>
std::string field_lines(const P& props, const std::string& indent) {
  std::string out;
  for_each_field(props, [&](const char* name, const auto& value) {
    out += indent + name + " = " + value_to_text(value) + "\n";
  });
  return out;
}

template <class T>
constexpr bool is_numeric_field = std::is_arithmetic_v<T>;

}  // namespace detail

//! The living vertex with this label, or 0.
template <class Tr>
std::uint32_t slot_of_label(const context<Tr>& ctx, const std::vector<const mesh<Tr>*>& meshes,
                            std::uint32_t label) {
  for (const mesh<Tr>* m : meshes)
    for (std::uint32_t id : m->slots())
      if (id && ctx.label(id) == label) return id;
  return 0;
}

//! "vertex 7", its properties, "in meshes: S C", its neighbourhood as
//! labels in rotation order ("[3]" is the flagged entry) and the records of
//! its half-edges that carry fields. `names[i]` names `meshes[i]`.
template <class Tr>
std::string describe_vertex(context<Tr>& ctx, const std::vector<const mesh<Tr>*>& meshes,
                            const std::vector<std::string>& names, std::uint32_t id) {
  std::string out = "vertex " + std::to_string(ctx.label(id)) + "\n";
  std::string in;
  for (std::size_t i = 0; i < meshes.size(); ++i)
    if (meshes[i]->contains(vertex<Tr>::from_slot(&ctx, id))) in += " " + names[i];
  out += "  in meshes:" + (in.empty() ? std::string(" none") : in) + "\n";
  std::string props = detail::field_lines(ctx.props(id), "    ");
  out += props.empty() ? "  properties: none\n" : "  properties:\n" + props;

  using entry_traits = typename context<Tr>::entry_traits;
  const auto& nb = ctx.nb(id);
  std::string order, records;
  std::int32_t flag = nb.flag();
  std::int32_t position = 0;
  for (const auto& e : nb) {
    std::string label = std::to_string(ctx.label(detail::entry_id(e)));
    order += " " + (position++ == flag ? "[" + label + "]" : label);
    std::string fields = detail::field_lines(entry_traits::rec(e, ctx.empty_record()), "      ");
    if (!fields.empty()) records += "    " + std::to_string(ctx.label(id)) + " -> " + label + ":\n" + fields;
  }
  out += "  neighbourhood (" + std::to_string(nb.size()) + ", rotation order" +
         (flag >= 0 ? ", [flagged]" : "") + "):" + (order.empty() ? " empty" : order) + "\n";
  if (!records.empty()) out += "  half-edge records:\n" + records;
  return out;
}

//! The names of the vertex properties that are numbers (bool included),
//! comma-separated, for a host offering "colour by".
template <class Tr>
std::string numeric_vertex_fields() {
  std::string out;
  typename Tr::vertex_props probe{};
  for_each_field(probe, [&](const char* name, const auto& value) {
    if constexpr (detail::is_numeric_field<std::decay_t<decltype(value)>>)
      out += (out.empty() ? "" : ", ") + std::string(name);
  });
  return out;
}

//! The numeric vertex property `field` of each vertex, in the order of
//! `ids`; false when there is no numeric property of that name.
template <class Tr>
bool numeric_field_values(context<Tr>& ctx, const std::vector<std::uint32_t>& ids, const std::string& field,
                          std::vector<double>& out) {
  bool found = false;
  typename Tr::vertex_props probe{};
  for_each_field(probe, [&](const char* name, const auto& value) {
    if constexpr (detail::is_numeric_field<std::decay_t<decltype(value)>>) found = found || field == name;
  });
  if (!found) return false;
  out.clear();
  out.reserve(ids.size());
  for (std::uint32_t id : ids)
    for_each_field(ctx.props(id), [&](const char* name, const auto& value) {
      if constexpr (detail::is_numeric_field<std::decay_t<decltype(value)>>)
        if (field == name) out.push_back(static_cast<double>(value));
    });
  return true;
}

}  // namespace vv
