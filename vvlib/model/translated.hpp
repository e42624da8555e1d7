// The few functions translated programs call that C++ users of vvlib
// would spell differently: they give every vv statement one call form.
//
//   (a^b)  -> vv::edge_hat(a, b)     (a|b)  -> vv::edge_bar(a, b)
// Between vertices these are half-edge records; between anything else they
// are the C++ operators ^ and |, so `(i|j)` on integers keeps its meaning
// (C++ overloading decides, not the translator).
#pragma once

#include <utility>

#include <vv/detail/inline.hpp>
#include <vv/edges.hpp>
#include <vv/mesh.hpp>

namespace vv {

template <class A, class B>
constexpr auto edge_hat(A&& a, B&& b) -> decltype(std::forward<A>(a) ^ std::forward<B>(b)) {
  return std::forward<A>(a) ^ std::forward<B>(b);
}
template <class Tr>
typename Tr::edge_props& edge_hat(const vertex<Tr>& a, const vertex<Tr>& b,
                                  where w = where::here()) {
  return edge(a, b, w);
}
template <class Tr>
const typename Tr::edge_props& edge_hat(const old_vertex<Tr>& a, const vertex<Tr>& b,
                                        where w = where::here()) {
  return edge(a, b, w);
}

template <class A, class B>
constexpr auto edge_bar(A&& a, B&& b) -> decltype(std::forward<A>(a) | std::forward<B>(b)) {
  return std::forward<A>(a) | std::forward<B>(b);
}
template <class Tr>
typename Tr::edge_props& edge_bar(const vertex<Tr>& a, const vertex<Tr>& b,
                                  where w = where::here(),
                                  detail::symmetric_sync<Tr>&& sync = detail::symmetric_sync<Tr>()) {
  return sym_edge(a, b, w, std::move(sync));
}
template <class Tr>
const typename Tr::edge_props& edge_bar(const old_vertex<Tr>& a, const vertex<Tr>& b,
                                        where w = where::here()) {
  return edge(a, b, w);
}

//! `add v to M;`
template <class Tr>
VV_INLINE void add_to(const vertex<Tr>& v, mesh<Tr>& m, where w = where::here()) {
  m.add(v, w);
}
//! `remove v from M;`
template <class Tr>
void remove_from(const vertex<Tr>& v, mesh<Tr>& m, where w = where::here()) {
  m.remove(v, w);
}
//! `merge M with N;`
template <class Tr>
void merge_with(mesh<Tr>& m, const mesh<Tr>& n, where w = where::here()) {
  m.merge(n, w);
}
//! `clear M;`
template <class Tr>
void clear(mesh<Tr>& m, where w = where::here()) {
  m.clear(w);
}

}  // namespace vv
