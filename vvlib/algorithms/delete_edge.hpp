// DeleteEdge: takes an edge out of a vertex-vertex mesh with symmetric,
// counter-clockwise neighbourhoods (the inverse of InsertEdge).
//
//   * The two faces beside the edge differ: they join into one. Where one
//     of them is a hole (a boundary orbit, longer than the host's
//     max_face), the other face opens into it.
//   * The edge has the same face on both sides (a bridge, or the edge that
//     joined two faces): that face splits in two. This undoes a handle or
//     a tube: the genus drops by 1, or the surface falls in two.
//
// b leaves a* and a leaves b*, with their half-edge records; the other
// entries keep their order, and the flag its entry (a flag on a deleted
// entry is unset). So InsertEdge then DeleteEdge restores every
// neighbourhood exactly, and DeleteEdge(a, b) then InsertEdge(a, p, b, q),
// with p = prevto b in a and q = prevto a in b read before the deletion,
// restores every rotation (as a cyclic order: where b was a's first entry
// it comes back as the last).
//
// Refused with a vv::error naming the vertices, before anything changes: a
// null end, a and b not mutual neighbours, an end whose only neighbour is
// the other (it would be left with no neighbours: use Remove), and a face
// beside the edge that does not close (one-sided neighbours on its way).
#pragma once

#include <vv/edits.hpp>
#include <vv/queries.hpp>

#include "face_change.hpp"

namespace algorithms {

//! `DeleteEdge<vertex> delete_edge; delete_edge(a, b);` — removes the edge
//! a-b; returns whether its two faces were joined or its one face split.
template <class V>
class DeleteEdge {
 public:
  face_change operator()(const V& a, const V& b, vv::where w = vv::where::here()) const {
    constexpr const char* op = "DeleteEdge";
    detail::require_mutual(a, b, op, "there is no edge to delete", w);
    for (const V& end : {a, b})
      if (vv::valence(end, w) == 1)
        throw vv::error(w, op, "deleting the edge " + vv::name_of(a) + "-" + vv::name_of(b) +
                                   " would leave " + vv::name_of(end) + " with no neighbours");
    bool one_face = detail::on_same_face(a, b, b, a, op, w);
    vv::erase_from(b, a, w);
    vv::erase_from(a, b, w);
    return one_face ? face_change::split : face_change::joined;
  }
};

}  // namespace algorithms
