// What the panel counts of the drawn mesh: vertices, edges, faces, and the
// edges that show trouble (on one face only: a boundary; on three or more:
// not a manifold).
#pragma once

#include <cstddef>

#include <model/abi.hpp>

namespace vvi {

struct mesh_counts {
  std::size_t vertices = 0, edges = 0, faces = 0;
  std::size_t boundary_edges = 0, non_manifold_edges = 0;
};

mesh_counts count_mesh(const vv_geometry& g);

}  // namespace vvi
