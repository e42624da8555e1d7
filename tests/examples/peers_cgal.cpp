// CGAL's Subdivision_method_3 on oracle::polygons (see peers.hpp).
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

#include <cstdint>
#include <vector>

#include "peers.hpp"

namespace peers {

namespace {

using kernel = CGAL::Simple_cartesian<double>;
using cgal_mesh = CGAL::Surface_mesh<kernel::Point_3>;

cgal_mesh to_cgal(const oracle::polygons& in) {
  cgal_mesh m;
  std::vector<cgal_mesh::Vertex_index> v;
  for (const auto& p : in.points) v.push_back(m.add_vertex({p[0], p[1], p[2]}));
  for (const auto& f : in.faces) {
    std::vector<cgal_mesh::Vertex_index> face;
    for (std::uint32_t i : f) face.push_back(v[i]);
    EXPECT_NE(m.add_face(face), cgal_mesh::null_face()) << "CGAL rejected a face of the input";
  }
  return m;
}

oracle::polygons from_cgal(const cgal_mesh& m) {
  // Subdivision leaves removed elements behind: number the live vertices.
  oracle::polygons out;
  std::vector<std::uint32_t> index(m.number_of_vertices() + m.number_of_removed_vertices());
  for (auto h : m.vertices()) {
    index[h.idx()] = static_cast<std::uint32_t>(out.points.size());
    out.points.push_back({m.point(h).x(), m.point(h).y(), m.point(h).z()});
  }
  for (auto f : m.faces()) {
    std::vector<std::uint32_t> face;
    for (auto h : CGAL::vertices_around_face(m.halfedge(f), m)) face.push_back(index[h.idx()]);
    out.faces.push_back(face);
  }
  return out;
}

//! `steps` steps of a CGAL subdivision method: method(mesh, named parameters).
template <class Method>
oracle::polygons subdivide(const oracle::polygons& in, unsigned steps, Method method) {
  cgal_mesh m = to_cgal(in);
  method(m, CGAL::parameters::number_of_iterations(steps));
  return from_cgal(m);
}

// The geometry policy for CGAL's PTQ refinement: linear interpolation.
struct linear_mask {
  cgal_mesh* m;
  void edge_node(cgal_mesh::Halfedge_index h, kernel::Point_3& pt) {
    pt = CGAL::midpoint(m->point(m->source(h)), m->point(m->target(h)));
  }
  void vertex_node(cgal_mesh::Vertex_index v, kernel::Point_3& pt) { pt = m->point(v); }
  void border_node(cgal_mesh::Halfedge_index h, kernel::Point_3& ept, kernel::Point_3& vpt) {
    edge_node(h, ept);
    vpt = m->point(m->target(h));
  }
};

}  // namespace

oracle::polygons cgal_loop(const oracle::polygons& in, unsigned steps) {
  return subdivide(in, steps, [](auto& m, auto params) { CGAL::Subdivision_method_3::Loop_subdivision(m, params); });
}

oracle::polygons cgal_sqrt3(const oracle::polygons& in, unsigned steps) {
  return subdivide(in, steps, [](auto& m, auto params) { CGAL::Subdivision_method_3::Sqrt3_subdivision(m, params); });
}

oracle::polygons cgal_catmull_clark(const oracle::polygons& in, unsigned steps) {
  return subdivide(in, steps,
                   [](auto& m, auto params) { CGAL::Subdivision_method_3::CatmullClark_subdivision(m, params); });
}

oracle::polygons cgal_doo_sabin(const oracle::polygons& in, unsigned steps) {
  return subdivide(in, steps, [](auto& m, auto params) { CGAL::Subdivision_method_3::DooSabin_subdivision(m, params); });
}

oracle::polygons cgal_midpoint(const oracle::polygons& in, unsigned steps) {
  return subdivide(in, steps,
                   [](cgal_mesh& m, auto params) { CGAL::Subdivision_method_3::PTQ(m, linear_mask{&m}, params); });
}

}  // namespace peers
