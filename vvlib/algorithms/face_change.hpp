// What an edge insertion or deletion did to the faces around it, and the
// test InsertEdge and DeleteEdge use to find out before they edit (on the
// face walk of face_walk.hpp).
#pragma once

#include <string>

#include <vv/error.hpp>
#include <vv/queries.hpp>

#include "face_walk.hpp"

namespace algorithms {

//! `split`: one face became two (or, for a deletion, the edge had the same
//! face on both sides and that face fell apart in two). `joined`: two faces
//! became one. Splitting keeps the genus; joining two faces of one
//! connected surface with an edge adds a handle (genus + 1), and joining
//! faces of two surfaces makes them one.
enum class face_change { split, joined };

namespace detail {

// Throws "op: problem: <why>" unless a and b are non-null mutual
// neighbours (then the oriented edge (a, b) lies on exactly one face).
template <class V>
void require_mutual(const V& a, const V& b, const char* op, const std::string& problem,
                    vv::where w) {
  if (!a || !b) throw vv::error(w, op, problem + ": an end is the null vertex");
  if (!vv::is_in(b, a, w) || !vv::is_in(a, b, w))
    throw vv::error(w, op,
                    problem + ": " + vv::name_of(a) + " and " + vv::name_of(b) + " are not mutual neighbours");
}

// Whether the walk around the face of (a, b) meets the oriented edge
// (c, d); throws when the face does not close.
template <class V>
bool face_meets(const V& a, const V& b, const V& c, const V& d, const char* op, vv::where w) {
  return walk_face(a, b, op, w, [&](const V& x, const V& y) { return x == c && y == d; });
}

// Whether the oriented edges (a, b) and (c, d), each between mutual
// neighbours, lie on one face. Throws, naming the face, when a face they
// lie on does not close: the edit would leave it broken.
template <class V>
bool on_same_face(const V& a, const V& b, const V& c, const V& d, const char* op, vv::where w) {
  if (face_meets(a, b, c, d, op, w)) return true;
  face_meets(c, d, a, b, op, w);  // to check that this face closes too
  return false;
}

}  // namespace detail

}  // namespace algorithms
