// The traits bundle that parameterises everything (the property structs of
// one model), the empty property struct, and forward declarations.
#pragma once

#include <type_traits>

namespace vv {

//! The property struct of a model that declares no properties of a kind.
struct no_props {
  template <class F>
  void vv_fields(F&&) {}
  template <class F>
  void vv_fields(F&&) const {}
  friend bool operator==(const no_props&, const no_props&) noexcept { return true; }
  friend bool operator!=(const no_props&, const no_props&) noexcept { return false; }
};

//! The user-defined property structs of one model: per vertex, per half-edge
//! record and per mesh. InlineValence neighbours are stored without a heap
//! allocation (6 suits triangle meshes; larger neighbourhoods still work).
template <class VertexProps, class EdgeProps = no_props, class MeshProps = no_props,
          unsigned InlineValence = 6>
struct traits {
  using vertex_props = VertexProps;
  using edge_props = EdgeProps;
  using mesh_props = MeshProps;
  static constexpr unsigned inline_valence = InlineValence;
  //! Parallel loops (vv/parallel.hpp) may share this model's vertices out to
  //! threads. A model without them sets it false (vvc does so for a program
  //! with no `parallel forall`): each handle copy then costs one test less,
  //! and its loops run in order.
  static constexpr bool parallel_loops = true;
};

template <class Tr>
class context;

namespace detail {
//! Whether the traits name the one context of their model (`Tr::context()`,
//! as a translated program's do).
template <class Tr, class = void>
struct has_default_context : std::false_type {};
template <class Tr>
struct has_default_context<Tr, std::void_t<decltype(Tr::context())>> : std::true_type {};
}  // namespace detail

template <class Tr>
class vertex;
template <class Tr>
class old_vertex;
template <class Tr>
class mesh;

}  // namespace vv
