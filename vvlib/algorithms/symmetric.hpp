// vv 1.1 algorithms::Symmetric: make neighbourhoods symmetric again.
//
// For each v and each u in v* with v missing from u*, v is put into u*
// where the face orbits need it: before w1 = prevto u in v if w1 is in u*
// (the triangle u, v, w1), else after w2 = nextto u in v if w2 is in u* (the
// triangle w2, v, u), else at the end of u*.
#pragma once

#include <vv/edits.hpp>
#include <vv/iteration.hpp>
#include <vv/mesh.hpp>
#include <vv/queries.hpp>

namespace algorithms {

template <class V>
class Symmetric {
 public:
  //! Repairs the pairs (v, u) for every u in v*.
  void operator()(const V& v, vv::where w = vv::where::here()) const {
    for (V u : vv::each(v, w)) {
      if (vv::is_in(v, u, w)) continue;
      V w1 = vv::prev_to(u, v, w), w2 = vv::next_to(u, v, w);
      if (w1 && w1 != u && vv::is_in(w1, u, w)) vv::splice_before(v, w1, u, w);
      else if (w2 && w2 != u && vv::is_in(w2, u, w)) vv::splice_after(v, w2, u, w);
      else append(v, u, w);
    }
  }
  //! Repairs every member of a mesh.
  template <class Tr>
  void operator()(const vv::mesh<Tr>& m, vv::where w = vv::where::here()) const {
    for (V v : vv::each(m)) (*this)(v, w);
  }

 private:
  static void append(const V& x, const V& u, vv::where w) {
    if (vv::valence(u, w) == 0) vv::make_nb(u, {x}, w);
    else vv::splice_after(x, vv::prev_to(vv::any_in(u, w), u, w), u, w);  // after the last entry
  }
};

}  // namespace algorithms
