// Reference 1: OpenMesh's uniform Loop subdivider on a double-precision TriMesh.
#include "bench_result.hpp"
#include "heap_usage.hpp"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>

#include <chrono>
#include <stdexcept>
#include <string>

namespace {

// Normal must be double too: LoopT accumulates positions in the Normal type.
struct om_traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using om_mesh = OpenMesh::TriMesh_ArrayKernelT<om_traits>;

void build(om_mesh& mesh, const bench_input& input)
{
  std::vector<om_mesh::VertexHandle> handles;
  handles.reserve(input.points.size());
  for (const auto& p : input.points) handles.push_back(mesh.add_vertex({p[0], p[1], p[2]}));
  for (const auto& t : input.triangles)
    if (!mesh.add_face(handles[t[0]], handles[t[1]], handles[t[2]]).is_valid())
      throw std::runtime_error("OpenMesh rejected a triangle (non-manifold input)");
}

}  // namespace

bench_result run_openmesh_loop(const bench_input& input, int levels, bool keep_positions)
{
  bench_result result;
  const std::size_t heap_before = heap_in_use();
  om_mesh mesh;
  build(mesh, input);

  const auto start = std::chrono::steady_clock::now();
  {
    OpenMesh::Subdivider::Uniform::LoopT<om_mesh, double> loop;
    loop.attach(mesh);
    loop(static_cast<std::size_t>(levels));
    loop.detach();
  }
  const auto stop = std::chrono::steady_clock::now();
  result.ms = std::chrono::duration<double, std::milli>(stop - start).count();
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
