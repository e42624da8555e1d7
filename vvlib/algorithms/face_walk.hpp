// The face walk shared by the operations that need a face's corners
// (Centroid in stellar.hpp) or whether two edges share a face (InsertEdge
// and DeleteEdge through face_change.hpp).
//
// Faces are the orbits of oriented edges, (x, y) -> (y, prevto x in y)
// (LANGUAGE.md section 1): with counter-clockwise neighbourhoods a face
// (.., p, c, n, ..) has n immediately before p in the rotation of c.
#pragma once

#include <vv/error.hpp>
#include <vv/queries.hpp>

namespace algorithms {
namespace detail {

// Calls visit(x, y) for every oriented edge of the face orbit that starts
// with (a, b), in order, until visit returns true; returns whether it did.
// Throws, naming the face and `op`, when the orbit does not close: the
// neighbourhoods around the face are not symmetric.
template <class V, class Visit>
bool walk_face(const V& a, const V& b, const char* op, vv::where w, Visit&& visit) {
  V x = a, y = b;
  do {
    if (visit(x, y)) return true;
    V z = vv::prev_to(x, y, w);
    if (!z)
      throw vv::error(w, op, "the face of (" + vv::name_of(a) + ", " + vv::name_of(b) +
                                 ") is not closed: the neighbourhoods around it are not symmetric");
    x = y;
    y = z;
    // The step is one-to-one on oriented edges, so the walk comes back to
    // (a, b) unless it meets a one-sided neighbour (above).
  } while (!(x == a && y == b));
  return false;
}

}  // namespace detail
}  // namespace algorithms
