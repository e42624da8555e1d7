// Curves: a mesh none of whose vertices has more than two neighbours is a
// curve or polygon, not a surface. Its face orbits would be the two sides
// of a polygon; it is drawn and written as polylines instead (an OBJ file
// holds them as `l` lines).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "faces.hpp"

namespace vv {

//! True when m has members and none of them has more than two neighbours.
template <class Tr>
bool is_curve(const mesh<Tr>& m) {
  if (m.empty()) return false;
  for (std::uint32_t id : m.slots())
    if (id && m.ctx()->nb(id).size() > 2) return false;
  return true;
}

//! The polylines of a curve, as positions of the members in iteration
//! order: open ones from an end, closed ones ending with their first vertex
//! again. A member with no neighbour in the mesh is on no polyline.
template <class Tr>
std::vector<std::vector<std::size_t>> polylines(const mesh<Tr>& m) {
  constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::vector<std::size_t>> lines;
  context<Tr>* ctx = m.ctx();
  if (!ctx || m.empty()) return lines;
  std::vector<std::uint32_t> pos = member_positions(m);
  // Adjacency both ways, so a one-sided neighbourhood still joins.
  std::vector<std::vector<std::size_t>> adjacent(m.size());
  for (std::uint32_t id : m.slots()) {
    if (!id) continue;
    for (const auto& e : ctx->nb(id)) {
      std::uint32_t u = detail::entry_id(e);
      if (u >= pos.size() || pos[u] == none) continue;
      auto link = [&](std::size_t a, std::size_t b) {
        for (std::size_t x : adjacent[a])
          if (x == b) return;
        adjacent[a].push_back(b);
      };
      link(pos[id], pos[u]);
      link(pos[u], pos[id]);
    }
  }
  std::vector<char> visited(m.size(), 0);
  auto walk_from = [&](std::size_t start) {
    std::vector<std::size_t> line{start};
    visited[start] = 1;
    for (std::size_t at = start;;) {
      std::size_t next = none;
      for (std::size_t x : adjacent[at])
        if (!visited[x]) {
          next = x;
          break;
        }
      if (next == none) {
        bool closes = false;
        for (std::size_t x : adjacent[at]) closes = closes || x == start;
        if (line.size() > 2 && closes) line.push_back(start);
        break;
      }
      visited[next] = 1;
      line.push_back(next);
      at = next;
    }
    if (line.size() >= 2) lines.push_back(std::move(line));
  };
  for (std::size_t i = 0; i < adjacent.size(); ++i)  // open curves, from an end
    if (!visited[i] && adjacent[i].size() == 1) walk_from(i);
  for (std::size_t i = 0; i < adjacent.size(); ++i)  // closed ones
    if (!visited[i] && !adjacent[i].empty()) walk_from(i);
  return lines;
}

}  // namespace vv
