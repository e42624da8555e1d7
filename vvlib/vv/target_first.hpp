// The neighbourhood operations written target first: the vertex whose
// neighbourhood is read or changed comes first, then the other operands in
// the order the vv statement names them (docs/library.md, "Operand
// order"). `make_nb(v, list)`, `valence(v)` and the other one-target
// operations already read that way; these are the rest. Each is the same
// operation as its vv-order spelling (queries.hpp, edits.hpp), which
// translated programs keep using: same result, same errors.
#pragma once

#include "edits.hpp"
#include "queries.hpp"

namespace vv {

//! `is x in v`: x is a neighbour of v (vv order: `is_in(x, v)`).
template <class V, detail::if_vertex_like<V> = 0>
bool has_nb(const V& v, const vertex<typename V::traits_type>& x, where w = where::here()) {
  return is_in(x, v, w);
}

//! `nextto x in v` / `next(i)to x in v` (vv order: `next_to(x, v[, i])`).
template <class V, detail::if_vertex_like<V> = 0>
vertex<typename V::traits_type> nb_after(const V& v, const vertex<typename V::traits_type>& x,
                                         where w = where::here()) {
  return next_to(x, v, w);
}
template <class V, detail::if_vertex_like<V> = 0>
vertex<typename V::traits_type> nb_after(const V& v, const vertex<typename V::traits_type>& x,
                                         long i, where w = where::here()) {
  return next_to(x, v, i, w);
}

//! `prevto x in v` / `prev(i)to x in v` (vv order: `prev_to(x, v[, i])`).
template <class V, detail::if_vertex_like<V> = 0>
vertex<typename V::traits_type> nb_before(const V& v, const vertex<typename V::traits_type>& x,
                                          where w = where::here()) {
  return prev_to(x, v, w);
}
template <class V, detail::if_vertex_like<V> = 0>
vertex<typename V::traits_type> nb_before(const V& v, const vertex<typename V::traits_type>& x,
                                          long i, where w = where::here()) {
  return prev_to(x, v, i, w);
}

//! `erase x from v;` (vv order: `erase_from(x, v)`).
template <class V, detail::if_vertex_like<V> = 0>
void erase_nb(const V& v, const vertex<typename V::traits_type>& x, where w = where::here()) {
  erase_from(x, v, w);
}

//! `replace a with x in v;` (vv order: `replace_in(a, x, v)`).
template <class V, detail::if_vertex_like<V> = 0>
void replace_nb(const V& v, const vertex<typename V::traits_type>& a,
                const vertex<typename V::traits_type>& x, where w = where::here()) {
  replace_in(a, x, v, w);
}

//! `splice x after a in v;` (vv order: `splice_after(x, a, v)`).
template <class V, detail::if_vertex_like<V> = 0>
void splice_nb_after(const V& v, const vertex<typename V::traits_type>& x,
                     const vertex<typename V::traits_type>& a, where w = where::here()) {
  splice_after(x, a, v, w);
}

//! `splice x before a in v;` (vv order: `splice_before(x, a, v)`).
template <class V, detail::if_vertex_like<V> = 0>
void splice_nb_before(const V& v, const vertex<typename V::traits_type>& x,
                      const vertex<typename V::traits_type>& a, where w = where::here()) {
  splice_before(x, a, v, w);
}

//! `flag b in a;` (vv order: `flag_in(b, a)`); a null b unsets the flag.
template <class V, detail::if_vertex_like<V> = 0>
void flag_nb(const V& a, const vertex<typename V::traits_type>& b, where w = where::here()) {
  flag_in(b, a, w);
}

//! `splice b after flag in a;` (vv order: `splice_after_flag(b, a)`).
template <class V, detail::if_vertex_like<V> = 0>
void splice_nb_after_flag(const V& a, const vertex<typename V::traits_type>& b,
                          where w = where::here()) {
  splice_after_flag(b, a, w);
}

//! `splice b before flag in a;` (vv order: `splice_before_flag(b, a)`).
template <class V, detail::if_vertex_like<V> = 0>
void splice_nb_before_flag(const V& a, const vertex<typename V::traits_type>& b,
                           where w = where::here()) {
  splice_before_flag(b, a, w);
}

//! `replace flag with b in a;` (vv order: `replace_flag(b, a)`).
template <class V, detail::if_vertex_like<V> = 0>
void replace_flagged_nb(const V& a, const vertex<typename V::traits_type>& b,
                        where w = where::here()) {
  replace_flag(b, a, w);
}

}  // namespace vv
