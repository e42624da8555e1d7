// util::Point: the vv 1.1 vector API, checked against hand-computed values.
// Including only point.hpp must also bring in the geometry helpers.
#include <util/point.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace {

using Pt = util::Point<double>;
using Ptf = util::Point<float>;

// Compile-time contract: scalars keep the point type, `p * q` is a dot.
static_assert(std::is_same_v<decltype(0.5f * std::declval<Pt>()), Pt>);
static_assert(std::is_same_v<decltype(std::declval<Pt>() * 2), Pt>);
static_assert(std::is_same_v<decltype(2 * std::declval<Pt>()), Pt>);
static_assert(std::is_same_v<decltype(std::declval<Pt>() * 0.5), Pt>);
static_assert(std::is_same_v<decltype(std::declval<Pt>() / 2), Pt>);
static_assert(std::is_same_v<decltype(std::declval<Pt>() / 2.0f), Pt>);
static_assert(std::is_same_v<decltype(std::declval<Ptf>() * 0.5), Ptf>);
static_assert(std::is_same_v<decltype(2u * std::declval<Ptf>()), Ptf>);
static_assert(std::is_same_v<decltype(std::declval<Pt>() * std::declval<Pt>()), double>);
static_assert(std::is_same_v<decltype(std::declval<Ptf>() * std::declval<Ptf>()), float>);
// Conversions must be spelled out: no silent double<->float or glm->Point.
static_assert(!std::is_convertible_v<Ptf, Pt>);
static_assert(std::is_constructible_v<Pt, Ptf>);
static_assert(!std::is_convertible_v<glm::dvec3, Pt>);
static_assert(!std::is_convertible_v<double, Pt>);

// Detects `P * X` so that non-numbers can be shown not to multiply.
template <class P, class X, class = void>
struct can_multiply : std::false_type {};
template <class P, class X>
struct can_multiply<P, X, std::void_t<decltype(std::declval<P>() * std::declval<X>())>>
    : std::true_type {};
static_assert(!can_multiply<Pt, const char*>::value);
static_assert(can_multiply<Pt, long double>::value);

void expect_point(const Pt& p, double x, double y, double z) {
  EXPECT_DOUBLE_EQ(p.x(), x);
  EXPECT_DOUBLE_EQ(p.y(), y);
  EXPECT_DOUBLE_EQ(p.z(), z);
}

TEST(UtilPoint, DefaultIsZero) { expect_point(Pt(), 0, 0, 0); }

TEST(UtilPoint, ComponentConstructorAndGetters) {
  const Pt p(1.5, -2, 3.25);
  EXPECT_EQ(p.x(), 1.5);
  EXPECT_EQ(p.y(), -2.0);
  EXPECT_EQ(p.z(), 3.25);
}

TEST(UtilPoint, GlmConstructorAndAccessor) {
  Pt p(glm::dvec3(1, 2, 3));
  expect_point(p, 1, 2, 3);
  EXPECT_EQ(p.glm(), glm::dvec3(1, 2, 3));
  p.glm().y = 7;  // non-const accessor writes through
  EXPECT_EQ(p.y(), 7.0);
  const Pt& cp = p;
  EXPECT_EQ(cp.glm().y, 7.0);
}

TEST(UtilPoint, ConvertingConstructor) {
  const Ptf f(0.5f, 1.25f, -2.0f);
  const Pt d(f);
  expect_point(d, 0.5, 1.25, -2.0);
  const util::Point<int> i(Pt(1.0, 2.0, -3.0));
  EXPECT_EQ(i, util::Point<int>(1, 2, -3));
}

TEST(UtilPoint, SettersChangeOneCoordinate) {
  Pt p(1, 2, 3);
  p.x(10);
  expect_point(p, 10, 2, 3);
  p.y(20);
  expect_point(p, 10, 20, 3);
  p.z(30);
  expect_point(p, 10, 20, 30);
  p.x() += 1;  // non-const getter is a reference
  EXPECT_EQ(p.x(), 11.0);
}

TEST(UtilPoint, SetAndZero) {
  Pt p;
  p.set(4, 5, 6);
  expect_point(p, 4, 5, 6);
  Pt& r = p.zero();
  EXPECT_EQ(&r, &p);
  expect_point(p, 0, 0, 0);
}

TEST(UtilPoint, IndexOperator) {
  Pt p(7, 8, 9);
  EXPECT_EQ(p[0], 7.0);
  EXPECT_EQ(p[1], 8.0);
  EXPECT_EQ(p[2], 9.0);
  p[1] = -1;
  EXPECT_EQ(p.y(), -1.0);
  const Pt& cp = p;
  EXPECT_EQ(cp[2], 9.0);
}

TEST(UtilPoint, DataIsThreeContiguousValues) {
  Pt p(1, 2, 3);
  const double* c = p.c_data();
  EXPECT_EQ(c[0], 1.0);
  EXPECT_EQ(c[1], 2.0);
  EXPECT_EQ(c[2], 3.0);
  p.data()[2] = 5;
  EXPECT_EQ(p.z(), 5.0);
}

TEST(UtilPoint, LengthAndDistance) {
  const Pt p(3, 4, 12);
  EXPECT_DOUBLE_EQ(p.length_sq(), 169.0);
  EXPECT_DOUBLE_EQ(p.length(), 13.0);
  EXPECT_DOUBLE_EQ(Pt(1, 1, 1).distance(Pt(4, 5, 1)), 5.0);
}

TEST(UtilPoint, CrossProduct) {
  expect_point(Pt(1, 0, 0).cross(Pt(0, 1, 0)), 0, 0, 1);
  expect_point(Pt(0, 1, 0).cross(Pt(1, 0, 0)), 0, 0, -1);
  expect_point(Pt(1, 2, 3).cross(Pt(4, 5, 6)), -3, 6, -3);
}

TEST(UtilPoint, NormaliseInPlace) {
  Pt p(3, 0, 4);
  Pt& r = p.normalise();
  EXPECT_EQ(&r, &p);
  expect_point(p, 0.6, 0, 0.8);
  Pt q(0, -2, 0);
  q.normalize();
  expect_point(q, 0, -1, 0);
}

TEST(UtilPoint, NormaliseZeroStaysZero) {
  Pt p;
  p.normalise();
  EXPECT_FALSE(std::isnan(p.x()) || std::isnan(p.y()) || std::isnan(p.z()));
  expect_point(p, 0, 0, 0);
}

TEST(UtilPoint, ProductOfPointsIsDot) {
  EXPECT_DOUBLE_EQ(Pt(1, 2, 3) * Pt(4, 5, 6), 32.0);
  EXPECT_DOUBLE_EQ(Pt(1, 0, 0) * Pt(0, 1, 0), 0.0);
}

TEST(UtilPoint, ScalarMultiplyBothSides) {
  const Pt p(1, 2, 3);
  expect_point(p * 2, 2, 4, 6);
  expect_point(2 * p, 2, 4, 6);
  expect_point(p * 0.5f, 0.5, 1, 1.5);
  expect_point(0.5f * p, 0.5, 1, 1.5);
  expect_point(p * 0.25, 0.25, 0.5, 0.75);
  expect_point(0.25 * p, 0.25, 0.5, 0.75);
  expect_point(3u * p, 3, 6, 9);
  expect_point(p * -1, -1, -2, -3);
}

TEST(UtilPoint, ScalarDivide) {
  const Pt p(1, 2, 3);
  expect_point(p / 2, 0.5, 1, 1.5);  // int scalar, still real division
  expect_point(p / 4.0f, 0.25, 0.5, 0.75);
  expect_point(p / 0.5, 2, 4, 6);
}

TEST(UtilPoint, FloatPointWithDoubleScalar) {
  const Ptf p(1, 2, 3);
  const Ptf q = p * 0.5;
  EXPECT_FLOAT_EQ(q.x(), 0.5f);
  EXPECT_FLOAT_EQ(q.z(), 1.5f);
  EXPECT_FLOAT_EQ((2.0 * p).y(), 4.0f);
}

TEST(UtilPoint, IntPointArithmetic) {
  const util::Point<int> p(1, -2, 3);
  EXPECT_EQ(p * 2, util::Point<int>(2, -4, 6));
  EXPECT_EQ(p / 2, util::Point<int>(0, -1, 1));  // integer division
  EXPECT_EQ(p * p, 14);
}

TEST(UtilPoint, AddSubtractNegate) {
  const Pt a(1, 2, 3), b(10, 20, 30);
  expect_point(a + b, 11, 22, 33);
  expect_point(b - a, 9, 18, 27);
  expect_point(-a, -1, -2, -3);
}

TEST(UtilPoint, CompoundAssignment) {
  Pt p(1, 2, 3);
  EXPECT_EQ(&(p += Pt(1, 1, 1)), &p);
  expect_point(p, 2, 3, 4);
  p -= Pt(2, 2, 2);
  expect_point(p, 0, 1, 2);
  p *= 3;
  expect_point(p, 0, 3, 6);
  p *= 0.5f;
  expect_point(p, 0, 1.5, 3);
  p *= 2.0;
  expect_point(p, 0, 3, 6);
  p /= 3;
  expect_point(p, 0, 1, 2);
  p /= 4.0f;
  expect_point(p, 0, 0.25, 0.5);
  p /= 0.25;
  expect_point(p, 0, 1, 2);
}

TEST(UtilPoint, Equality) {
  EXPECT_TRUE(Pt(1, 2, 3) == Pt(1, 2, 3));
  EXPECT_FALSE(Pt(1, 2, 3) != Pt(1, 2, 3));
  EXPECT_TRUE(Pt(1, 2, 3) != Pt(1, 2, 4));
  EXPECT_FALSE(Pt(1, 2, 3) == Pt(0, 2, 3));
  EXPECT_TRUE(Pt(0.0, 0, 0) == Pt(-0.0, 0, 0));  // numeric, not bitwise
}

TEST(UtilPoint, StreamOutputUsesSpaces) {
  std::ostringstream os;
  os << Pt(1, 2.5, -3);
  EXPECT_EQ(os.str(), "1 2.5 -3");
}

TEST(UtilPoint, StreamOutputHonoursFormatting) {
  std::ostringstream os;
  os << std::fixed << std::setprecision(2) << Pt(1.0 / 3, 2, -0.125);
  EXPECT_EQ(os.str(), "0.33 2.00 -0.12");
}

TEST(UtilPoint, StreamRoundTrip) {
  const Pt p(0.1, -123.456, 1e-7);
  std::ostringstream os;
  os << std::setprecision(17) << p;
  std::istringstream is(os.str());
  Pt q;
  is >> q;
  ASSERT_FALSE(is.fail());
  EXPECT_EQ(q, p);
}

TEST(UtilPoint, StreamInputReadsThreeValues) {
  std::istringstream is("4 5 6 7");
  Pt p;
  is >> p;
  expect_point(p, 4, 5, 6);
  double rest = 0;
  is >> rest;
  EXPECT_EQ(rest, 7.0);
}

TEST(UtilPoint, StreamInputFailsOnShortInput) {
  std::istringstream is("1 2");
  Pt p;
  is >> p;
  EXPECT_TRUE(is.fail());
}

TEST(UtilPoint, HeaderAlsoProvidesGeometry) {
  EXPECT_DOUBLE_EQ(util::angle(Pt(1, 0, 0), Pt(0, 0, 1)), util::pi / 2);
}

}  // namespace

// Issue 9, item 2: vv 1.1 programs write 2D points with two coordinates,
// e.g. a normal `Pt n(-w.y(), w.x());`.
TEST(UtilPoint, TwoCoordinatesMakeAPointOfTheXyPlane) {
  Pt w(3, 4, 9);
  Pt n(-w.y(), w.x());
  expect_point(n, -4, 3, 0);
  util::Point<float> f(1.5f, -2.0f);
  expect_point(Pt(f), 1.5, -2, 0);
}

// A vector of points (util/first_room_vector.hpp) is a standard vector
// whose first push makes room for four.
TEST(UtilPoint, AVectorOfPointsMakesRoomForFourAtItsFirstPush) {
  using points = std::vector<Pt>;
  static_assert(std::is_same<std::allocator_traits<points::allocator_type>::rebind_alloc<Pt>,
                             points::allocator_type>::value);
  points corners;
  EXPECT_EQ(corners.capacity(), 0u);
  corners.push_back(Pt(1, 0, 0));
  EXPECT_EQ(corners.capacity(), 4u);
  const Pt* block = corners.data();
  corners.emplace_back(0, 1, 0);
  corners.push_back(Pt(0, 0, 1));
  corners.emplace_back();
  EXPECT_EQ(corners.data(), block) << "four points fit without moving";
  corners.push_back(Pt(2, 2, 2));
  EXPECT_EQ(corners.size(), 5u);
  expect_point(corners[1], 0, 1, 0);
  expect_point(corners[3], 0, 0, 0);
  expect_point(corners.back(), 2, 2, 2);

  points same{Pt(1, 0, 0), Pt(0, 1, 0), Pt(0, 0, 1), Pt(), Pt(2, 2, 2)};
  EXPECT_EQ(corners, same);
  std::vector deduced{Pt(1, 0, 0)};
  static_assert(std::is_same<decltype(deduced), points>::value);
  deduced = {Pt(3, 3, 3)};
  points moved = std::move(deduced);
  EXPECT_TRUE(deduced.empty());
  expect_point(moved.front(), 3, 3, 3);
  std::vector<Ptf> floats;
  floats.push_back(Ptf(1, 2, 3));
  EXPECT_EQ(floats.capacity(), 4u);
}
