// What the dual stellar schemes (Doo-Sabin, Peters and Reif's simplest
// scheme; examples/stellar_doo_sabin.vvp and stellar_peters.vvp) need
// besides the operators of stellar.hpp: the faces of a closed polygon mesh,
// each named once, so that a level can begin with a face split of every
// polygon, and an edge flip that must succeed.
#pragma once

#include <utility>
#include <vector>

#include <vv/error.hpp>
#include <vv/iteration.hpp>
#include <vv/mesh.hpp>

#include "stellar.hpp"

namespace algorithms {

//! `for (auto [a, b] : algorithms::face_starts(S)) face_split(a, b);` —
//! one oriented edge (a, b) for each face of S: the face on the left of
//! a -> b, walked (a, b) -> (b, prevto a in b) as Centroid walks it, with a
//! its lowest-labelled corner. In the order of S and of a's rotation, so
//! the same mesh gives the same list. Read it before changing S.
//! \throw vv::error when a face does not close (a boundary or an asymmetric
//! neighbourhood): the dual schemes here are for closed meshes.
template <class Tr>
std::vector<std::pair<vv::vertex<Tr>, vv::vertex<Tr>>> face_starts(const vv::mesh<Tr>& m,
                                                                     vv::where w = vv::where::here()) {
  std::vector<std::pair<vv::vertex<Tr>, vv::vertex<Tr>>> starts;
  for (vv::vertex<Tr> a : vv::each(m))
    for (vv::vertex<Tr> b : vv::each(a, w)) {
      bool lowest = true;
      for (const vv::vertex<Tr>& corner : detail::face_of(a, b, "face_starts", w))
        if (corner < a) lowest = false;
      // A face has one lowest corner and meets it once: one start each.
      if (lowest) starts.push_back({a, b});
    }
  return starts;
}

//! `FlipOrFail<vertex> flip; flip(a, b);` — Flip, where the scheme needs
//! every flip to happen: a flip that cannot happen (the edge is not between
//! two triangles, or their far corners are already joined) throws instead
//! of leaving a mesh with the wrong faces.
template <class V>
class FlipOrFail {
 public:
  void operator()(const V& a, const V& b, vv::where w = vv::where::here()) const {
    if (!Flip<V>()(a, b, w))
      throw vv::error(w, "FlipOrFail",
                      "cannot flip " + vv::name_of(a) + "-" + vv::name_of(b) +
                          ": it is not between two triangles with unjoined far corners");
  }
};

}  // namespace algorithms
