// InsertEdge: a new edge between two face corners of a vertex-vertex mesh
// with symmetric, counter-clockwise neighbourhoods.
//
// A corner is named by the oriented edge that leaves it along its face:
// (a, a_next) is the corner of a in the face whose orbit goes a -> a_next
// (the face on the left of a -> a_next, the face Centroid(a, a_next) fills).
// Around a that corner lies between a_next and the neighbour after it, so
// the new neighbour b goes right after a_next in a*, and a right after
// b_next in b*. Naming a corner by an edge rather than by a vertex and a
// face keeps it unambiguous where a face passes through a vertex twice.
//
//   * Both corners on one face (.., a, a_next, .., b, b_next, ..): the face
//     splits in two, (a, b, b_next, ..) and (b, a, a_next, ..).
//   * Corners on two different faces: they join into one face that passes
//     through a and b twice, (a, b, b_next, .., b, a, a_next, .., a). On one
//     connected surface this adds a handle (V - E + F drops by 2, the genus
//     rises by 1); between two surfaces it makes a tube joining them. The
//     joined face is not a manifold orbit (check_invariants with `manifold`
//     refuses it) until another edge splits it again.
//
// Refused with a vv::error naming the vertices, before anything changes:
// a null end, a == b (a loop), a and b already neighbours (a double edge),
// a corner whose two vertices are not mutual neighbours (it is on no
// face), and a corner on a face that does not close (one-sided neighbours
// on its way).
#pragma once

#include <vv/edits.hpp>
#include <vv/queries.hpp>

#include "face_change.hpp"

namespace algorithms {

//! `InsertEdge<vertex> insert_edge; insert_edge(a, a_next, b, b_next);` —
//! joins a and b across the corners (a, a_next) and (b, b_next); returns
//! whether a face was split or two were joined.
template <class V>
class InsertEdge {
 public:
  face_change operator()(const V& a, const V& a_next, const V& b, const V& b_next,
                         vv::where w = vv::where::here()) const {
    constexpr const char* op = "InsertEdge";
    if (!a || !b) throw vv::error(w, op, "an end of the new edge is the null vertex");
    if (a == b) throw vv::error(w, op, "cannot join " + vv::name_of(a) + " to itself");
    if (vv::is_in(b, a, w) || vv::is_in(a, b, w))
      throw vv::error(w, op, vv::name_of(a) + " and " + vv::name_of(b) + " are already neighbours");
    detail::require_mutual(a, a_next, op, corner_problem(a, a_next), w);
    detail::require_mutual(b, b_next, op, corner_problem(b, b_next), w);
    bool one_face = detail::on_same_face(a, a_next, b, b_next, op, w);
    vv::splice_after(b, a_next, a, w);
    vv::splice_after(a, b_next, b, w);
    return one_face ? face_change::split : face_change::joined;
  }

 private:
  static std::string corner_problem(const V& v, const V& next) {
    return "the corner (" + vv::name_of(v) + ", " + vv::name_of(next) + ") is on no face";
  }
};

}  // namespace algorithms
