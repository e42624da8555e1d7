// Reference 3: OpenSubdiv's CPU refinement (Far): uniform refinement of the
// topology with Far::TopologyRefiner, then positions interpolated level by
// level with Far::PrimvarRefiner, as OpenSubdiv's own tutorials do it. The
// last level is refined with its full topology (fullTopologyInLastLevel), so
// that, like every other implementation here, it ends with a mesh that can
// be refined again.
#include "bench_result.hpp"
#include "heap_usage.hpp"
#include "stopwatch.hpp"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <memory>
#include <stdexcept>

namespace {

using namespace OpenSubdiv;

// What PrimvarRefiner interpolates: a position.
struct position {
  double x, y, z;
  void Clear() { x = y = z = 0; }
  void AddWithWeight(const position& p, double w)
  {
    x += w * p.x;
    y += w * p.y;
    z += w * p.z;
  }
};

bench_result run(const bench_input& input, int levels, bool keep_positions, Sdc::SchemeType scheme)
{
  bench_result result;
  const std::size_t heap_before = heap_in_use();

  std::vector<int> corners_per_face, corners;
  for (const auto& face : input.polygons()) {
    corners_per_face.push_back(static_cast<int>(face.size()));
    for (std::uint32_t i : face) corners.push_back(static_cast<int>(i));
  }
  Far::TopologyDescriptor desc;
  desc.numVertices = static_cast<int>(input.points.size());
  desc.numFaces = static_cast<int>(corners_per_face.size());
  desc.numVertsPerFace = corners_per_face.data();
  desc.vertIndicesPerFace = corners.data();
  Sdc::Options options;
  options.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  using factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  std::unique_ptr<Far::TopologyRefiner> refiner(factory::Create(desc, factory::Options(scheme, options)));
  if (!refiner) throw std::runtime_error("OpenSubdiv rejected the input mesh");

  const stopwatch timer;
  Far::TopologyRefiner::UniformOptions uniform(levels);
  uniform.fullTopologyInLastLevel = true;
  refiner->RefineUniform(uniform);
  std::vector<position> buffer(static_cast<std::size_t>(refiner->GetNumVerticesTotal()));
  for (std::size_t i = 0; i < input.points.size(); ++i)
    buffer[i] = {input.points[i][0], input.points[i][1], input.points[i][2]};
  Far::PrimvarRefinerReal<double> primvars(*refiner);  // double weights, as the others use
  position* src = buffer.data();
  for (int level = 1; level <= levels; ++level) {
    position* dst = src + refiner->GetLevel(level - 1).GetNumVertices();
    primvars.Interpolate(level, src, dst);
    src = dst;
  }
  timer.stop(result);
  result.bytes = heap_in_use() - heap_before;

  const Far::TopologyLevel& last = refiner->GetLevel(levels);
  result.vertices = static_cast<std::size_t>(last.GetNumVertices());
  result.faces = static_cast<std::size_t>(last.GetNumFaces());
  if (keep_positions)
    for (std::size_t i = 0; i < result.vertices; ++i) result.positions.push_back({src[i].x, src[i].y, src[i].z});
  return result;
}

}  // namespace

bench_result run_opensubdiv_loop(const bench_input& input, int levels, bool keep_positions)
{
  return run(input, levels, keep_positions, Sdc::SCHEME_LOOP);
}

bench_result run_opensubdiv_catmull_clark(const bench_input& input, int levels, bool keep_positions)
{
  return run(input, levels, keep_positions, Sdc::SCHEME_CATMARK);
}
