// vv 1.1 <algorithms/render.hpp>: immediate-mode drawing of a mesh for
// render blocks. Each drawer opens one GL primitive and calls the vertex
// property member glRender() for every vertex it emits:
//
//   algorithms::Draw(S, algorithms::DrawTriangles());
//
// Triangles and quads are the cycles around each vertex that start with
// consecutive neighbours, emitted counter-clockwise and once each (from
// their lowest-labelled corner). The plain drawers trust that such cycles
// are faces; the "Checked" ones emit only closed face orbits of that
// length. DrawTriAndQuads draws the face orbits of length 3 and 4.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include <vv/iteration.hpp>
#include <vv/mesh.hpp>
#include <vv/faces.hpp>
#include <vv/queries.hpp>

namespace algorithms {

namespace detail {

template <class V>
void emit(const V& v) {
  v->glRender();
}

// True when the corners are a closed face orbit of exactly that length.
template <class V, std::size_t K>
bool is_face(const V (&corner)[K]) {
  for (std::size_t i = 0; i < K; ++i)
    if (vv::prev_to(corner[i], corner[(i + 1) % K]) != corner[(i + 2) % K]) return false;
  return true;
}

// Calls f(corners) for each k-cycle (v, u, ..., w) with u, w consecutive
// around v, v its lowest label; `checked` keeps only face orbits.
template <std::size_t K, class Tr, class F>
void for_each_cycle(const vv::mesh<Tr>& m, bool checked, F&& f) {
  using V = vv::vertex<Tr>;
  for (V v : vv::each(m)) {
    for (V u : vv::each(v)) {
      V w = vv::next_to(u, v);
      if (u == w) continue;
      V corner[K];
      corner[0] = v;
      corner[1] = u;
      if constexpr (K == 3) {
        corner[2] = w;
      } else {
        corner[2] = vv::prev_to(v, u);  // the corner opposite v
        corner[3] = w;
        if (!corner[2] || corner[2] == v || corner[2] == w) continue;
      }
      bool lowest = true;
      for (std::size_t i = 1; i < K; ++i) lowest = lowest && v < corner[i];
      if (!lowest || (checked && !is_face(corner))) continue;
      f(corner);
    }
  }
}

}  // namespace detail

//! Runs a drawer on a mesh.
template <class Mesh, class Drawer>
void Draw(const Mesh& m, const Drawer& drawer) {
  drawer(m);
}

//! Every vertex as a GL point.
template <class V = void>
struct DrawPoints {
  template <class Tr>
  void operator()(const vv::mesh<Tr>& m) const {
    glBegin(GL_POINTS);
    for (auto v : vv::each(m)) detail::emit(v);
    glEnd();
  }
};

//! Every edge once as a GL line (an asymmetric pair too).
template <class V = void>
struct DrawWireframe {
  template <class Tr>
  void operator()(const vv::mesh<Tr>& m) const {
    glBegin(GL_LINES);
    for (auto v : vv::each(m))
      for (auto u : vv::each(v))
        if (v < u || !vv::is_in(v, u)) detail::emit(v), detail::emit(u);
    glEnd();
  }
};

template <bool Checked>
struct draw_triangles_impl {
  template <class Tr>
  void operator()(const vv::mesh<Tr>& m) const {
    glBegin(GL_TRIANGLES);
    detail::for_each_cycle<3>(m, Checked, [](const auto& c) {
      for (const auto& v : c) detail::emit(v);
    });
    glEnd();
  }
};
template <bool Checked>
struct draw_quads_impl {
  template <class Tr>
  void operator()(const vv::mesh<Tr>& m) const {
    glBegin(GL_QUADS);
    detail::for_each_cycle<4>(m, Checked, [](const auto& c) {
      for (const auto& v : c) detail::emit(v);
    });
    glEnd();
  }
};

template <class V = void>
struct DrawTriangles : draw_triangles_impl<false> {};
template <class V = void>
struct DrawTrianglesChecked : draw_triangles_impl<true> {};
template <class V = void>
struct DrawQuads : draw_quads_impl<false> {};
template <class V = void>
struct DrawQuadsChecked : draw_quads_impl<true> {};

//! The face orbits of three and four corners, as triangles and quads.
template <class V = void>
struct DrawTriAndQuads {
  template <class Tr>
  void operator()(const vv::mesh<Tr>& m) const {
    std::vector<vv::vertex<Tr>> members;
    for (auto v : vv::each(m)) members.push_back(v);
    auto faces = vv::face_orbits(m, 4);
    for (std::size_t k : {std::size_t(3), std::size_t(4)}) {
      glBegin(k == 3 ? GL_TRIANGLES : GL_QUADS);
      for (const auto& f : faces)
        if (f.size() == k)
          for (std::uint32_t i : f) detail::emit(members[i]);
      glEnd();
    }
  }
};
//! vv 1.1 spelling.
template <class V = void>
struct DrawTriAndQuds : DrawTriAndQuads<V> {};

}  // namespace algorithms
