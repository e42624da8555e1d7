// vv::insert(p, q): a new vertex on the edge p-q. The vv 1.1 functor
// algorithms::Insert (<algorithms/insert.hpp>) does the same through it.
#pragma once

#include "edits.hpp"
#include "queries.hpp"

namespace vv {

//! Creates x with x* = {p, q} and puts it in place of q in p* and of p in
//! q* (their half-edge records stay with the slots); returns x.
//! \throw vv::error when p or q is null or they are not mutual neighbours.
template <class Tr>
vertex<Tr> insert(const vertex<Tr>& p, const vertex<Tr>& q, where w = where::here()) {
  if (!p || !q) throw error(w, "insert", "cannot insert next to the null vertex");
  if (!is_in(q, p, w) || !is_in(p, q, w))
    throw error(w, "insert", name_of(p) + " and " + name_of(q) + " are not mutual neighbours");
  vertex<Tr> x = p.ctx()->new_vertex();
  replace_in(q, x, p, w);
  replace_in(p, x, q, w);
  make_nb(x, {p, q}, w);
  return x;
}

}  // namespace vv
