// Reference 2: CGAL's Loop subdivision on a Surface_mesh of double points.
#include "bench_result.hpp"
#include "heap_usage.hpp"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include <chrono>
#include <stdexcept>

namespace {

using kernel = CGAL::Simple_cartesian<double>;
using cgal_mesh = CGAL::Surface_mesh<kernel::Point_3>;

void build(cgal_mesh& mesh, const bench_input& input)
{
  std::vector<cgal_mesh::Vertex_index> handles;
  handles.reserve(input.points.size());
  for (const auto& p : input.points) handles.push_back(mesh.add_vertex(kernel::Point_3(p[0], p[1], p[2])));
  for (const auto& t : input.triangles)
    if (mesh.add_face(handles[t[0]], handles[t[1]], handles[t[2]]) == cgal_mesh::null_face())
      throw std::runtime_error("CGAL rejected a triangle (non-manifold input)");
}

}  // namespace

bench_result run_cgal_loop(const bench_input& input, int levels, bool keep_positions)
{
  bench_result result;
  const std::size_t heap_before = heap_in_use();
  cgal_mesh mesh;
  build(mesh, input);

  const auto start = std::chrono::steady_clock::now();
  CGAL::Subdivision_method_3::Loop_subdivision(
      mesh, CGAL::parameters::number_of_iterations(static_cast<unsigned int>(levels)));
  const auto stop = std::chrono::steady_clock::now();
  result.ms = std::chrono::duration<double, std::milli>(stop - start).count();
  result.bytes = heap_in_use() - heap_before;

  result.vertices = mesh.number_of_vertices();
  result.faces = mesh.number_of_faces();
  if (keep_positions) {
    result.positions.reserve(mesh.number_of_vertices());
    for (const auto v : mesh.vertices()) {
      const auto& p = mesh.point(v);
      result.positions.push_back({p.x(), p.y(), p.z()});
    }
  }
  return result;
}
