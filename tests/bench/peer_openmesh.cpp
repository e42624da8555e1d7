// Reference 1: OpenMesh's uniform subdividers (Loop, sqrt(3), modified
// butterfly on a TriMesh; Catmull-Clark on a PolyMesh), double precision.
#include "bench_result.hpp"
#include "heap_usage.hpp"
#include "stopwatch.hpp"

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/ModifiedButterFlyT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/Sqrt3T.hh>

#include <stdexcept>
#include <string>

namespace {

// Normal must be double too: LoopT accumulates positions in the Normal type.
struct om_traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using om_tri_mesh = OpenMesh::TriMesh_ArrayKernelT<om_traits>;
using om_poly_mesh = OpenMesh::PolyMesh_ArrayKernelT<om_traits>;

template <class Mesh>
void build(Mesh& mesh, const bench_input& input)
{
  std::vector<typename Mesh::VertexHandle> handles;
  handles.reserve(input.points.size());
  for (const auto& p : input.points) handles.push_back(mesh.add_vertex({p[0], p[1], p[2]}));
  std::vector<typename Mesh::VertexHandle> corners;
  for (const auto& face : input.polygons()) {
    corners.clear();
    for (std::uint32_t i : face) corners.push_back(handles[i]);
    if (!mesh.add_face(corners).is_valid())
      throw std::runtime_error("OpenMesh rejected a face (non-manifold input)");
  }
}

// Subdivider is one of OpenMesh's uniform subdividers of Mesh.
template <class Mesh, class Subdivider>
bench_result run(const bench_input& input, int levels, bool keep_positions)
{
  bench_result result;
  const std::size_t heap_before = heap_in_use();
  Mesh mesh;
  build(mesh, input);

  const stopwatch timer;
  {
    Subdivider subdivide;
    subdivide.attach(mesh);
    subdivide(static_cast<std::size_t>(levels));
    subdivide.detach();
  }
  timer.stop(result);
  result.bytes = heap_in_use() - heap_before;

  result.vertices = mesh.n_vertices();
  result.faces = mesh.n_faces();
  if (keep_positions) {
    result.positions.reserve(mesh.n_vertices());
    for (const auto v : mesh.vertices()) {
      const auto& p = mesh.point(v);
      result.positions.push_back({p[0], p[1], p[2]});
    }
  }
  return result;
}

}  // namespace

bench_result run_openmesh_loop(const bench_input& input, int levels, bool keep_positions)
{
  return run<om_tri_mesh, OpenMesh::Subdivider::Uniform::LoopT<om_tri_mesh, double>>(input, levels, keep_positions);
}

bench_result run_openmesh_sqrt3(const bench_input& input, int levels, bool keep_positions)
{
  return run<om_tri_mesh, OpenMesh::Subdivider::Uniform::Sqrt3T<om_tri_mesh, double>>(input, levels, keep_positions);
}

bench_result run_openmesh_butterfly(const bench_input& input, int levels, bool keep_positions)
{
  return run<om_tri_mesh, OpenMesh::Subdivider::Uniform::ModifiedButterflyT<om_tri_mesh, double>>(
      input, levels, keep_positions);
}

bench_result run_openmesh_catmull_clark(const bench_input& input, int levels, bool keep_positions)
{
  return run<om_poly_mesh, OpenMesh::Subdivider::Uniform::CatmullClarkT<om_poly_mesh, double>>(
      input, levels, keep_positions);
}
