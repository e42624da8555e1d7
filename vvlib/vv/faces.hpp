// Faces of a vertex-vertex system: the orbits of oriented edges. From the
// oriented edge (a, b) the orbit goes on to (b, prevto a in b); with
// counter-clockwise neighbourhoods this walks each face counter-clockwise
// seen from outside (LANGUAGE.md section 1), so normals point outwards.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "detail/nb_access.hpp"
#include "mesh.hpp"

namespace vv {

struct orbit_set {
  //! Closed orbits, as positions of the vertices in the mesh's iteration
  //! order, each starting from the first vertex (in that order) that begins
  //! one of its edges, in the order they are found.
  std::vector<std::vector<std::uint32_t>> faces;
  //! Oriented edges whose walk leaves the mesh or meets an asymmetric pair.
  std::size_t broken_edges = 0;
  //! Closed orbits longer than the limit (holes, boundaries), not listed.
  std::size_t long_orbits = 0;
};

//! Position of each member in iteration order, indexed by slot.
template <class Tr>
std::vector<std::uint32_t> member_positions(const mesh<Tr>& m) {
  constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> pos(m.ctx() ? m.ctx()->slot_count() : 0, none);
  std::uint32_t i = 0;
  for (std::uint32_t id : m.slots())
    if (id) pos[id] = i++;
  return pos;
}

//! The face orbits of a mesh; orbits longer than max_face are not listed.
template <class Tr>
orbit_set orbits(const mesh<Tr>& m, std::size_t max_face = std::numeric_limits<std::size_t>::max()) {
  constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  orbit_set result;
  context<Tr>* ctx = m.ctx();
  if (!ctx || m.empty()) return result;
  std::vector<std::uint32_t> pos = member_positions(m);
  std::vector<std::uint32_t> members;
  members.reserve(m.size());
  for (std::uint32_t id : m.slots())
    if (id) members.push_back(id);
  // Oriented edge (v, j-th neighbour of v) has number first_edge[pos v] + j.
  std::vector<std::size_t> first_edge(members.size() + 1, 0);
  for (std::size_t i = 0; i < members.size(); ++i)
    first_edge[i + 1] = first_edge[i] + ctx->nb(members[i]).size();
  std::vector<bool> visited(first_edge.back(), false);

  std::vector<std::uint32_t> face;
  for (std::size_t i = 0; i < members.size(); ++i) {
    const auto& nb = ctx->nb(members[i]);
    for (std::uint32_t j = 0; j < nb.size(); ++j) {
      std::size_t start = first_edge[i] + j;
      if (visited[start] || pos[detail::entry_id(nb[j])] == none) continue;
      face.clear();
      std::uint32_t a = members[i], b = detail::entry_id(nb[j]);
      std::size_t edge = start;
      bool closed = false;
      while (true) {
        if (visited[edge]) break;  // joined another walk: not a simple orbit
        visited[edge] = true;
        face.push_back(pos[a]);
        const auto& bnb = ctx->nb(b);
        std::int32_t at = detail::find(bnb, a);
        if (at < 0) break;
        std::uint32_t k = static_cast<std::uint32_t>((at + bnb.size() - 1) % bnb.size());
        std::uint32_t c = detail::entry_id(bnb[k]);
        if (pos[c] == none) break;
        edge = first_edge[pos[b]] + k;
        a = b;
        b = c;
        if (edge == start) {
          closed = true;
          break;
        }
      }
      if (!closed) result.broken_edges += face.size();
      else if (face.size() > max_face) ++result.long_orbits;
      else result.faces.push_back(face);
    }
  }
  return result;
}

//! The closed face orbits (see orbits()).
template <class Tr>
std::vector<std::vector<std::uint32_t>> face_orbits(
    const mesh<Tr>& m, std::size_t max_face = std::numeric_limits<std::size_t>::max()) {
  return orbits(m, max_face).faces;
}

//! The closed face orbits as vertex handles: the same faces, in the same
//! order and from the same first vertex, as face_orbits() gives positions.
template <class Tr>
std::vector<std::vector<vertex<Tr>>> face_vertices(
    const mesh<Tr>& m, std::size_t max_face = std::numeric_limits<std::size_t>::max()) {
  std::vector<std::vector<std::uint32_t>> orbits_by_position = orbits(m, max_face).faces;
  std::vector<std::uint32_t> members;
  members.reserve(m.size());
  for (std::uint32_t id : m.slots())
    if (id) members.push_back(id);
  std::vector<std::vector<vertex<Tr>>> out(orbits_by_position.size());
  for (std::size_t f = 0; f < out.size(); ++f) {
    out[f].reserve(orbits_by_position[f].size());
    for (std::uint32_t at : orbits_by_position[f])
      out[f].push_back(vertex<Tr>::from_slot(m.ctx(), members[at]));
  }
  return out;
}

//! Oriented edges that lie on no closed orbit.
template <class Tr>
std::size_t face_orbit_failures(const mesh<Tr>& m) {
  return orbits(m).broken_edges;
}

//! Undirected edges between members: half the oriented edges.
template <class Tr>
std::size_t edge_count(const mesh<Tr>& m) {
  std::vector<std::uint32_t> pos = member_positions(m);
  std::size_t oriented = 0;
  for (std::uint32_t id : m.slots())
    if (id)
      for (const auto& e : m.ctx()->nb(id))
        if (pos[detail::entry_id(e)] != std::numeric_limits<std::uint32_t>::max()) ++oriented;
  return oriented / 2;
}

//! V - E + F of a mesh with symmetric neighbourhoods.
template <class Tr>
long euler_characteristic(const mesh<Tr>& m) {
  return static_cast<long>(m.size()) - static_cast<long>(edge_count(m)) +
         static_cast<long>(orbits(m).faces.size());
}

}  // namespace vv
