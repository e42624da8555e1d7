// Shared plumbing of the neighbourhood operations: which neighbourhood an
// operand denotes, finding a neighbour in it, and error texts.
#pragma once

#include "inline.hpp"

#include <cstdint>
#include <string>
#include <type_traits>

#include "../error.hpp"
#include "../vertex.hpp"

namespace vv::detail {

template <class V>
struct is_vertex_like : std::false_type {};
template <class Tr>
struct is_vertex_like<vertex<Tr>> : std::true_type {};
template <class Tr>
struct is_vertex_like<old_vertex<Tr>> : std::true_type {};

template <class V>
using if_vertex_like = std::enable_if_t<is_vertex_like<V>::value, int>;

//! A neighbourhood an operation reads: the current or the old one.
template <class Tr>
struct nb_view {
  using nb_type = typename context<Tr>::nb_type;
  context<Tr>* ctx;
  const nb_type* nb;
};

template <class Tr>
VV_INLINE nb_view<Tr> view(const vertex<Tr>& v, const char* op, const where& w) {
  if (!v) raise(w, op, [] { return std::string("the target is the null vertex"); });
  return {v.ctx(), &v.ctx()->nb(v.slot())};
}
template <class Tr>
VV_INLINE nb_view<Tr> view(const old_vertex<Tr>& v, const char*, const where&) noexcept {
  return {v.ctx(), &v.ctx()->old_nb(v.slot())};
}

//! The vertex whose current state an edit changes (`` `v `` as an edit
//! target means v itself).
template <class Tr>
VV_INLINE const vertex<Tr>& edit_target(const vertex<Tr>& v, const char* op, const where& w) {
  if (!v) raise(w, op, [] { return std::string("the target is the null vertex"); });
  v.ctx()->note_edit(v.slot(), op, w);
  return v;
}
template <class Tr>
VV_INLINE vertex<Tr> edit_target(const old_vertex<Tr>& v, const char* op, const where& w) {
  v.ctx()->note_edit(v.slot(), op, w);
  return v.current();
}

template <class NB>
VV_INLINE std::int32_t find(const NB& nb, std::uint32_t id) noexcept {
  return nb.index_of(id);
}

//! The slot a vertex operand occupies in v's context, or 0 when it is null
//! or lives in another context (then it can be no neighbour of v).
template <class Tr>
VV_INLINE std::uint32_t slot_in(const vertex<Tr>& x, const context<Tr>* ctx) noexcept {
  return x && x.ctx() == ctx ? x.slot() : 0u;
}

//! Checks a vertex about to be inserted into v*.
template <class Tr, class NB>
VV_INLINE void check_insertable(const vertex<Tr>& x, const vertex<Tr>& v, const NB& nb, const char* op,
                      const where& w) {
  if (!x) raise(w, op, [&] { return "cannot insert the null vertex into the neighbourhood of " + name_of(v); });
  if (x.ctx() != v.ctx())
    raise(w, op, [&] { return name_of(x) + " and " + name_of(v) + " belong to different contexts"; });
  if (x == v) raise(w, op, [&] { return name_of(v) + " cannot be its own neighbour"; });
  if (find(nb, x.slot()) >= 0)
    raise(w, op, [&] { return name_of(x) + " is already a neighbour of " + name_of(v); });
}

}  // namespace vv::detail
