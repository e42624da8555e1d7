// vv 1.1 stellar operations on triangulated (or polygonal) vertex-vertex
// meshes with symmetric, counter-clockwise neighbourhoods (Velho's stellar
// subdivision grammars are sequences of these).
//
// A counter-clockwise face (.., p, c, n, ..) has n immediately before p in
// the rotation of its corner c. So, naming an edge a-b, l = nextto b in a
// and r = prevto b in a are the third corners of the two triangles
// (a, b, l) and (a, r, b) beside it.
#pragma once

#include <vector>

#include <vv/edits.hpp>
#include <vv/io/positions.hpp>
#include <vv/iteration.hpp>
#include <vv/queries.hpp>

#include "face_walk.hpp"
#include "insert.hpp"

namespace algorithms {

namespace detail {

template <class V>
void require_edge(const V& a, const V& b, const char* op, vv::where w) {
  if (!a || !b) throw vv::error(w, op, "an end of the edge is the null vertex");
  if (!vv::is_in(b, a, w) || !vv::is_in(a, b, w))
    throw vv::error(w, op, vv::name_of(a) + " and " + vv::name_of(b) + " are not mutual neighbours");
}

// The corners of the face orbit that starts with the oriented edge (a, b).
template <class V>
std::vector<V> face_of(const V& a, const V& b, const char* op, vv::where w) {
  std::vector<V> face;
  walk_face(a, b, op, w, [&](const V& x, const V&) {
    face.push_back(x);
    return false;
  });
  return face;
}

}  // namespace detail

//! `EdgeSplit<vertex> split; x = split(a, b);` — a new vertex x on the
//! edge a-b, joined to the opposite corners l and r (each triangle beside
//! the edge becomes two). Its position is the edge midpoint when vertices
//! have a `pos`.
template <class V>
class EdgeSplit {
 public:
  V operator()(const V& a, const V& b, vv::where w = vv::where::here()) const {
    detail::require_edge(a, b, "EdgeSplit", w);
    V l = vv::next_to(b, a, w), r = vv::prev_to(b, a, w);
    V x = Insert<V>()(a, b, w);  // x* = {a, b}
    using P = typename V::traits_type::vertex_props;
    if constexpr (vv::detail::has_pos<P>::value) x->pos = (a->pos + b->pos) * 0.5;
    // The triangles (a, x, l), (x, b, l), (a, r, x), (x, r, b): around x
    // a, r, b, l; around r, x comes after b; around l, after a.
    if (r && r != b && vv::is_in(a, r, w) && vv::is_in(b, r, w)) {
      vv::splice_after(r, a, x, w);
      vv::splice_after(x, b, r, w);
    }
    if (l && l != b && l != r && vv::is_in(a, l, w) && vv::is_in(b, l, w)) {
      vv::splice_after(l, b, x, w);
      vv::splice_after(x, a, l, w);
    }
    return x;
  }
};

//! `Flip<vertex> flip; flip(a, b);` — replaces the edge a-b by l-r in the
//! two triangles beside it. Returns false (and changes nothing) when that is
//! impossible: no two distinct opposite corners, or l and r already joined.
template <class V>
class Flip {
 public:
  bool operator()(const V& a, const V& b, vv::where w = vv::where::here()) const {
    detail::require_edge(a, b, "Flip", w);
    V l = vv::next_to(b, a, w), r = vv::prev_to(b, a, w);
    if (!l || !r || l == r || l == b || r == b) return false;
    if (vv::prev_to(a, b, w) != l || vv::next_to(a, b, w) != r) return false;  // not two triangles
    if (vv::is_in(r, l, w) || vv::is_in(l, r, w)) return false;
    // The new triangles (a, r, l) and (r, b, l).
    vv::erase_from(b, a, w);
    vv::erase_from(a, b, w);
    vv::splice_after(l, b, r, w);  // around r: b, l, a
    vv::splice_after(r, a, l, w);  // around l: a, r, b
    return true;
  }
};

//! `Centroid<vertex> centroid; x = centroid(a, b);` — a new vertex x in
//! the face whose orbit starts with the oriented edge (a, b), joined to all
//! its corners (a k-gon becomes k triangles). Its position is the average
//! of the corners when vertices have a `pos`.
template <class V>
class Centroid {
 public:
  V operator()(const V& a, const V& b, vv::where w = vv::where::here()) const {
    detail::require_edge(a, b, "Centroid", w);
    std::vector<V> face = detail::face_of(a, b, "Centroid", w);
    V x = a.ctx()->new_vertex();
    vv::make_nb_from(x, face, w);  // the triangles (face[i], face[i+1], x)
    const std::size_t k = face.size();
    for (std::size_t i = 0; i < k; ++i)  // around face[i]: face[i+1], x, face[i-1]
      vv::splice_after(x, face[(i + 1) % k], face[i], w);
    using P = typename V::traits_type::vertex_props;
    if constexpr (vv::detail::has_pos<P>::value) {
      auto sum = face[0]->pos;
      for (std::size_t i = 1; i < k; ++i) sum += face[i]->pos;
      x->pos = sum / static_cast<double>(k);
    }
    return x;
  }
};

//! `Remove<vertex> remove; remove(v);` — takes v out of every neighbour's
//! rotation and empties v*, so the faces around v merge into one polygon
//! (the inverse of Centroid). With a mesh, v also leaves the mesh.
template <class V>
class Remove {
 public:
  void operator()(const V& v, vv::where w = vv::where::here()) const {
    if (!v) throw vv::error(w, "Remove", "cannot remove the null vertex");
    for (V u : vv::each(v, w)) vv::erase_from(v, u, w);
    vv::make_nb(v, {}, w);
  }
  template <class Mesh>
  void operator()(const V& v, Mesh& m, vv::where w = vv::where::here()) const {
    (*this)(v, w);
    m.remove(v);
  }
};

//! `p = halfway_to_average(v, ring);` — ½ v + 1/(2k) (r1 + .. + rk): v
//! moved halfway to the average of the k points of `ring`. The smoothing
//! rule of the stellar Catmull-Clark (catm, ring: the one-ring after the
//! face split) and 4-8 (velh) grammars; the scheme chooses the ring.
template <class P>
P halfway_to_average(const P& v, const std::vector<P>& ring, vv::where w = vv::where::here()) {
  if (ring.empty()) throw vv::error(w, "halfway_to_average", "the ring is empty: there is no average");
  P sum = ring[0];
  for (std::size_t i = 1; i < ring.size(); ++i) sum += ring[i];
  return v * 0.5 + sum * (0.5 / static_cast<double>(ring.size()));
}

}  // namespace algorithms
