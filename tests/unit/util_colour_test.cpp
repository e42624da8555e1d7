// util::Colour: RGBA with alpha defaulting to 1, checked by hand values.
#include <util/colour.hpp>

#include <gtest/gtest.h>

#include <sstream>
#include <type_traits>
#include <utility>

namespace {

using Col = util::Colour<float>;
using Cold = util::Colour<double>;

static_assert(std::is_same_v<decltype(0.5 * std::declval<Col>()), Col>);
static_assert(std::is_same_v<decltype(std::declval<Col>() * 2), Col>);
static_assert(std::is_same_v<decltype(std::declval<Cold>() / 2.0f), Cold>);

void expect_colour(const Col& c, float r, float g, float b, float a) {
  EXPECT_FLOAT_EQ(c.r(), r);
  EXPECT_FLOAT_EQ(c.g(), g);
  EXPECT_FLOAT_EQ(c.b(), b);
  EXPECT_FLOAT_EQ(c.a(), a);
}

TEST(UtilColour, DefaultIsOpaqueBlack) { expect_colour(Col(), 0, 0, 0, 1); }

TEST(UtilColour, Constructors) {
  expect_colour(Col(0.25f, 0.5f, 0.75f), 0.25f, 0.5f, 0.75f, 1);
  expect_colour(Col(0.25f, 0.5f, 0.75f, 0.1f), 0.25f, 0.5f, 0.75f, 0.1f);
}

TEST(UtilColour, Setters) {
  Col c;
  c.r(0.1f).g(0.2f);
  c.b(0.3f);
  c.a(0.4f);
  expect_colour(c, 0.1f, 0.2f, 0.3f, 0.4f);
}

TEST(UtilColour, IndexAndData) {
  Col c(1, 2, 3, 4);
  EXPECT_EQ(c[0], 1.0f);
  EXPECT_EQ(c[3], 4.0f);
  c[1] = 9;
  EXPECT_EQ(c.g(), 9.0f);
  const float* d = c.c_data();
  EXPECT_EQ(d[0], 1.0f);
  EXPECT_EQ(d[1], 9.0f);
  EXPECT_EQ(d[2], 3.0f);
  EXPECT_EQ(d[3], 4.0f);
  c.data()[2] = 7;
  EXPECT_EQ(c.b(), 7.0f);
  const Col& cc = c;
  EXPECT_EQ(cc[2], 7.0f);
}

TEST(UtilColour, AddSubtract) {
  const Col a(0.5f, 0.25f, 0, 1), b(0.25f, 0.25f, 0.5f, 0.5f);
  expect_colour(a + b, 0.75f, 0.5f, 0.5f, 1.5f);
  expect_colour(a - b, 0.25f, 0, -0.5f, 0.5f);
  Col c = a;
  c += b;
  c -= a;
  EXPECT_EQ(c, b);
}

TEST(UtilColour, ScalarOperators) {
  const Col c(0.5f, 1, 0.25f, 1);
  expect_colour(c * 2, 1, 2, 0.5f, 2);
  expect_colour(2 * c, 1, 2, 0.5f, 2);
  expect_colour(c * 0.5f, 0.25f, 0.5f, 0.125f, 0.5f);
  expect_colour(0.5 * c, 0.25f, 0.5f, 0.125f, 0.5f);
  expect_colour(c / 2, 0.25f, 0.5f, 0.125f, 0.5f);
  expect_colour(c / 0.5, 1, 2, 0.5f, 2);
  Col d = c;
  d *= 4;
  d /= 2.0f;
  expect_colour(d, 1, 2, 0.5f, 2);
}

TEST(UtilColour, Equality) {
  EXPECT_TRUE(Col(1, 0, 0) == Col(1, 0, 0, 1));
  EXPECT_FALSE(Col(1, 0, 0) == Col(1, 0, 0, 0.5f));
  EXPECT_TRUE(Col(1, 0, 0) != Col(0, 1, 0));
  EXPECT_FALSE(Col(1, 0, 0) != Col(1, 0, 0));
}

TEST(UtilColour, BlendIsLinear) {
  const Col red(1, 0, 0, 1), blue(0, 0, 1, 0);
  EXPECT_EQ(red.blend(blue, 0), red);
  EXPECT_EQ(red.blend(blue, 1), blue);
  expect_colour(red.blend(blue, 0.5f), 0.5f, 0, 0.5f, 0.5f);
  expect_colour(red.blend(blue, 0.25f), 0.75f, 0, 0.25f, 0.75f);
  expect_colour(red, 1, 0, 0, 1);  // blend does not modify its operands
}

TEST(UtilColour, StreamRoundTrip) {
  const Cold c(0.1, 0.2, 0.3, 0.4);
  std::ostringstream os;
  os << c;
  EXPECT_EQ(os.str(), "0.1 0.2 0.3 0.4");
  std::istringstream is(os.str());
  Cold d;
  is >> d;
  ASSERT_FALSE(is.fail());
  EXPECT_EQ(d, c);
}

}  // namespace
