// vvlib: the vertex-vertex data structure and algebra, in one include.
//
//   struct VP { util::Point<double> pos; template <class F> void vv_fields(F&& f) { f("pos", pos); } };
//   using G = vv::graph<VP>;             // or vv::graph<VP, EdgeProps, MeshProps>
//   G::context ctx;
//   G::mesh S(ctx);
//   G::vertex v = ctx.new_vertex();
//
// See docs/library.md for the whole API.
#pragma once

#include "context.hpp"
#include "edges.hpp"
#include "edits.hpp"
#include "error.hpp"
#include "invariants.hpp"
#include "io/vvm.hpp"
#include "iteration.hpp"
#include "mesh.hpp"
#include "faces.hpp"
#include "insert.hpp"
#include "parallel.hpp"
#include "path.hpp"
#include "queries.hpp"
#include "target_first.hpp"
#include "uncounted.hpp"
#include "vertex.hpp"

namespace vv {

//! The types of one model, named as a vv program names them.
template <class VertexProps, class EdgeProps = no_props, class MeshProps = no_props,
          unsigned InlineValence = 6>
struct graph {
  using traits = vv::traits<VertexProps, EdgeProps, MeshProps, InlineValence>;
  using context = vv::context<traits>;
  using vertex = vv::vertex<traits>;
  using old_vertex = vv::old_vertex<traits>;
  using mesh = vv::mesh<traits>;
  using edge = EdgeProps;
};

}  // namespace vv
