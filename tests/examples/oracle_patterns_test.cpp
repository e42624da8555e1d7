// examples/penrose.vvp and examples/terrain.vvp.
//
// Penrose: the tiles counted by their angles follow the deflation rule
// (thick' = 2 thick + thin, thin' = thick + thin, in half rhombs), the
// edge labels obey the matching rules on every tile, and the tiling equals
// the one given by an independent implementation: Robinson triangles
// subdivided as a soup of triangles, then paired into rhombs.
//
// Terrain: the same seed gives the same file, different seeds different
// terrains; the river is a simple path of edges across the square at
// height 0, and the land never dips below it.
#include <cmath>
#include <complex>
#include <map>
#include <set>

#include "oracle.hpp"

namespace {

// ---------------------------------------------------------------- Penrose

struct penrose_edge {
  int kind = 0;
  bool forward = false;
  bool operator==(const penrose_edge& o) const { return kind == o.kind && forward == o.forward; }
  bool operator!=(const penrose_edge& o) const { return !(*this == o); }
  template <class F>
  void vv_fields(F&& f) {
    f("kind", kind);
    f("forward", forward);
  }
};
using penrose_graph = vv::graph<positions_graph::props, penrose_edge>;

const double phi = (1 + std::sqrt(5.0)) / 2;
const double pi = std::acos(-1.0);

// Runs the example for `steps` steps and gives the path of its export.
std::string run_penrose(unsigned steps, const std::string& extra_name = "") {
  std::string out = test_files::scratch_dir() + "penrose" + extra_name + "_" + std::to_string(steps) + ".vvm";
  test_run::result r = test_run::run(
      test_run::interpreter({"--batch", "--quiet", "--steps", std::to_string(steps), "--export", out,
                             std::string(VV_SOURCE_DIR) + "/examples/penrose.vvp"}),
      600);
  EXPECT_EQ(r.status, 0) << r.err;
  return out;
}

struct tile_counts {
  long thick = 0, thin = 0;          // whole rhombs
  long thick_half = 0, thin_half = 0;  // half rhombs (Robinson triangles) on the outline
  long thick_halves() const { return 2 * thick + thick_half; }
  long thin_halves() const { return 2 * thin + thin_half; }
};

double angle_at(const util::Point<double>& c, const util::Point<double>& a, const util::Point<double>& b) {
  util::Point<double> u = a - c, w = b - c;
  return std::acos(std::max(-1.0, std::min(1.0, u * w / (u.length() * w.length())))) * 180 / pi;
}

bool near(double a, double b) { return std::fabs(a - b) < 1e-6; }

// Classifies every face of at most four corners by its angles and checks
// its shape and its edge labels.
tile_counts classify(const std::string& vvm, unsigned steps) {
  penrose_graph::context ctx;
  penrose_graph::mesh m(ctx);
  vv::read_vvm(m, vvm);
  EXPECT_EQ(vv::invariant_violations(m, {true, true}), std::vector<std::string>{});
  std::vector<penrose_graph::vertex> vs;
  for (penrose_graph::vertex v : vv::each(m)) vs.push_back(v);
  double side = std::pow(phi, -double(steps));  // the seed's rhombs have sides 1
  tile_counts c;
  for (const auto& f : vv::face_orbits(m, 4)) {
    std::size_t k = f.size();
    std::vector<double> angles;
    for (std::size_t i = 0; i < k; ++i)
      angles.push_back(angle_at(vs[f[i]]->pos, vs[f[(i + 1) % k]]->pos, vs[f[(i + k - 1) % k]]->pos));
    auto label = [&](std::size_t i, std::size_t j) { return vv::edge(vs[f[i]], vs[f[j]]); };
    if (k == 4) {
      // A rhomb: equal sides; 72/108 (thick) or 36/144 (thin) degrees.
      for (std::size_t i = 0; i < 4; ++i)
        EXPECT_NEAR((vs[f[i]]->pos - vs[f[(i + 1) % 4]]->pos).length(), side, 1e-9);
      bool thick = near(angles[0], 72) || near(angles[0], 108);
      bool thin = near(angles[0], 36) || near(angles[0], 144);
      if (!thick && !thin) {
        ADD_FAILURE() << "a quad with an angle of " << angles[0] << " degrees";
        continue;
      }
      for (std::size_t i = 0; i < 4; ++i)
        EXPECT_TRUE(near(angles[i] + angles[(i + 1) % 4], 180) && near(angles[i], angles[(i + 2) % 4]));
      (thick ? c.thick : c.thin)++;
      // Matching rules: the corner B between two single arrows, with C
      // (two double arrows) opposite; double arrows point into C; single
      // arrows point into B on a thin rhomb, out of it on a thick one. B
      // and C are the acute corners of a thick rhomb, the obtuse of a thin.
      int found = 0;
      for (std::size_t b = 0; b < 4; ++b) {
        std::size_t nb = (b + 1) % 4, pb = (b + 3) % 4, cc = (b + 2) % 4;
        if (label(b, nb).kind != 1 || label(b, pb).kind != 1) continue;
        ++found;
        EXPECT_EQ(label(cc, nb).kind, 2);
        EXPECT_EQ(label(cc, pb).kind, 2);
        EXPECT_TRUE(label(nb, cc).forward && label(pb, cc).forward) << "double arrows must point into C";
        EXPECT_EQ(label(b, nb).forward, thick) << "single arrows leave B on thick rhombs only";
        EXPECT_EQ(label(b, pb).forward, thick);
        EXPECT_TRUE(near(angles[b], thick ? 72 : 144));
      }
      EXPECT_EQ(found, 1) << "a rhomb needs exactly one corner between two single arrows";
    } else if (k == 3) {
      // A half rhomb on the outline: legs of the tile side, the diagonal
      // (kind 0) on the outline; 108/36/36 (thick) or 36/72/72 (thin).
      double largest = *std::max_element(angles.begin(), angles.end());
      bool thick = near(largest, 108);
      if (!thick && !near(largest, 72)) {
        ADD_FAILURE() << "a triangle with an angle of " << largest << " degrees";
        continue;
      }
      (thick ? c.thick_half : c.thin_half)++;
      int diagonals = 0;
      for (std::size_t i = 0; i < 3; ++i) diagonals += label(i, (i + 1) % 3).kind == 0;
      EXPECT_EQ(diagonals, 1);
    } else {
      ADD_FAILURE() << "a face of " << k << " corners";
    }
    for (std::size_t i = 0; i < k; ++i) {  // both half-edges carry the same kind, one arrow
      penrose_edge ab = label(i, (i + 1) % k), ba = vv::edge(vs[f[(i + 1) % k]], vs[f[i]]);
      EXPECT_EQ(ab.kind, ba.kind);
      if (ab.kind != 0) {
        EXPECT_NE(ab.forward, ba.forward);
      }
    }
  }
  return c;
}

TEST(PenroseOracle, TileCountsFollowTheDeflationRule) {
  // In half rhombs: T' = 2 T + t, t' = T + t, from the sun's 10 thick halves.
  // Outline edges (single, double arrow, thick and thin diagonal):
  // s' = D, d' = s + dt, D' = d + D, dt' = s, from 10 double arrows;
  // the half rhombs on the outline are those on its diagonals.
  long T = 10, t = 0, s = 0, d = 10, D = 0, dt = 0;
  for (unsigned k = 0; k <= 5; ++k) {
    tile_counts c = classify(run_penrose(k), k);
    SCOPED_TRACE("after " + std::to_string(k) + " steps");
    EXPECT_EQ(c.thick_halves(), T);
    EXPECT_EQ(c.thin_halves(), t);
    EXPECT_EQ(c.thick_half, D);
    EXPECT_EQ(c.thin_half, dt);
    long T2 = 2 * T + t, t2 = T + t, s2 = D, d2 = s + dt, D2 = d + D, dt2 = s;
    T = T2, t = t2, s = s2, d = d2, D = D2, dt = dt2;
  }
}

// The deflation without vv: a soup of Robinson triangles (apex, B, C),
// each split into two or three, then halves sharing a diagonal paired.
struct robinson {
  bool thick;
  std::complex<double> a, b, c;
};

oracle::polygons robinson_tiling(unsigned steps) {
  std::vector<robinson> ts;
  auto unit = [](double deg) { return std::polar(1.0, deg * pi / 180); };
  for (int k = 0; k < 5; ++k) {  // the sun: B at the centre, apexes at 72k degrees
    std::complex<double> p = unit(72 * k), q = unit(72 * (k + 1));
    ts.push_back({true, p, 0, p + q});
    ts.push_back({true, q, 0, p + q});
  }
  for (unsigned s = 0; s < steps; ++s) {
    std::vector<robinson> next;
    for (const robinson& r : ts) {
      if (r.thick) {
        std::complex<double> q = r.b + (r.a - r.b) / phi, x = r.b + (r.c - r.b) / phi;
        next.push_back({true, x, r.c, r.a});
        next.push_back({true, q, x, r.b});
        next.push_back({false, x, q, r.a});
      } else {
        std::complex<double> p = r.a + (r.b - r.a) / phi;
        next.push_back({false, r.c, p, r.b});
        next.push_back({true, p, r.c, r.a});
      }
    }
    ts = next;
  }
  oracle::polygons out;
  std::map<std::pair<long long, long long>, std::uint32_t> index;
  auto id = [&](std::complex<double> z) {
    std::pair<long long, long long> key(std::llround(z.real() * 1e7), std::llround(z.imag() * 1e7));
    auto it = index.find(key);
    if (it != index.end()) return it->second;
    out.points.push_back({z.real(), z.imag(), 0});
    return index[key] = std::uint32_t(out.points.size() - 1);
  };
  auto ccw = [&](std::vector<std::uint32_t> f) {
    double area = 0;
    for (std::size_t i = 0; i < f.size(); ++i) {
      const oracle::point &p = out.points[f[i]], &q = out.points[f[(i + 1) % f.size()]];
      area += p[0] * q[1] - p[1] * q[0];
    }
    if (area < 0) std::reverse(f.begin(), f.end());
    return f;
  };
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> by_diagonal;
  for (const robinson& r : ts) {
    std::uint32_t a = id(r.a), b = id(r.b), c = id(r.c);
    by_diagonal[{std::min(b, c), std::max(b, c)}].push_back(a);
  }
  for (const auto& [bc, apexes] : by_diagonal) {
    if (apexes.size() == 2) out.faces.push_back(ccw({apexes[0], bc.first, apexes[1], bc.second}));
    else out.faces.push_back(ccw({apexes[0], bc.first, bc.second}));
  }
  return out;
}

TEST(PenroseOracle, SameTilingAsRobinsonTriangles) {
  for (unsigned steps : {1u, 4u}) {
    SCOPED_TRACE("after " + std::to_string(steps) + " steps");
    oracle::polygons ours = oracle::read_polygons(run_penrose(steps, "_oracle"));
    std::vector<std::vector<std::uint32_t>> tiles;
    for (const auto& f : ours.faces)
      if (f.size() <= 4) tiles.push_back(f);
    ours.faces = tiles;
    oracle::polygons theirs = robinson_tiling(steps);
    oracle::expect_same_points(ours.points, theirs.points, 1e-9);
    oracle::expect_same_faces(ours, theirs, 1e-9);
  }
}

// ---------------------------------------------------------------- Terrain

struct terrain_vertex {
  util::Point<double> pos;
  bool river = false;
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos);
    f("river", river);
  }
};
struct terrain_edge {
  bool river = false;
  bool operator==(const terrain_edge& o) const { return river == o.river; }
  bool operator!=(const terrain_edge& o) const { return !(*this == o); }
  template <class F>
  void vv_fields(F&& f) {
    f("river", river);
  }
};
using terrain_graph = vv::graph<terrain_vertex, terrain_edge>;

std::string run_terrain(unsigned steps, const std::string& seed, const std::string& name) {
  std::string out = test_files::scratch_dir() + "terrain_" + name + ".vvm";
  std::vector<std::string> args = {"--batch", "--quiet", "--steps", std::to_string(steps), "--export", out};
  if (!seed.empty()) args.insert(args.end(), {"--seed", seed});
  args.push_back(std::string(VV_SOURCE_DIR) + "/examples/terrain.vvp");
  test_run::result r = test_run::run(test_run::interpreter(args), 600);
  EXPECT_EQ(r.status, 0) << r.err;
  return out;
}

TEST(TerrainOracle, SameSeedSameTerrainOtherSeedsDiffer) {
  std::string a = test_files::slurp(run_terrain(4, "", "default"));
  std::string b = test_files::slurp(run_terrain(4, "0", "zero"));
  std::string c = test_files::slurp(run_terrain(4, "12345", "a"));
  std::string d = test_files::slurp(run_terrain(4, "12345", "b"));
  std::string e = test_files::slurp(run_terrain(4, "12346", "c"));
  ASSERT_FALSE(a.empty());
  EXPECT_TRUE(a == b) << "the default seed is 0";
  EXPECT_TRUE(c == d) << "the same seed must give the same export";
  EXPECT_FALSE(a == c) << "different seeds must give different terrains";
  EXPECT_FALSE(c == e) << "different seeds must give different terrains";
}

TEST(TerrainOracle, RiverIsAPathAcrossTheSquareAtHeightZero) {
  for (const char* seed : {"0", "1", "2", "3"}) {
    SCOPED_TRACE(std::string("seed ") + seed);
    terrain_graph::context ctx;
    terrain_graph::mesh m(ctx);
    vv::read_vvm(m, run_terrain(4, seed, std::string("river") + seed));
    ASSERT_EQ(m.size(), 65u * 65u);
    EXPECT_EQ(vv::invariant_violations(m, {true, true}), std::vector<std::string>{});
    std::vector<terrain_graph::vertex> ends;
    std::size_t river_vertices = 0, river_edges = 0;
    double highest = 0;
    for (terrain_graph::vertex v : vv::each(m)) {
      highest = std::max(highest, v->pos.z());
      EXPECT_GE(v->pos.z(), 0) << "land below the river";
      std::size_t degree = 0;
      for (terrain_graph::vertex u : vv::each(v)) {
        bool r = vv::edge(v, u).river;
        EXPECT_EQ(r, vv::edge(u, v).river);
        if (r) {
          ++degree;
          EXPECT_TRUE(v->river && u->river) << "a river edge between vertices off the river";
        }
      }
      river_edges += degree;
      if (!v->river) {
        EXPECT_EQ(degree, 0u);
        continue;
      }
      ++river_vertices;
      EXPECT_EQ(v->pos.z(), 0) << "a river vertex off height 0";
      EXPECT_TRUE(degree == 1 || degree == 2) << "the river branches";
      if (degree == 1) ends.push_back(v);
    }
    EXPECT_GT(highest, 0.2);
    river_edges /= 2;
    // A simple path: one fewer edge than vertices, two ends, on the left
    // and right sides, and connected (walk from one end to the other).
    ASSERT_EQ(ends.size(), 2u);
    EXPECT_EQ(river_edges + 1, river_vertices);
    EXPECT_NEAR(std::fabs(ends[0]->pos.x()), 1, 1e-12);
    EXPECT_NEAR(std::fabs(ends[1]->pos.x()), 1, 1e-12);
    EXPECT_NE(ends[0]->pos.x(), ends[1]->pos.x());
    std::set<unsigned> seen;
    terrain_graph::vertex at = ends[0], from = at;
    std::size_t walked = 1;
    seen.insert(vv::label_of(at));
    while (at != ends[1]) {
      terrain_graph::vertex next = at;
      for (terrain_graph::vertex u : vv::each(at))
        if (vv::edge(at, u).river && u != from) next = u;
      ASSERT_NE(next, at) << "the river stops";
      ASSERT_TRUE(seen.insert(vv::label_of(next)).second) << "the river runs in a circle";
      from = at, at = next, ++walked;
    }
    EXPECT_EQ(walked, river_vertices);
    // At 4 steps the river has meandered: longer than the 4 x 16 edges
    // it would have with no detours.
    EXPECT_GT(river_edges, 4u * 16u);
  }
}

}  // namespace
