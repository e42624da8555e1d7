#include "runner/mesh_counts.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace vvi {

mesh_counts count_mesh(const vv_geometry& g) {
  mesh_counts c;
  c.vertices = g.vertex_count;
  c.faces = g.face_count;
  // Every side of every face, then runs of the same edge: their length is
  // the number of faces on that edge.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> sides;
  for (std::size_t f = 0; f < g.face_count; ++f) {
    const std::uint32_t* v = g.face_vertices + g.face_offsets[f];
    std::size_t k = g.face_offsets[f + 1] - g.face_offsets[f];
    for (std::size_t i = 0; i < k; ++i) sides.emplace_back(std::min(v[i], v[(i + 1) % k]), std::max(v[i], v[(i + 1) % k]));
  }
  for (std::size_t l = 0; l < g.line_count; ++l)  // a curve's segments are edges on no face
    for (std::uint32_t i = g.line_offsets[l]; i + 1 < g.line_offsets[l + 1]; ++i)
      ++c.edges;
  std::sort(sides.begin(), sides.end());
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i;
    while (j < sides.size() && sides[j] == sides[i]) ++j;
    ++c.edges;
    if (j - i == 1) ++c.boundary_edges;
    if (j - i >= 3) ++c.non_manifold_edges;
    i = j;
  }
  return c;
}

}  // namespace vvi
