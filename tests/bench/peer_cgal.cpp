// Reference 2: CGAL's subdivision methods (Loop, sqrt(3), Catmull-Clark,
// Doo-Sabin) on a Surface_mesh of double points.
#include "bench_result.hpp"
#include "heap_usage.hpp"
#include "stopwatch.hpp"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include <stdexcept>

namespace {

using kernel = CGAL::Simple_cartesian<double>;
using cgal_mesh = CGAL::Surface_mesh<kernel::Point_3>;

void build(cgal_mesh& mesh, const bench_input& input)
{
  std::vector<cgal_mesh::Vertex_index> handles;
  handles.reserve(input.points.size());
  for (const auto& p : input.points) handles.push_back(mesh.add_vertex(kernel::Point_3(p[0], p[1], p[2])));
  std::vector<cgal_mesh::Vertex_index> corners;
  for (const auto& face : input.polygons()) {
    corners.clear();
    for (std::uint32_t i : face) corners.push_back(handles[i]);
    if (mesh.add_face(corners) == cgal_mesh::null_face())
      throw std::runtime_error("CGAL rejected a face (non-manifold input)");
  }
}

// subdivide(mesh, levels) is one of CGAL's Subdivision_method_3 functions.
template <class Subdivide>
bench_result run(const bench_input& input, int levels, bool keep_positions, Subdivide subdivide)
{
  bench_result result;
  const std::size_t heap_before = heap_in_use();
  cgal_mesh mesh;
  build(mesh, input);

  const stopwatch timer;
  subdivide(mesh, CGAL::parameters::number_of_iterations(static_cast<unsigned int>(levels)));
  timer.stop(result);
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

}  // namespace

bench_result run_cgal_loop(const bench_input& input, int levels, bool keep_positions)
{
  return run(input, levels, keep_positions,
             [](cgal_mesh& m, const auto& np) { CGAL::Subdivision_method_3::Loop_subdivision(m, np); });
}

bench_result run_cgal_sqrt3(const bench_input& input, int levels, bool keep_positions)
{
  return run(input, levels, keep_positions,
             [](cgal_mesh& m, const auto& np) { CGAL::Subdivision_method_3::Sqrt3_subdivision(m, np); });
}

bench_result run_cgal_catmull_clark(const bench_input& input, int levels, bool keep_positions)
{
  return run(input, levels, keep_positions,
             [](cgal_mesh& m, const auto& np) { CGAL::Subdivision_method_3::CatmullClark_subdivision(m, np); });
}

bench_result run_cgal_doo_sabin(const bench_input& input, int levels, bool keep_positions)
{
  return run(input, levels, keep_positions,
             [](cgal_mesh& m, const auto& np) { CGAL::Subdivision_method_3::DooSabin_subdivision(m, np); });
}
