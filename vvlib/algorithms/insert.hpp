// vv 1.1 <algorithms/insert.hpp>: put a new vertex on an edge.
#pragma once

#include <vv/insert.hpp>

namespace algorithms {

//! `algorithms::Insert<vertex> insert; vertex x = insert(p, q);`
//! creates x with x* = {p, q} and puts it in place of q in p* and of p in
//! q* (their half-edge records stay with the slots). p and q must be
//! mutual neighbours. The same as vv::insert(p, q) (<vv/insert.hpp>).
template <class V>
class Insert {
 public:
  V operator()(const V& p, const V& q, vv::where w = vv::where::here()) const {
    return vv::insert(p, q, w);
  }
};

}  // namespace algorithms
