// Building a vertex-vertex mesh from a polygon list (the form every
// standard mesh format has), with counter-clockwise faces.
//
// A counter-clockwise face (.., a, b, c, ..) puts c immediately before a in
// the rotation of b. Collecting these links around b gives one cycle for an
// interior vertex and open chains for a boundary vertex; the neighbourhood
// lists the chains, then the cycles, in the order the faces mention them.
#pragma once

#include <algorithm>
#include <array>
#include <limits>
#include <cstdint>
#include <string>
#include <vector>

#include "../edits.hpp"
#include "../mesh.hpp"
#include "face_check.hpp"
#include "positions.hpp"

namespace vv {

//! Replaces the contents of m by the polygon mesh (positions go to the
//! `pos` property when there is one). `source` names the input in errors;
//! w is where the edits are noted (vvinterpreter --check names that line),
//! the caller's line by default.
template <class Tr>
void build_from_faces(mesh<Tr>& m, const std::vector<std::array<double, 3>>& points,
                      const std::vector<std::vector<std::uint32_t>>& faces,
                      const std::string& source, where w = where::here()) {
  context<Tr>* ctx = m.ctx();
  if (!ctx) throw error(source, 0, "the mesh has no context to create vertices in");
  const std::size_t n = points.size();
  // Links around each vertex b, stored contiguously (CSR): (c, a) means
  // "c comes right before a around b".
  std::vector<std::size_t> first(n + 1, 0);
  constexpr std::size_t unseen = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> seen_in_face(n, unseen);  // the last face that listed each vertex
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto& face = faces[f];
    auto fail = [&](const std::string& problem) {
      throw error(source, 0, "face " + std::to_string(f) + ": " + problem);
    };
    std::string few = io::too_few_corners(face.size());
    if (!few.empty()) fail(few);
    for (std::uint32_t b : face) {
      if (b >= n) fail(io::missing_vertex_problem(b, n, 0));
      if (seen_in_face[b] == f) fail("the face lists vertex " + std::to_string(b) + " twice");
      seen_in_face[b] = f;
      ++first[b + 1];
    }
  }
  for (std::size_t i = 0; i < n; ++i) first[i + 1] += first[i];
  std::vector<std::pair<std::uint32_t, std::uint32_t>> links(first[n]);
  {
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for (const auto& face : faces)
      for (std::size_t i = 0, k = face.size(); i < k; ++i)
        links[fill[face[i]]++] = {face[(i + 1) % k], face[(i + k - 1) % k]};
  }

  // Where each vertex's list starts: at the next corner of the first face
  // that lists the vertex first. The writers list each face from its first
  // vertex and in the order of that vertex's list, so a file written by vv
  // reads back to lists that write it out again byte for byte.
  constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> start_at(n, none);
  for (const auto& face : faces)
    if (face.size() >= 2 && start_at[face[0]] == none) start_at[face[0]] = face[1];

  std::vector<std::vector<std::uint32_t>> rotation(n);
  std::vector<bool> placed;
  for (std::uint32_t b = 0; b < n; ++b) {
    const auto* lb = links.data() + first[b];
    const std::size_t count = first[b + 1] - first[b];
    // Valences are small: linear scans beat hashing here.
    auto next_of = [&](std::uint32_t c) -> std::ptrdiff_t {
      for (std::size_t i = 0; i < count; ++i)
        if (lb[i].first == c) return static_cast<std::ptrdiff_t>(i);
      return -1;
    };
    auto has_incoming = [&](std::uint32_t x) {
      for (std::size_t i = 0; i < count; ++i)
        if (lb[i].second == x) return true;
      return false;
    };
    for (std::size_t i = 0; i < count; ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (lb[i].first == lb[j].first || lb[i].second == lb[j].second)
          throw error(source, 0,
                      "vertex " + std::to_string(b) +
                          " is not a manifold vertex: two faces share an edge at it with the "
                          "same orientation");
    std::vector<std::uint32_t>& out = rotation[b];
    placed.assign(count, false);  // by link index of the entry's `c`
    auto walk = [&](std::size_t i) {
      std::uint32_t x = lb[i].first;
      while (true) {
        std::ptrdiff_t j = next_of(x);
        if (j >= 0 && placed[static_cast<std::size_t>(j)]) break;
        out.push_back(x);
        if (j < 0) break;  // end of a chain
        placed[static_cast<std::size_t>(j)] = true;
        x = lb[j].second;
      }
    };
    for (std::size_t i = 0; i < count; ++i)  // chains start where nothing links in
      if (!placed[i] && !has_incoming(lb[i].first)) walk(i);
    for (std::size_t i = 0; i < count; ++i)  // what is left lies on cycles
      if (!placed[i]) walk(i);
    auto start = std::find(out.begin(), out.end(), start_at[b]);
    if (start != out.end()) std::rotate(out.begin(), start, out.end());
  }

  mesh<Tr> fresh(*ctx);
  std::vector<vertex<Tr>> created;
  created.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    created.push_back(ctx->new_vertex());
    if constexpr (detail::has_pos<typename Tr::vertex_props>::value)
      detail::set_xyz(created.back().props().pos, points[i]);
  }
  std::vector<vertex<Tr>> list;
  for (std::size_t i = 0; i < n; ++i) {
    list.clear();
    for (std::uint32_t j : rotation[i]) list.push_back(created[j]);
    make_nb_from(created[i], list, w);
    fresh.add(created[i], w);
  }
  static_cast<typename Tr::mesh_props&>(fresh) = static_cast<const typename Tr::mesh_props&>(m);
  m = std::move(fresh);
}

}  // namespace vv
