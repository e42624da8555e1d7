#include "bench_input.hpp"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>

namespace {

using point = std::array<double, 3>;

point sub(const point& a, const point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double dot(const point& a, const point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
point cross(const point& a, const point& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
point normalized(const point& p)
{
  const double len = std::sqrt(dot(p, p));
  return {p[0] / len, p[1] / len, p[2] / len};
}

bench_input icosahedron()
{
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
  bench_input ico;
  for (double s : {-1.0, 1.0})
    for (double t : {-phi, phi}) {
      ico.points.push_back({s, t, 0});
      ico.points.push_back({0, s, t});
      ico.points.push_back({t, 0, s});
    }
  // Faces are the triples of mutually adjacent vertices (edge length 2),
  // oriented so that the normal points away from the centre.
  const auto adjacent = [&](std::uint32_t i, std::uint32_t j) {
    const point d = sub(ico.points[i], ico.points[j]);
    return dot(d, d) < 4.0 + 1e-9;
  };
  const std::uint32_t n = static_cast<std::uint32_t>(ico.points.size());
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b)
      for (std::uint32_t c = b + 1; c < n; ++c) {
        if (!adjacent(a, b) || !adjacent(b, c) || !adjacent(a, c)) continue;
        const point normal = cross(sub(ico.points[b], ico.points[a]), sub(ico.points[c], ico.points[a]));
        if (dot(normal, ico.points[a]) > 0)
          ico.triangles.push_back({a, b, c});
        else
          ico.triangles.push_back({a, c, b});
      }
  for (point& p : ico.points) p = normalized(p);
  return ico;
}

// Splits every triangle into 4, sharing each edge's new point between its faces.
void split_on_sphere(bench_input& mesh)
{
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoint_of;
  const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
    const auto key = std::minmax(a, b);
    const auto found = midpoint_of.find(key);
    if (found != midpoint_of.end()) return found->second;
    const point& p = mesh.points[a];
    const point& q = mesh.points[b];
    const auto index = static_cast<std::uint32_t>(mesh.points.size());
    mesh.points.push_back(normalized({p[0] + q[0], p[1] + q[1], p[2] + q[2]}));
    midpoint_of.emplace(key, index);
    return index;
  };
  std::vector<std::array<std::uint32_t, 3>> finer;
  finer.reserve(mesh.triangles.size() * 4);
  for (const auto& t : mesh.triangles) {
    const std::uint32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
    finer.push_back({t[0], ab, ca});
    finer.push_back({t[1], bc, ab});
    finer.push_back({t[2], ca, bc});
    finer.push_back({ab, bc, ca});
  }
  mesh.triangles = std::move(finer);
}

struct read_traits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
// A polygon mesh, so that non-triangular faces are reported, not triangulated.
using read_mesh_t = OpenMesh::PolyMesh_ArrayKernelT<read_traits>;

// OpenMesh reports reader problems on its own streams; we report one line.
struct quiet_openmesh {
  quiet_openmesh() { omerr().disable(); omlog().disable(); }
  ~quiet_openmesh() { omerr().enable(); omlog().enable(); }
  quiet_openmesh(const quiet_openmesh&) = delete;
  quiet_openmesh& operator=(const quiet_openmesh&) = delete;
};

}  // namespace

bench_input make_icosphere(int subdivisions)
{
  if (subdivisions < 0) throw std::runtime_error("icosphere subdivisions must be >= 0");
  bench_input mesh = icosahedron();
  for (int i = 0; i < subdivisions; ++i) split_on_sphere(mesh);
  return mesh;
}

bench_input make_quad_torus(int n)
{
  if (n < 3) throw std::runtime_error("a quad torus needs at least 3 x 3 quads");
  const double big = 1.0, small = 0.4, two_pi = 6.283185307179586;
  bench_input mesh;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = two_pi * i / n, v = two_pi * j / n;
      mesh.points.push_back({(big + small * std::cos(v)) * std::cos(u),
                             (big + small * std::cos(v)) * std::sin(u), small * std::sin(v)});
    }
  const auto at = [n](int i, int j) { return static_cast<std::uint32_t>((i % n) * n + j % n); };
  // Around the big circle (i), then around the tube (j): counter-clockwise seen from outside.
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) mesh.quads.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
  return mesh;
}

std::vector<std::vector<std::uint32_t>> bench_input::polygons() const
{
  std::vector<std::vector<std::uint32_t>> faces;
  faces.reserve(triangles.size() + quads.size());
  for (const auto& t : triangles) faces.push_back({t[0], t[1], t[2]});
  for (const auto& q : quads) faces.push_back({q[0], q[1], q[2], q[3]});
  return faces;
}

bench_input read_input(const std::string& path)
{
  if (!std::ifstream(path)) throw std::runtime_error("cannot open input file '" + path + "'");
  read_mesh_t mesh;
  {
    const quiet_openmesh quiet;
    if (!OpenMesh::IO::read_mesh(mesh, path))
      throw std::runtime_error("OpenMesh cannot read '" + path + "' (unknown format or malformed)");
  }
  if (mesh.n_faces() == 0) throw std::runtime_error("'" + path + "' has no faces");
  for (const auto f : mesh.faces())
    if (mesh.valence(f) != 3)
      throw std::runtime_error("'" + path + "' is not a triangle mesh (face " +
                               std::to_string(f.idx()) + " has " + std::to_string(mesh.valence(f)) +
                               " corners)");
  for (const auto h : mesh.halfedges())
    if (mesh.is_boundary(h))
      throw std::runtime_error("'" + path + "' is not closed (it has boundary edges)");

  // Unused vertices are dropped: they take no part in the subdivision.
  bench_input input;
  std::vector<std::uint32_t> index(mesh.n_vertices(), std::numeric_limits<std::uint32_t>::max());
  for (const auto v : mesh.vertices()) {
    if (mesh.is_isolated(v)) continue;
    index[static_cast<std::size_t>(v.idx())] = static_cast<std::uint32_t>(input.points.size());
    const auto& p = mesh.point(v);
    input.points.push_back({p[0], p[1], p[2]});
  }
  double volume6 = 0;  // six times the signed volume: negative if inside-out
  for (const auto f : mesh.faces()) {
    std::array<std::uint32_t, 3> t{};
    std::size_t k = 0;
    for (const auto v : mesh.fv_range(f)) t[k++] = index[static_cast<std::size_t>(v.idx())];
    volume6 += dot(input.points[t[0]], cross(input.points[t[1]], input.points[t[2]]));
    input.triangles.push_back(t);
  }
  if (volume6 < 0)
    for (auto& t : input.triangles) std::swap(t[1], t[2]);
  return input;
}

double mesh_size(const bench_input& input)
{
  point lo{}, hi{};
  lo.fill(std::numeric_limits<double>::infinity());
  hi.fill(-std::numeric_limits<double>::infinity());
  for (const point& p : input.points)
    for (std::size_t i = 0; i < 3; ++i) {
      lo[i] = std::min(lo[i], p[i]);
      hi[i] = std::max(hi[i], p[i]);
    }
  const point d = sub(hi, lo);
  return std::sqrt(dot(d, d));
}
