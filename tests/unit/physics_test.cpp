// The physics and cell geometry helpers (algorithms/physics.hpp,
// algorithms/cell_geometry.hpp) against values worked out by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <algorithms/cell_geometry.hpp>
#include <algorithms/physics.hpp>
#include <util/point.hpp>
#include <vv/vv.hpp>

namespace {

using Pt = util::Point<double>;

struct vertex_props {
  Pt pos, vel;
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos);
    f("vel", vel);
  }
};
struct edge_props {
  double rest;
  template <class F>
  void vv_fields(F&& f) {
    f("rest", rest);
  }
};
using graph = vv::graph<vertex_props, edge_props>;
using vertex = graph::vertex;

void expect_point(const Pt& p, double x, double y, double z) {
  EXPECT_NEAR(p.x(), x, 1e-12);
  EXPECT_NEAR(p.y(), y, 1e-12);
  EXPECT_NEAR(p.z(), z, 1e-12);
}

struct two_masses : ::testing::Test {
  graph::context ctx;
  graph::mesh S{ctx};
  vertex a = ctx.new_vertex(), b = ctx.new_vertex();
  algorithms::MassSpring<vertex> springs;

  // a at the origin, b at (2, 0, 0), a spring of rest length 1 between them.
  void SetUp() override {
    a->pos = Pt(0, 0, 0);
    b->pos = Pt(2, 0, 0);
    vv::make_nb(a, {b});
    vv::make_nb(b, {a});
    vv::edge(a, b).rest = 1;
    vv::edge(b, a).rest = 1;
    S.add(a);
    S.add(b);
  }
};

TEST_F(two_masses, OneSpringPullsBothEndsTogether) {
  vv::synchronise(S);
  // k (|d| - rest) d/|d| = 1 * (2 - 1) * (1, 0, 0).
  expect_point(springs.acceleration(a, algorithms::RestFromRecords()), 1, 0, 0);
  expect_point(springs.acceleration(b, algorithms::RestFromRecords()), -1, 0, 0);
  springs.stiffness = 3;
  springs.mass = 2;
  expect_point(springs.acceleration(a, algorithms::UniformRest{0.5}), 2.25, 0, 0);  // 3 * 1.5 / 2
}

TEST_F(two_masses, RestLengthsFromAnyCallable) {
  vv::synchronise(S);
  // Given both ends, without the record: rest 0.25 from a, 1.5 from b.
  auto rest = [&](const vertex& v, const vertex&) { return v == a ? 0.25 : 1.5; };
  expect_point(springs.acceleration(a, rest), 1.75, 0, 0);
  expect_point(springs.acceleration(b, rest), -0.5, 0, 0);
  // RestFromRecords also answers for two vertices.
  EXPECT_EQ(algorithms::RestFromRecords()(a, b), 1);
}

TEST_F(two_masses, DragOpposesTheOldVelocity) {
  a->vel = Pt(0.5, 0, 0);
  springs.drag = 0.2;
  vv::synchronise(S);
  // 1 - 0.2 * 0.5 = 0.9.
  expect_point(springs.acceleration(a, algorithms::RestFromRecords()), 0.9, 0, 0);
}

TEST_F(two_masses, OneEulerStepUsesTheOldPositionAndVelocity) {
  a->vel = Pt(0.5, 0, 0);
  springs.drag = 0.2;
  springs.dt = 0.1;
  const double fastest = springs.step(S, algorithms::RestFromRecords());
  // a: pos 0 + 0.1 * 0.5, vel 0.5 + 0.1 * 0.9; b: pos 2, vel 0 + 0.1 * -1.
  expect_point(a->pos, 0.05, 0, 0);
  expect_point(a->vel, 0.59, 0, 0);
  expect_point(b->pos, 2, 0, 0);
  expect_point(b->vel, -0.1, 0, 0);
  EXPECT_NEAR(fastest, 0.59, 1e-12);
  EXPECT_FALSE(algorithms::settled(S, 0.5));
  EXPECT_TRUE(algorithms::settled(S, 0.6));
}

TEST_F(two_masses, SettleAtTheRestLength) {
  springs.drag = 1;
  springs.dt = 0.05;
  const unsigned steps = springs.relax(S, algorithms::RestFromRecords(), 1e-9, 100000);
  EXPECT_LT(steps, 100000u);
  EXPECT_TRUE(algorithms::settled(S, 1e-9));
  // Speeds below 1e-9 leave the overdamped spring within 1e-7 of its rest.
  EXPECT_NEAR((b->pos - a->pos).length(), 1, 1e-7);
  // The springs' forces are equal and opposite: the middle stays at x = 1.
  EXPECT_NEAR((a->pos.x() + b->pos.x()) / 2, 1, 1e-12);
}

TEST_F(two_masses, ExtraForceIsAdded) {
  vv::synchronise(S);
  auto gravity = [](const vertex&) { return Pt(0, -9.8, 0); };
  expect_point(springs.acceleration(a, algorithms::RestFromRecords(), gravity), 1, -9.8, 0);
}

// A square pyramid: apex (0, 0, 1) over (±1, 0, 0), (0, ±1, 0), its
// neighbours counter-clockwise seen from above.
struct pyramid : ::testing::Test {
  graph::context ctx;
  vertex apex = ctx.new_vertex();
  std::vector<vertex> base;
  void SetUp() override {
    apex->pos = Pt(0, 0, 1);
    const Pt corners[] = {Pt(1, 0, 0), Pt(0, 1, 0), Pt(-1, 0, 0), Pt(0, -1, 0)};
    for (const Pt& c : corners) {
      vertex v = ctx.new_vertex();
      v->pos = c;
      base.push_back(v);
    }
    vv::make_nb_from(apex, base);
  }
};

TEST_F(pyramid, ApexNormalPointsUp) {
  // Each arm pair, e.g. (1, 0, -1) x (0, 1, -1) = (1, 1, 1): the sum is (0, 0, 4).
  expect_point(algorithms::fan_cross_sum(apex), 0, 0, 4);
  expect_point(algorithms::vertex_normal(apex), 0, 0, 1);
}

TEST_F(pyramid, SurfacePressureIsTheVolumeGradient) {
  // Volume = base 2 * height / 3: d/dheight = 2/3, times pressure 3.
  expect_point(algorithms::surface_pressure(apex, 3.0), 0, 0, 2);
}

TEST_F(pyramid, NormalOfTheOldState) {
  graph::mesh S(ctx);
  S.add(apex);
  for (const vertex& v : base) S.add(v);
  vv::synchronise(S);
  base[0]->pos = Pt(1, 0, 1);  // tilts the current fan; the old stays
  expect_point(algorithms::fan_cross_sum(vv::old(apex)), 0, 0, 4);
  // Arms (1,0,0) (0,1,-1) (-1,0,-1) (0,-1,-1): crosses (0,1,1) (-1,1,1)
  // (-1,-1,1) (0,-1,1).
  expect_point(algorithms::fan_cross_sum(apex), -2, 0, 4);
  expect_point(algorithms::vertex_normal(vv::old(apex)), 0, 0, 1);
}

TEST(wall_pressure, PushesAlongTheOutwardNormalsOfBoundaryWalls) {
  graph::context ctx;
  graph::mesh S(ctx);
  // A unit square cell, counter-clockwise: corners 0 (0,0), 1 (1,0), 2 (1,1), 3 (0,1).
  std::vector<vertex> c;
  const Pt corners[] = {Pt(0, 0), Pt(1, 0), Pt(1, 1), Pt(0, 1)};
  for (const Pt& p : corners) {
    vertex v = ctx.new_vertex();
    v->pos = p;
    c.push_back(v);
    S.add(v);
  }
  // Around each corner: the next corner, then the previous one (the cell
  // is on the left of corner -> next).
  for (int i = 0; i < 4; ++i) vv::make_nb(c[i], {c[(i + 1) % 4], c[(i + 3) % 4]});
  vv::synchronise(S);
  // The cell is on the left of i -> i+1; the outside on the left of i -> i-1.
  auto pressure = [&](const vertex& v, const vertex& n) {
    for (int i = 0; i < 4; ++i)
      if (v == c[i] && n == c[(i + 1) % 4]) return 2.0;
    return 0.0;
  };
  // p/2 times the outward normals of the two unit walls: (-1, 0) and (0, -1).
  expect_point(algorithms::wall_pressure(c[0], pressure), -1, -1, 0);
  expect_point(algorithms::wall_pressure(c[2], pressure), 1, 1, 0);
  // Equal pressure inside and out: no net force.
  expect_point(algorithms::wall_pressure(c[1], [](const vertex&, const vertex&) { return 1.0; }), 0, 0, 0);
  // The cell's walls by orbit, and its geometry.
  std::vector<vertex> walls = algorithms::cell_corners(c[0], c[1]);
  ASSERT_EQ(walls.size(), 4u);
  EXPECT_EQ(walls[2], c[2]);
  EXPECT_DOUBLE_EQ(algorithms::cell_area(walls), 1);
  expect_point(algorithms::cell_centroid(walls), 0.5, 0.5, 0);
  // The outside orbit runs clockwise.
  EXPECT_DOUBLE_EQ(algorithms::cell_area(algorithms::cell_corners(c[1], c[0])), -1);
}

TEST(polygon, AreaAndCentroidOfAUnitSquare) {
  const std::vector<Pt> square = {Pt(0, 0), Pt(1, 0), Pt(1, 1), Pt(0, 1)};
  EXPECT_DOUBLE_EQ(algorithms::polygon_area(square), 1);
  expect_point(algorithms::polygon_centroid(square), 0.5, 0.5, 0);
  EXPECT_TRUE(algorithms::polygon_is_convex(square));
}

TEST(polygon, AreaAndCentroidOfATriangle) {
  // Legs 3 and 6: area 9; centroid the corners' mean (1, 2).
  const std::vector<Pt> triangle = {Pt(0, 0), Pt(3, 0), Pt(0, 6)};
  EXPECT_DOUBLE_EQ(algorithms::polygon_area(triangle), 9);
  expect_point(algorithms::polygon_centroid(triangle), 1, 2, 0);
  const std::vector<Pt> clockwise = {Pt(0, 0), Pt(0, 6), Pt(3, 0)};
  EXPECT_DOUBLE_EQ(algorithms::polygon_area(clockwise), -9);
  expect_point(algorithms::polygon_centroid(clockwise), 1, 2, 0);
  EXPECT_FALSE(algorithms::polygon_is_convex(clockwise));
}

TEST(polygon, AnArrowIsNotConvexAndAFlatPolygonCentresOnItsCorners) {
  const std::vector<Pt> arrow = {Pt(0, 0), Pt(2, 1), Pt(0, 2), Pt(1, 1)};
  EXPECT_DOUBLE_EQ(algorithms::polygon_area(arrow), 1);
  EXPECT_FALSE(algorithms::polygon_is_convex(arrow));
  const std::vector<Pt> flat = {Pt(0, 0), Pt(1, 0), Pt(2, 0)};
  EXPECT_DOUBLE_EQ(algorithms::polygon_area(flat), 0);
  expect_point(algorithms::polygon_centroid(flat), 1, 0, 0);
}

}  // namespace
