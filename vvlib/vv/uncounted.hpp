// Queries whose vertex is read at once and never kept, as in
// `` `(nextto q in `p)$pos ``: the translator passes such a query's result
// straight to `` ` `` through these, which name the vertex by its slot and
// do not count it. Nothing between the query and the read can create a
// vertex, so the collector cannot free it meanwhile; a handle would cost a
// count in and a count out for every such read.
//
//   `(nextto x in v)     vv::old(vv::uncounted::next_to(x, v))
#pragma once

#include "detail/inline.hpp"

#include <string>

#include "queries.hpp"

namespace vv {

namespace uncounted {

template <class V, detail::if_vertex_like<V> = 0>
VV_INLINE vertex_ref<typename V::traits_type> next_to(const vertex<typename V::traits_type>& x, const V& v,
                                                      where w = where::here()) {
  return detail::step_ref(x, v, 1UL, true, "nextto", w);
}
template <class V, detail::if_vertex_like<V> = 0>
VV_INLINE vertex_ref<typename V::traits_type> next_to(const vertex<typename V::traits_type>& x, const V& v,
                                                      long i, where w = where::here()) {
  return detail::step_ref(x, v, detail::step_count(i, "next(i)to", w), true, "next(i)to", w);
}
template <class V, detail::if_vertex_like<V> = 0>
VV_INLINE vertex_ref<typename V::traits_type> prev_to(const vertex<typename V::traits_type>& x, const V& v,
                                                      where w = where::here()) {
  return detail::step_ref(x, v, 1UL, false, "prevto", w);
}
template <class V, detail::if_vertex_like<V> = 0>
VV_INLINE vertex_ref<typename V::traits_type> prev_to(const vertex<typename V::traits_type>& x, const V& v,
                                                      long i, where w = where::here()) {
  return detail::step_ref(x, v, detail::step_count(i, "prev(i)to", w), false, "prev(i)to", w);
}
template <class V, detail::if_vertex_like<V> = 0>
VV_INLINE vertex_ref<typename V::traits_type> any_in(const V& v, where w = where::here()) {
  auto s = detail::view(v, "any in", w);
  if (s.nb->empty()) return {nullptr, 0};
  return {s.ctx, detail::entry_id((*s.nb)[0])};
}

}  // namespace uncounted

//! `` `(query) ``: the old state of a query's vertex; the same checks as
//! for a handle (null: an error; in strict mode, never synchronised: an
//! error naming the vertex).
template <class Tr>
VV_INLINE old_vertex<Tr> old(const vertex_ref<Tr>& r, where w = where::here()) {
  if (!r.id || r.ctx->strict_old_state) return old_vertex<Tr>(vertex<Tr>::from_slot(r.ctx, r.id), w);
  return old_vertex<Tr>::from_slot(r.ctx, r.id);
}

}  // namespace vv
