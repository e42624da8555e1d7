// The examples for surfaces with boundaries and features, checked against
// independent implementations:
//   loop_boundary: examples/loop.vvp on closed meshes; OpenMesh's LoopT and
//     CGAL's Loop_subdivision on the open patch; the boundary against the
//     cubic B-spline subdivision of the boundary polygon;
//   loop_creases:  examples/loop.vvp without marks; a plain C++ Loop with
//     crease, dart and corner rules on the patch; the crease vertices
//     against the curve rule;
//   loop_mobius:   a plain C++ Loop with Warren's weights on the strip's
//     triangles (no orientation needed); the topology of the result;
//   loop_adaptive: a closed manifold triangle mesh after every step, the
//     unselected vertices never move, and the selected vertices and their
//     neighbours are where examples/loop.vvp puts them.

#include <map>
#include <set>

#include "oracle.hpp"
#include "peers.hpp"


namespace {

using oracle::point;
using index_t = std::uint32_t;
using edge_key = std::pair<index_t, index_t>;  // (lower, higher)

edge_key key(index_t a, index_t b) { return {std::min(a, b), std::max(a, b)}; }

point operator+(const point& a, const point& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
point operator*(double s, const point& a) { return {s * a[0], s * a[1], s * a[2]}; }
double distance(const point& a, const point& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// ---- Reading exports with all the fields of these examples ----

struct vertex_fields {
  util::Point<double> pos;
  bool selected = false;
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos);
    f("selected", selected);
  }
};
struct edge_fields {
  bool boundary = false;
  bool crease = false;
  template <class F>
  void vv_fields(F&& f) {
    f("boundary", boundary);
    f("crease", crease);
  }
  friend bool operator==(const edge_fields& a, const edge_fields& b) {
    return a.boundary == b.boundary && a.crease == b.crease;
  }
  friend bool operator!=(const edge_fields& a, const edge_fields& b) { return !(a == b); }
};
using graph = vv::graph<vertex_fields, edge_fields>;

//! A vertex-vertex mesh as plain data: vertices in file order.
struct plain {
  std::vector<point> pts;
  std::vector<bool> selected;
  std::vector<std::vector<index_t>> nb;  // rotation order
  std::set<std::pair<index_t, index_t>> boundary_half;  // (a, b) with (a^b).boundary
  std::set<edge_key> crease;
};

plain read_plain(const std::string& vvm) {
  graph::context ctx;
  graph::mesh m(ctx);
  vv::read_vvm(m, vvm);
  std::map<unsigned, index_t> at;
  plain p;
  for (graph::vertex v : vv::each(m)) {
    at[vv::label_of(v)] = static_cast<index_t>(p.pts.size());
    p.pts.push_back({v->pos.x(), v->pos.y(), v->pos.z()});
    p.selected.push_back(v->selected);
  }
  for (graph::vertex v : vv::each(m)) {
    index_t i = at[vv::label_of(v)];
    std::vector<index_t> nb;
    for (graph::vertex u : vv::each(v)) {
      index_t j = at.at(vv::label_of(u));
      nb.push_back(j);
      if (vv::edge(v, u).boundary) p.boundary_half.insert({i, j});
      if (vv::edge(v, u).crease) p.crease.insert(key(i, j));
    }
    p.nb.push_back(nb);
  }
  return p;
}

bool beside(const plain& m, index_t a, index_t b, index_t c) {  // a, b side by side around c
  const auto& n = m.nb[c];
  for (std::size_t i = 0; i < n.size(); ++i)
    if (n[i] == a) return n[(i + 1) % n.size()] == b || n[(i + n.size() - 1) % n.size()] == b;
  return false;
}

//! The triangles of a mesh without using orientation: corners that each see
//! the other two side by side.
std::vector<std::array<index_t, 3>> triangles_of(const plain& m) {
  std::set<std::array<index_t, 3>> found;
  for (index_t v = 0; v < m.nb.size(); ++v)
    for (std::size_t i = 0; i < m.nb[v].size(); ++i) {
      index_t u = m.nb[v][i], w = m.nb[v][(i + 1) % m.nb[v].size()];
      if (u == w || !beside(m, v, w, u) || !beside(m, u, v, w)) continue;
      std::array<index_t, 3> t = {v, u, w};
      std::sort(t.begin(), t.end());
      found.insert(t);
    }
  return {found.begin(), found.end()};
}

// ---- A plain C++ Loop subdivision with sharp edges ----

struct tri_mesh {
  std::vector<point> pts;
  std::vector<std::array<index_t, 3>> tris;
  std::set<edge_key> sharp;  // creases; boundary edges are found from the triangles
};

//! One step of Loop subdivision: sharp and boundary edges take midpoints; a
//! vertex with two of them the curve rule 3/4, 1/8, 1/8, with three or more
//! stays, else Loop's weights (or Warren's: 3/(8n), 3/16 for n = 3).
tri_mesh loop_step(const tri_mesh& in, bool warren) {
  std::map<edge_key, std::vector<index_t>> opposite;
  for (const auto& t : in.tris)
    for (int i = 0; i < 3; ++i) opposite[key(t[i], t[(i + 1) % 3])].push_back(t[(i + 2) % 3]);
  auto is_sharp = [&](const edge_key& e) { return in.sharp.count(e) || opposite.at(e).size() == 1; };
  std::size_t n = in.pts.size();
  std::vector<std::vector<index_t>> nbrs(n), sharp_nbrs(n);
  for (const auto& [e, opp] : opposite) {
    nbrs[e.first].push_back(e.second), nbrs[e.second].push_back(e.first);
    if (is_sharp(e)) sharp_nbrs[e.first].push_back(e.second), sharp_nbrs[e.second].push_back(e.first);
  }
  tri_mesh out;
  for (std::size_t v = 0; v < n; ++v) {
    const point& p = in.pts[v];
    if (sharp_nbrs[v].size() == 2) {
      out.pts.push_back(0.75 * p + 0.125 * (in.pts[sharp_nbrs[v][0]] + in.pts[sharp_nbrs[v][1]]));
    } else if (sharp_nbrs[v].size() > 2) {
      out.pts.push_back(p);
    } else {
      double k = static_cast<double>(nbrs[v].size());
      double beta;  // the weight of each neighbour
      if (warren) {
        beta = nbrs[v].size() == 3 ? 3.0 / 16 : 3.0 / (8 * k);
      } else {
        double a = 3.0 / 8 + std::cos(2 * util::pi / k) / 4;
        beta = (5.0 / 8 - a * a) / k;
      }
      point q = (1 - k * beta) * p;
      for (index_t u : nbrs[v]) q = q + beta * in.pts[u];
      out.pts.push_back(q);
    }
  }
  std::map<edge_key, index_t> mid;
  for (const auto& [e, opp] : opposite) {
    mid[e] = static_cast<index_t>(out.pts.size());
    point a = in.pts[e.first], b = in.pts[e.second];
    if (is_sharp(e)) {
      out.pts.push_back(0.5 * (a + b));
      if (in.sharp.count(e)) out.sharp.insert(key(e.first, mid[e])), out.sharp.insert(key(mid[e], e.second));
    } else {
      out.pts.push_back(0.375 * (a + b) + 0.125 * (in.pts[opp[0]] + in.pts[opp[1]]));
    }
  }
  for (const auto& t : in.tris) {
    index_t a = mid[key(t[0], t[1])], b = mid[key(t[1], t[2])], c = mid[key(t[2], t[0])];
    out.tris.push_back({t[0], a, c});
    out.tris.push_back({a, t[1], b});
    out.tris.push_back({c, b, t[2]});
    out.tris.push_back({a, b, c});
  }
  return out;
}

tri_mesh loop_steps(tri_mesh m, unsigned steps, bool warren) {
  for (unsigned i = 0; i < steps; ++i) m = loop_step(m, warren);
  return m;
}

tri_mesh tri_mesh_of(const plain& p, bool with_creases) {
  tri_mesh m{p.pts, triangles_of(p), {}};
  if (with_creases) m.sharp = p.crease;
  return m;
}

// ---- OpenMesh and CGAL on triangle meshes (with boundary) ----

//! The triangles of an open mesh's export, without its boundary polygon.
oracle::polygons triangles_only(oracle::polygons p) {
  auto not_triangle = [](const auto& f) { return f.size() != 3; };
  p.faces.erase(std::remove_if(p.faces.begin(), p.faces.end(), not_triangle), p.faces.end());
  return p;
}

std::vector<point> openmesh_loop(const oracle::polygons& in, unsigned steps) {
  return peers::openmesh_loop(triangles_only(in), steps).points;
}

std::vector<point> cgal_loop(const oracle::polygons& in, unsigned steps) {
  return peers::cgal_loop(triangles_only(in), steps).points;
}

// ---- Helpers ----

using oracle::model;

//! Runs an example and reads its export with all fields.
plain run_plain(const std::string& example, const std::string& input, unsigned steps) {
  oracle::run_example(example, input, steps);
  return read_plain(oracle::export_of(example, steps));
}

//! Every point of `some` is (within tol) one of `all`.
void expect_among(const std::vector<point>& some, std::vector<point> all, double tol, const std::string& what) {
  std::sort(all.begin(), all.end());
  std::size_t missing = 0;
  for (const point& p : some) {
    auto it = std::lower_bound(all.begin(), all.end(), point{p[0] - tol, -1e300, -1e300});
    bool found = false;
    for (; it != all.end() && (*it)[0] <= p[0] + tol && !found; ++it) found = distance(*it, p) <= 2 * tol;
    if (!found && ++missing <= 5) ADD_FAILURE() << what << ": no match for (" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  }
  EXPECT_EQ(missing, 0u) << what << ": of " << some.size() << " points";
}

//! The boundary polygon of an open mesh: its one face orbit longer than 3.
std::vector<point> boundary_polygon(const oracle::polygons& m) {
  std::vector<point> loop;
  for (const auto& f : m.faces)
    if (f.size() > 3) {
      EXPECT_TRUE(loop.empty()) << "more than one boundary orbit";
      for (index_t i : f) loop.push_back(m.points[i]);
    }
  return loop;
}

//! One step of cubic B-spline subdivision of a closed polygon.
std::vector<point> bspline_step(const std::vector<point>& poly) {
  std::vector<point> out;
  std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const point &prev = poly[(i + n - 1) % n], &p = poly[i], &next = poly[(i + 1) % n];
    out.push_back(0.75 * p + 0.125 * (prev + next));
    out.push_back(0.5 * (p + next));
  }
  return out;
}

//! The same cyclic sequence of points, up to rotation and direction.
void expect_same_cycle(const std::vector<point>& a, const std::vector<point>& b, double tol) {
  ASSERT_EQ(a.size(), b.size());
  std::size_t n = a.size();
  for (int dir : {1, -1})
    for (std::size_t s = 0; s < n; ++s) {
      bool same = true;
      for (std::size_t i = 0; i < n && same; ++i)
        same = distance(a[i], b[dir == 1 ? (s + i) % n : (s + n - i) % n]) <= tol;
      if (same) return;
    }
  ADD_FAILURE() << "the cycles differ";
}

}  // namespace

// ---------------------------------------------------------------- loop_boundary

TEST(LoopBoundaryOracle, ClosedMeshesAsLoop) {
  std::string pyramid = model("pyramid.vvm");
  oracle::polygons ours = oracle::run_example("examples/loop_boundary.vvp", pyramid, 3);
  oracle::polygons loop = oracle::run_example("examples/loop.vvp", "", 3);
  ASSERT_EQ(ours.points.size(), 258u);
  oracle::expect_same_points(ours.points, loop.points, 1e-9);
  oracle::expect_same_faces(ours, loop, 1e-9);

  std::string cow = oracle::input_vvm("cow", oracle::cgal_mesh_file("cow.off"));
  oracle::polygons ours_cow = oracle::run_example("examples/loop_boundary.vvp", cow, 1);
  oracle::polygons loop_cow = oracle::run_example("examples/loop.vvp", cow, 1);
  double tol = 1e-9 * oracle::size_of(loop_cow.points);
  oracle::expect_same_points(ours_cow.points, loop_cow.points, tol);
  oracle::expect_same_faces(ours_cow, loop_cow, tol);
}

TEST(LoopBoundaryOracle, PatchAsOpenMeshCgalAndPlainLoop) {
  oracle::polygons base = oracle::read_polygons(model("patch.vvm"));
  plain input = read_plain(model("patch.vvm"));
  double tol = 1e-9 * oracle::size_of(base.points);
  for (unsigned steps : {1u, 3u}) {
    oracle::polygons ours = oracle::run_example("examples/loop_boundary.vvp", "", steps);
    ASSERT_EQ(ours.points.size(), steps == 1 ? 169u : 2401u);
    oracle::expect_same_points(ours.points, openmesh_loop(base, steps), tol);
    oracle::expect_same_points(ours.points, cgal_loop(base, steps), tol);
    oracle::expect_same_points(ours.points, loop_steps(tri_mesh_of(input, false), steps, false).pts, tol);
  }
}

TEST(LoopBoundaryOracle, BoundaryIsTheCubicBSplineOfTheBoundaryPolygon) {
  oracle::polygons base = oracle::read_polygons(model("patch.vvm"));
  std::vector<point> curve = boundary_polygon(base);
  ASSERT_EQ(curve.size(), 24u);
  double tol = 1e-9 * oracle::size_of(base.points);
  for (unsigned steps = 1; steps <= 3; ++steps) {
    curve = bspline_step(curve);
    oracle::polygons ours = oracle::run_example("examples/loop_boundary.vvp", "", steps);
    expect_same_cycle(boundary_polygon(ours), curve, tol);
  }
}

// ---------------------------------------------------------------- loop_creases

TEST(LoopCreasesOracle, UnmarkedClosedMeshesAsLoop) {
  oracle::polygons ours = oracle::run_example("examples/loop_creases.vvp", model("pyramid.vvm"), 3);
  oracle::polygons loop = oracle::run_example("examples/loop.vvp", "", 3);
  oracle::expect_same_points(ours.points, loop.points, 1e-9);
  oracle::expect_same_faces(ours, loop, 1e-9);

  std::string cow = oracle::input_vvm("cow", oracle::cgal_mesh_file("cow.off"));
  oracle::polygons ours_cow = oracle::run_example("examples/loop_creases.vvp", cow, 1);
  oracle::polygons loop_cow = oracle::run_example("examples/loop.vvp", cow, 1);
  double tol = 1e-9 * oracle::size_of(loop_cow.points);
  oracle::expect_same_points(ours_cow.points, loop_cow.points, tol);
  oracle::expect_same_faces(ours_cow, loop_cow, tol);
}

TEST(LoopCreasesOracle, PatchAsPlainLoopWithCreases) {
  plain input = read_plain(model("patch.vvm"));
  ASSERT_EQ(input.boundary_half.size(), 24u);
  ASSERT_EQ(input.crease.size(), 4u);
  double tol = 1e-9 * oracle::size_of(input.pts);
  for (unsigned steps = 1; steps <= 3; ++steps) {
    plain ours = run_plain("examples/loop_creases.vvp", "", steps);
    tri_mesh theirs = loop_steps(tri_mesh_of(input, true), steps, false);
    oracle::expect_same_points(ours.pts, theirs.pts, tol);
    // The marks went to both halves of each marked edge.
    EXPECT_EQ(ours.boundary_half.size(), 24u << steps);
    EXPECT_EQ(ours.crease.size(), 4u << steps);
    std::vector<point> ends;
    for (const auto& e : ours.crease) ends.push_back(0.5 * (ours.pts[e.first] + ours.pts[e.second]));
    std::vector<point> their_ends;
    for (const auto& e : theirs.sharp) their_ends.push_back(0.5 * (theirs.pts[e.first] + theirs.pts[e.second]));
    oracle::expect_same_points(ends, their_ends, tol);
    // Each marked boundary half lies on the boundary's face orbit, not on a
    // triangle: (a, b) -> (b, prevto a in b) comes back after more than 3 steps.
    for (const auto& [a, b] : ours.boundary_half) {
      index_t x = a, y = b;
      std::size_t length = 0;
      do {
        const auto& nb = ours.nb[y];
        index_t z = nb[(std::find(nb.begin(), nb.end(), x) - nb.begin() + nb.size() - 1) % nb.size()];
        x = y, y = z, ++length;
      } while (!(x == a && y == b) && length <= ours.pts.size());
      EXPECT_EQ(length, 24u << steps) << a << "-" << b << " is not on the boundary orbit";
    }
  }
}

TEST(LoopCreasesOracle, CreaseVerticesFollowTheCurveRule) {
  plain in = read_plain(model("patch.vvm"));
  plain out = run_plain("examples/loop_creases.vvp", "", 1);
  double tol = 1e-9 * oracle::size_of(in.pts);
  std::map<index_t, std::vector<index_t>> along;  // crease neighbours
  for (const auto& e : in.crease) along[e.first].push_back(e.second), along[e.second].push_back(e.first);
  unsigned crease_vertices = 0, darts = 0;
  for (const auto& [v, ends] : along) {
    // The old vertices come first in the export, in file order.
    if (ends.size() == 2) {
      ++crease_vertices;
      point want = 0.75 * in.pts[v] + 0.125 * (in.pts[ends[0]] + in.pts[ends[1]]);
      EXPECT_LE(distance(out.pts[v], want), tol) << "crease vertex " << v;
    } else {
      ++darts;  // a dart is smooth: Loop's mask over all its neighbours
      double k = static_cast<double>(in.nb[v].size()), a = 3.0 / 8 + std::cos(2 * util::pi / k) / 4;
      double beta = (5.0 / 8 - a * a) / k;
      point want = (1 - k * beta) * in.pts[v];
      for (index_t u : in.nb[v]) want = want + beta * in.pts[u];
      EXPECT_LE(distance(out.pts[v], want), tol) << "dart " << v;
    }
  }
  EXPECT_EQ(crease_vertices, 3u);
  EXPECT_EQ(darts, 2u);
  std::vector<point> midpoints;  // on the crease edges: the new vertices are midpoints
  for (const auto& e : in.crease) midpoints.push_back(0.5 * (in.pts[e.first] + in.pts[e.second]));
  expect_among(midpoints, out.pts, tol, "crease midpoints");
}

// ---------------------------------------------------------------- loop_mobius

namespace {

//! Whether the triangles can be given orientations that agree across every
//! edge (each shared edge run in opposite directions by its two triangles).
bool orientable(const std::vector<std::array<index_t, 3>>& tris) {
  std::map<edge_key, std::vector<std::size_t>> at;
  for (std::size_t t = 0; t < tris.size(); ++t)
    for (int i = 0; i < 3; ++i) at[key(tris[t][i], tris[t][(i + 1) % 3])].push_back(t);
  std::vector<int> flip(tris.size(), 0);  // 0: unvisited, 1: as listed, -1: reversed
  auto runs = [&](std::size_t t, index_t a, index_t b) {  // does t, as oriented, run a -> b?
    for (int i = 0; i < 3; ++i)
      if (tris[t][i] == a && tris[t][(i + 1) % 3] == b) return flip[t] == 1;
    return flip[t] == -1;
  };
  for (std::size_t s = 0; s < tris.size(); ++s) {
    if (flip[s]) continue;
    flip[s] = 1;
    std::vector<std::size_t> todo = {s};
    while (!todo.empty()) {
      std::size_t t = todo.back();
      todo.pop_back();
      for (int i = 0; i < 3; ++i) {
        index_t a = tris[t][i], b = tris[t][(i + 1) % 3];
        for (std::size_t u : at[key(a, b)]) {
          if (u == t) continue;
          if (!flip[u]) {
            flip[u] = 1;
            if (runs(u, a, b) == runs(t, a, b)) flip[u] = -1;
            todo.push_back(u);
          } else if (runs(u, a, b) == runs(t, a, b)) {
            return false;
          }
        }
      }
    }
  }
  return true;
}

}  // namespace

TEST(LoopMobiusOracle, AsPlainLoopWithWarrensWeights) {
  plain input = read_plain(model("mobius.vvm"));
  tri_mesh base = tri_mesh_of(input, false);
  ASSERT_EQ(base.tris.size(), 48u);
  double tol = 1e-9 * oracle::size_of(input.pts);
  for (unsigned steps = 1; steps <= 3; ++steps) {
    plain ours = run_plain("examples/loop_mobius.vvp", "", steps);
    oracle::expect_same_points(ours.pts, loop_steps(base, steps, true).pts, tol);
  }
}

TEST(LoopMobiusOracle, StaysAMobiusStrip) {
  for (unsigned steps = 0; steps <= 2; ++steps) {
    plain m = run_plain("examples/loop_mobius.vvp", "", steps);
    auto tris = triangles_of(m);
    std::map<edge_key, int> faces_at;
    for (const auto& t : tris)
      for (int i = 0; i < 3; ++i) ++faces_at[key(t[i], t[(i + 1) % 3])];
    std::size_t edges = 0;
    for (index_t v = 0; v < m.nb.size(); ++v) edges += m.nb[v].size();
    edges /= 2;
    EXPECT_EQ(tris.size(), 48u << (2 * steps));
    EXPECT_EQ(faces_at.size(), edges) << "every edge is on a triangle";
    // Euler characteristic 0, one boundary curve, and no orientation.
    EXPECT_EQ(static_cast<long>(m.pts.size()) - static_cast<long>(edges) + static_cast<long>(tris.size()), 0);
    std::map<index_t, std::vector<index_t>> along;
    for (const auto& [e, k] : faces_at) {
      EXPECT_LE(k, 2);
      if (k == 1) along[e.first].push_back(e.second), along[e.second].push_back(e.first);
    }
    std::size_t length = 0;
    index_t prev = along.begin()->first, at = along.begin()->second[0];
    for (; at != along.begin()->first && length <= along.size(); ++length) {
      ASSERT_EQ(along[at].size(), 2u);
      index_t next = along[at][0] == prev ? along[at][1] : along[at][0];
      prev = at, at = next;
    }
    EXPECT_EQ(length + 1, along.size()) << "the boundary is one closed curve";
    EXPECT_EQ(along.size(), 24u << steps);
    EXPECT_FALSE(orientable(tris));
  }
}

// ---------------------------------------------------------------- loop_adaptive

namespace {

void check_adaptive(const std::string& input, unsigned max_steps) {
  std::string example = "examples/loop_adaptive.vvp";
  plain before = input.empty() ? read_plain(model("pyramid.vvm")) : read_plain(input);
  long euler = static_cast<long>(before.pts.size()) - static_cast<long>(triangles_of(before).size()) / 2;
  double tol = 1e-9 * oracle::size_of(before.pts);
  // The selection made in start: as after 0 steps.
  before = run_plain(example, input, 0);
  for (unsigned steps = 1; steps <= max_steps; ++steps) {
    SCOPED_TRACE("after " + std::to_string(steps) + " steps");
    plain after = run_plain(example, input, steps);
    // A closed manifold triangle mesh: symmetric neighbourhoods, every face
    // orbit a triangle visiting each corner once, no broken orbit.
    {
      graph::context ctx;
      graph::mesh m(ctx);
      std::string out = oracle::export_of(example, steps);
      vv::read_vvm(m, out);
      EXPECT_NO_THROW(vv::check_invariants(m, {true, true}));
      vv::orbit_set orbits = vv::orbits(m);
      EXPECT_EQ(orbits.broken_edges, 0u);
      for (const auto& f : orbits.faces) EXPECT_EQ(f.size(), 3u);
      long v = static_cast<long>(m.size()), e = static_cast<long>(vv::edge_count(m));
      long f = static_cast<long>(orbits.faces.size());
      EXPECT_EQ(2 * e, 3 * f);
      EXPECT_EQ(v - e + f, euler) << "the same surface";
    }
    // The vertices there were keep their places in the export; unselected
    // ones never move, selected ones do.
    ASSERT_GT(after.pts.size(), before.pts.size());
    std::size_t moved = 0, selected = 0;
    for (std::size_t i = 0; i < before.pts.size(); ++i) {
      EXPECT_EQ(after.selected[i], before.selected[i]);
      if (!before.selected[i]) EXPECT_EQ(after.pts[i], before.pts[i]) << "vertex " << i << " moved";
      else ++selected, moved += after.pts[i] != before.pts[i];
    }
    EXPECT_GT(selected, 0u);
    EXPECT_EQ(moved, selected);
    // The selected vertices and their neighbours are uniform Loop's points.
    std::vector<point> region;
    for (index_t i = 0; i < after.pts.size(); ++i) {
      bool near = after.selected[i];
      for (index_t j : after.nb[i]) near = near || after.selected[j];
      if (near) region.push_back(after.pts[i]);
    }
    ASSERT_GT(region.size(), 0u);
    std::vector<point> uniform = input.empty() ? oracle::run_example("examples/loop.vvp", "", steps).points
                                               : oracle::run_example("examples/loop.vvp", input, steps).points;
    expect_among(region, uniform, tol, "region");
    before = after;
  }
}

}  // namespace

TEST(LoopAdaptiveOracle, PyramidRegionAsUniformLoop) { check_adaptive("", 4); }

TEST(LoopAdaptiveOracle, CowRegionAsUniformLoop) {
  check_adaptive(oracle::input_vvm("cow", oracle::cgal_mesh_file("cow.off")), 2);
}
