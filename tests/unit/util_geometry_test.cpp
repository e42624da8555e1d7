// util geometry helpers, checked against hand-computed values. geometry.hpp
// is included first on purpose: it must work without point.hpp before it.
#include <util/geometry.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>

namespace {

using Pt = util::Point<double>;
using Ptf = util::Point<float>;

static_assert(util::pi > 3.14159265 && util::pi < 3.14159266);
static_assert(util::two_pi == 2 * util::pi);
static_assert(util::clamp(5, 0, 10) == 5);
static_assert(util::range_closed(0, 1, 1));
static_assert(std::is_same_v<decltype(util::clamp(0.5, 0, 1)), double>);

constexpr double kEps = 1e-12;

void expect_point_near(const Pt& p, double x, double y, double z) {
  EXPECT_NEAR(p.x(), x, kEps);
  EXPECT_NEAR(p.y(), y, kEps);
  EXPECT_NEAR(p.z(), z, kEps);
}

TEST(UtilGeometry, Constants) {
  EXPECT_DOUBLE_EQ(util::pi, std::acos(-1.0));
  EXPECT_DOUBLE_EQ(util::two_pi, 2 * std::acos(-1.0));
}

TEST(UtilGeometry, Clamp) {
  EXPECT_EQ(util::clamp(5, 0, 10), 5);
  EXPECT_EQ(util::clamp(-1, 0, 10), 0);
  EXPECT_EQ(util::clamp(11, 0, 10), 10);
  EXPECT_EQ(util::clamp(0, 0, 10), 0);
  EXPECT_EQ(util::clamp(10, 0, 10), 10);
  EXPECT_DOUBLE_EQ(util::clamp(0.25, 0.0, 1.0), 0.25);
  // Mixed types are compared in the common type, not truncated.
  EXPECT_DOUBLE_EQ(util::clamp(0.5, 0, 1), 0.5);
  EXPECT_DOUBLE_EQ(util::clamp(2.5, 0, 1), 1.0);
  EXPECT_DOUBLE_EQ(util::clamp(-0.5f, 0, 1.0), 0.0);
}

TEST(UtilGeometry, RangeClosed) {
  EXPECT_TRUE(util::range_closed(0, 10, 5));
  EXPECT_TRUE(util::range_closed(0, 10, 0));   // lower bound included
  EXPECT_TRUE(util::range_closed(0, 10, 10));  // upper bound included
  EXPECT_FALSE(util::range_closed(0, 10, -1));
  EXPECT_FALSE(util::range_closed(0, 10, 11));
  EXPECT_TRUE(util::range_closed(0, 1, 0.5));
  EXPECT_FALSE(util::range_closed(0, 1, 1.0000001));
  EXPECT_FALSE(util::range_closed(5, 1, 3));  // empty range
}

TEST(UtilGeometry, AnglePerpendicular) {
  EXPECT_NEAR(util::angle(Pt(1, 0, 0), Pt(0, 3, 0)), util::pi / 2, kEps);
  EXPECT_NEAR(util::angle(Pt(0, 0, 2), Pt(5, 0, 0)), util::pi / 2, kEps);
}

TEST(UtilGeometry, AngleParallelAndOpposite) {
  EXPECT_NEAR(util::angle(Pt(1, 2, 3), Pt(2, 4, 6)), 0.0, kEps);
  EXPECT_NEAR(util::angle(Pt(1, 2, 3), Pt(-3, -6, -9)), util::pi, kEps);
}

TEST(UtilGeometry, AngleIsUnsigned) {
  EXPECT_NEAR(util::angle(Pt(1, 0, 0), Pt(1, 1, 0)), util::pi / 4, kEps);
  EXPECT_NEAR(util::angle(Pt(1, 0, 0), Pt(1, -1, 0)), util::pi / 4, kEps);
  EXPECT_NEAR(util::angle(Pt(1, 0, 0), Pt(-1, 1, 0)), 3 * util::pi / 4, kEps);
}

TEST(UtilGeometry, AngleWithZeroVectorIsZero) {
  EXPECT_EQ(util::angle(Pt(), Pt(1, 0, 0)), 0.0);
  EXPECT_EQ(util::angle(Pt(1, 0, 0), Pt()), 0.0);
  EXPECT_EQ(util::angle(Pt(), Pt()), 0.0);
}

TEST(UtilGeometry, AngleFloat) {
  EXPECT_NEAR(util::angle(Ptf(1, 0, 0), Ptf(0, 1, 0)), static_cast<float>(util::pi / 2), 1e-6f);
}

TEST(UtilGeometry, TriangleAreaSign) {
  const Pt a(0, 0, 0), b(2, 0, 0), c(0, 3, 0);
  EXPECT_DOUBLE_EQ(util::planar_triangle_area(a, b, c), 3.0);   // counter-clockwise
  EXPECT_DOUBLE_EQ(util::planar_triangle_area(a, c, b), -3.0);  // clockwise
  EXPECT_DOUBLE_EQ(util::planar_triangle_area(b, c, a), 3.0);   // rotation keeps sign
}

TEST(UtilGeometry, TriangleAreaIgnoresZ) {
  EXPECT_DOUBLE_EQ(util::planar_triangle_area(Pt(1, 1, 5), Pt(3, 1, -2), Pt(1, 2, 9)), 1.0);
  EXPECT_DOUBLE_EQ(util::planar_triangle_area(Pt(0, 0, 0), Pt(1, 1, 0), Pt(2, 2, 0)), 0.0);
}

TEST(UtilGeometry, LineIntersectionCrossing) {
  double ia = -1, ib = -1;
  ASSERT_TRUE(util::planar_line_intersection(Pt(0, 0, 0), Pt(2, 2, 0), Pt(0, 2, 0), Pt(2, 0, 0),
                                             ia, ib));
  EXPECT_DOUBLE_EQ(ia, 0.5);
  EXPECT_DOUBLE_EQ(ib, 0.5);

  // Horizontal a, vertical b meeting at (1, 0).
  ASSERT_TRUE(util::planar_line_intersection(Pt(0, 0, 0), Pt(4, 0, 0), Pt(1, -2, 0), Pt(1, 2, 0),
                                             ia, ib));
  EXPECT_DOUBLE_EQ(ia, 0.25);
  EXPECT_DOUBLE_EQ(ib, 0.5);
}

TEST(UtilGeometry, LineIntersectionBeyondSegments) {
  // Lines, not segments: the meeting point (3, 0) is outside both.
  const Pt a1(0, 0, 0), a2(1, 0, 0), b1(3, 1, 0), b2(3, 2, 0);
  double ia = 0, ib = 0;
  ASSERT_TRUE(util::planar_line_intersection(a1, a2, b1, b2, ia, ib));
  EXPECT_DOUBLE_EQ(ia, 3.0);
  EXPECT_DOUBLE_EQ(ib, -1.0);
  const Pt pa = a1 + ia * (a2 - a1);
  const Pt pb = b1 + ib * (b2 - b1);
  expect_point_near(pa, 3, 0, 0);
  expect_point_near(pb, 3, 0, 0);
}

TEST(UtilGeometry, LineIntersectionParallelLeavesOutputs) {
  double ia = 42, ib = 43;
  EXPECT_FALSE(util::planar_line_intersection(Pt(0, 0, 0), Pt(1, 1, 0), Pt(0, 1, 0), Pt(2, 3, 0),
                                              ia, ib));
  EXPECT_EQ(ia, 42.0);
  EXPECT_EQ(ib, 43.0);
  // Coincident lines have no single intersection either.
  EXPECT_FALSE(util::planar_line_intersection(Pt(0, 0, 0), Pt(1, 0, 0), Pt(2, 0, 0), Pt(5, 0, 0),
                                              ia, ib));
  // Decimal coordinates that are parallel on paper but not bit-exact.
  EXPECT_FALSE(util::planar_line_intersection(Pt(0, 0, 0), Pt(0.1, 0.3, 0), Pt(1, 1, 0),
                                              Pt(1.2, 1.6, 0), ia, ib));
  // A degenerate (zero-length) line.
  EXPECT_FALSE(util::planar_line_intersection(Pt(1, 1, 0), Pt(1, 1, 0), Pt(0, 0, 0), Pt(0, 1, 0),
                                              ia, ib));
  EXPECT_EQ(ia, 42.0);
  EXPECT_EQ(ib, 43.0);
}

TEST(UtilGeometry, LineIntersectionIgnoresZ) {
  double ia = 0, ib = 0;
  ASSERT_TRUE(util::planar_line_intersection(Pt(0, 0, 1), Pt(2, 2, 7), Pt(0, 2, -3), Pt(2, 0, 0),
                                             ia, ib));
  EXPECT_DOUBLE_EQ(ia, 0.5);
  EXPECT_DOUBLE_EQ(ib, 0.5);
}

TEST(UtilGeometry, RotationQuarterTurn) {
  expect_point_near(util::planar_rotation(Pt(1, 0, 5), util::pi / 2), 0, 1, 5);
  expect_point_near(util::planar_rotation(Pt(0, 1, 0), util::pi / 2), -1, 0, 0);
  expect_point_near(util::planar_rotation(Pt(2, 3, -1), util::pi / 2), -3, 2, -1);
  expect_point_near(util::planar_rotation(Pt(1, 0, 0), -util::pi / 2), 0, -1, 0);
}

TEST(UtilGeometry, RotationOtherAngles) {
  expect_point_near(util::planar_rotation(Pt(2, 3, 4), util::pi), -2, -3, 4);
  expect_point_near(util::planar_rotation(Pt(2, 3, 4), 0.0), 2, 3, 4);
  const double h = std::sqrt(0.5);
  expect_point_near(util::planar_rotation(Pt(1, 0, 0), util::pi / 4), h, h, 0);
}

TEST(UtilGeometry, RotationFloatWithDoubleAngle) {
  const Ptf r = util::planar_rotation(Ptf(1, 0, 0), util::pi / 2);
  EXPECT_NEAR(r.x(), 0.0f, 1e-6f);
  EXPECT_NEAR(r.y(), 1.0f, 1e-6f);
}

}  // namespace

// Issue 9, item 3: vv 1.1's signature, returning the point and telling
// whether it lies on each segment (ends included), worked out by hand.
TEST(UtilGeometry, LineIntersectionPointCrossingInsideBoth) {
  bool ia = false, ib = false;
  Pt p = util::planar_line_intersection(Pt(0, 0), Pt(2, 2), Pt(0, 2), Pt(2, 0), ia, ib);
  EXPECT_DOUBLE_EQ(p.x(), 1);
  EXPECT_DOUBLE_EQ(p.y(), 1);
  EXPECT_DOUBLE_EQ(p.z(), 0);
  EXPECT_TRUE(ia);
  EXPECT_TRUE(ib);
}

TEST(UtilGeometry, LineIntersectionPointOutsideOneSegment) {
  bool ia = true, ib = true;
  // a: y = 0 from x 0 to 1; b: x = 3 from y -1 to 1. They meet at (3, 0),
  // beyond a's end, inside b.
  Pt p = util::planar_line_intersection(Pt(0, 0), Pt(1, 0), Pt(3, -1), Pt(3, 1), ia, ib);
  EXPECT_DOUBLE_EQ(p.x(), 3);
  EXPECT_DOUBLE_EQ(p.y(), 0);
  EXPECT_FALSE(ia);
  EXPECT_TRUE(ib);
}

TEST(UtilGeometry, LineIntersectionPointAtAnEndIsOnTheSegment) {
  bool ia = false, ib = false;
  // b starts exactly on a's end (1/3, 1/3): a division gives it inexactly.
  Pt p = util::planar_line_intersection(Pt(0, 0), Pt(1.0 / 3, 1.0 / 3), Pt(1.0 / 3, 1.0 / 3), Pt(1, -1), ia, ib);
  EXPECT_NEAR(p.x(), 1.0 / 3, 1e-15);
  EXPECT_NEAR(p.y(), 1.0 / 3, 1e-15);
  EXPECT_TRUE(ia);
  EXPECT_TRUE(ib);
}

TEST(UtilGeometry, LineIntersectionPointOfParallelOrCollinearLinesIsNone) {
  bool ia = true, ib = true;
  Pt p = util::planar_line_intersection(Pt(0, 0), Pt(1, 1), Pt(0, 1), Pt(2, 3), ia, ib);
  EXPECT_TRUE(p == Pt());
  EXPECT_FALSE(ia);
  EXPECT_FALSE(ib);
  ia = ib = true;
  p = util::planar_line_intersection(Pt(0, 0), Pt(1, 0), Pt(2, 0), Pt(5, 0), ia, ib);  // collinear
  EXPECT_TRUE(p == Pt());
  EXPECT_FALSE(ia);
  EXPECT_FALSE(ib);
}
