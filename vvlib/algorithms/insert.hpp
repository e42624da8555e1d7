// vv 1.1 <algorithms/insert.hpp>: put a new vertex on an edge.
#pragma once

#include <vv/edits.hpp>
#include <vv/queries.hpp>

namespace algorithms {

//! `algorithms::Insert<vertex> insert; vertex x = insert(p, q);`
//! creates x with x* = {p, q} and puts it in place of q in p* and of p in
//! q* (their half-edge records stay with the slots). p and q must be
//! mutual neighbours.
template <class V>
class Insert {
 public:
  V operator()(const V& p, const V& q, vv::where w = vv::where::here()) const {
    if (!p || !q) throw vv::error(w, "insert", "cannot insert next to the null vertex");
    if (!vv::is_in(q, p, w) || !vv::is_in(p, q, w))
      throw vv::error(w, "insert",
                      vv::name_of(p) + " and " + vv::name_of(q) + " are not mutual neighbours");
    V x = p.ctx()->new_vertex();
    vv::replace_in(q, x, p, w);
    vv::replace_in(p, x, q, w);
    vv::make_nb(x, {p, q}, w);
    return x;
  }
};

}  // namespace algorithms
