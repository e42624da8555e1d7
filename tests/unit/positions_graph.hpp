// The smallest model the geometric tests need: vertices with a position
// and nothing else (no half-edge records, no mesh properties).
#pragma once

#include <util/point.hpp>
#include <vv/vv.hpp>

namespace positions_graph {

struct props {
  util::Point<double> pos;
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos);
  }
};
using graph = vv::graph<props>;
using vertex = graph::vertex;

}  // namespace positions_graph
