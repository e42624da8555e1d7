// The vvlib contender: the Loop program of examples/cpp/loop_subdivision.hpp,
// i.e. the C++ a translated vv program runs (synchronise, forall, old
// state, replace/make), on a mesh built from the same triangles.
#include "bench_result.hpp"
#include "heap_usage.hpp"
#include "stopwatch.hpp"

#include <vector>

#include <vv/io/from_faces.hpp>

#include "../../examples/cpp/loop_subdivision.hpp"

bench_result run_vvlib_loop(const bench_input& input, int levels, bool keep_positions) {
  using graph = loop_example::graph;
  bench_result result;
  std::vector<std::vector<std::uint32_t>> faces;
  faces.reserve(input.triangles.size());
  for (const auto& t : input.triangles) faces.push_back({t[0], t[1], t[2]});

  const std::size_t heap_before = heap_in_use();
  {
    graph::context ctx;
    graph::mesh S(ctx);
    vv::build_from_faces(S, input.points, faces, "bench input");

    const stopwatch timer;
    for (int i = 0; i < levels; ++i) loop_example::subdivide(S);
    timer.stop(result);
    result.bytes = heap_in_use() - heap_before;

    result.vertices = S.size();
    result.faces = vv::face_orbits(S).size();
    if (keep_positions) {
      result.positions.reserve(S.size());
      for (graph::vertex v : vv::each(S)) {
        const auto& p = v.props().pos;
        result.positions.push_back({p.x(), p.y(), p.z()});
      }
    }
  }
  return result;
}
