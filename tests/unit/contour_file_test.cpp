// util::Contour: the curve at known parameters on a square, every VLAB
// contour format, file errors with their file:line messages, rereading.
#include <util/contour.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "test_files.hpp"

namespace {

using test_files::write_scratch;
using util::Contour;
using Pt = util::Point<double>;

void expect_point(const Pt& p, double x, double y, double z = 0) {
  EXPECT_NEAR(p.x(), x, 1e-15);
  EXPECT_NEAR(p.y(), y, 1e-15);
  EXPECT_NEAR(p.z(), z, 1e-15);
}

std::string contour_read_error(const std::string& path) {
  try {
    Contour c(path);
  } catch (const vv::error& e) {
    return e.what();
  }
  return "";
}

const std::string square_cver = "cver 1 1\nname: square\npoints: 4 4\ntype: closed\n"
                                "1 1 0 1\n1 -1 0 1\n-1 -1 0 1\n-1 1 0 1\n";

// The closed uniform cubic B-spline over the square P0 (1,1), P1 (1,-1),
// P2 (-1,-1), P3 (-1,1): four segments, on the polygons P0P1P2P3, P1P2P3P0,
// P2P3P0P1, P3P0P1P2. At the start of a segment the weights are 1/6 4/6
// 1/6 0; half way they are 1/48 23/48 23/48 1/48. So
//   c(0)   = (P0 + 4 P1 + P2)/6 = (4, -4)/6          = (2/3, -2/3)
//   c(1/8) = (P0 + 23 P1 + 23 P2 + P3)/48 = (0, -44)/48 = (0, -11/12)
//   c(1/4) = (P1 + 4 P2 + P3)/6 = (-4, -4)/6         = (-2/3, -2/3)
//   c(1/2) = (P2 + 4 P3 + P0)/6 = (-4, 4)/6          = (-2/3, 2/3)
//   c(1)   = c(0): the curve is closed.
void expect_square(const Contour& c) {
  expect_point(c(0), 2.0 / 3.0, -2.0 / 3.0);
  expect_point(c(0.125), 0, -11.0 / 12.0);
  expect_point(c(0.25), -2.0 / 3.0, -2.0 / 3.0);
  expect_point(c(0.5), -2.0 / 3.0, 2.0 / 3.0);
  expect_point(c(1), 2.0 / 3.0, -2.0 / 3.0);
  expect_point(c(-1), 2.0 / 3.0, -2.0 / 3.0);  // t is clamped to [0, 1]
}

TEST(UtilContour, ClosedSquareByHand) {
  Contour c(write_scratch("square.con", square_cver));
  EXPECT_TRUE(c.closed());
  EXPECT_FALSE(c.endpointInterpolating());
  EXPECT_EQ(c.name(), "square");
  EXPECT_EQ(c.version(), util::vlab::contour_file::format::cver_1_1);
  ASSERT_EQ(c.points().size(), 4u);
  EXPECT_EQ(c.points()[2].pos, Pt(-1, -1, 0));
  expect_square(c);
  EXPECT_EQ(c.getMin(), Pt(-1, -1, 0));
  EXPECT_EQ(c.getMax(), Pt(1, 1, 0));
}

TEST(UtilContour, OriginalFormat) {
  Contour flat(write_scratch("square2.con", "4 2 closed\n1 1\n1 -1\n-1 -1\n-1 1\n"));
  EXPECT_EQ(flat.version(), util::vlab::contour_file::format::original);
  EXPECT_EQ(flat.name(), "square2");
  expect_square(flat);

  Contour raised(write_scratch("square3.con", "4 3 closed\n1 1 2\n1 -1 2\n-1 -1 2\n-1 1 2\n"));
  expect_point(raised(0), 2.0 / 3.0, -2.0 / 3.0, 2);
  EXPECT_EQ(raised.getMax(), Pt(1, 1, 2));
}

// Open and regular: four points make one segment, from
// (P0 + 4 P1 + P2)/6 to (P1 + 4 P2 + P3)/6; it misses the end points.
TEST(UtilContour, OpenRegularMissesTheEnds) {
  Contour c(write_scratch("open.con", "cver 1 1\nname: arc\npoints: 4 4\ntype: open\n"
                                      "0 0 0 1\n1 0 0 1\n1 1 0 1\n0 1 0 1\n"));
  EXPECT_FALSE(c.closed());
  expect_point(c(0), 5.0 / 6.0, 1.0 / 6.0);  // (0 + 4 + 1, 0 + 0 + 1)/6
  expect_point(c(1), 5.0 / 6.0, 5.0 / 6.0);  // (1 + 4 + 0, 0 + 4 + 1)/6
}

// Endpoint-interpolating ("e"): four points make a cubic Bézier curve,
// c(0) = P0, c(1) = P3, c(1/2) = (P0 + 3 P1 + 3 P2 + P3)/8.
TEST(UtilContour, EndpointInterpolatingOpen) {
  Contour c(write_scratch("oe.con", "cver 1 2\nname: arc\npoints: 4 4\ntype: oe\n"
                                    "0 0 0 1\n1 0 0 1\n1 1 0 1\n0 1 0 1\n"));
  EXPECT_TRUE(c.endpointInterpolating());
  EXPECT_EQ(c.version(), util::vlab::contour_file::format::cver_1_2);
  expect_point(c(0), 0, 0);
  expect_point(c(0.5), 0.75, 0.5);  // (0 + 3 + 3 + 0, 0 + 0 + 3 + 1)/8
  expect_point(c(1), 0, 1);
}

// Closed and endpoint-interpolating: the first point is repeated at the
// end, so a triangle P0 P1 P2 gives the Bézier curve P0 P1 P2 P0:
// c(0) = c(1) = P0, c(1/2) = (P0 + 3 P1 + 3 P2 + P0)/8.
TEST(UtilContour, EndpointInterpolatingClosed) {
  Contour c(write_scratch("ce.con", "cver 1 3\nname: tri\npoints: 3 3\ntype: ce\nsamples: 12\n"
                                    "background: tri.png\nbackgroundXY: 0 0\n"
                                    "0 0 0 1\n4 0 0 1\n0 4 0 1\n"));
  EXPECT_TRUE(c.closed());
  EXPECT_EQ(c.samples(), 12u);
  expect_point(c(0), 0, 0);
  expect_point(c(0.5), 1.5, 1.5);
  expect_point(c(1), 0, 0);
}

TEST(UtilContour, Version14) {
  Contour c(write_scratch("v14.con", "version: 1.4\ncontact: 0 0 0\nend: 0 0 0\nheading: 0 1 0\nup: 0 0 -1\n"
                                     "size: 1\npoints: 4\nrange: 0.0 1.0\ndimension: 4\ntype: bspline\n"
                                     "0 0 0 1\n1 0 0 1\n1 1 0 1\n0 1 0 1\n"));
  EXPECT_EQ(c.version(), util::vlab::contour_file::format::version_1_4);
  EXPECT_FALSE(c.closed());
  expect_point(c(0), 5.0 / 6.0, 1.0 / 6.0);
}

TEST(UtilContour, MultiplicityRepeatsThePoint) {
  Contour marked(write_scratch("marked.con", "cver 1 1\nname: m\npoints: 4 5\ntype: closed\n"
                                             "1 1 0 2\n1 -1 0 1\n-1 -1 0 1\n-1 1 0 1\n"));
  Contour repeated(write_scratch("repeated.con", "5 2 closed\n1 1\n1 1\n1 -1\n-1 -1\n-1 1\n"));
  for (int i = 0; i <= 20; ++i) EXPECT_EQ(marked(i / 20.0), repeated(i / 20.0)) << i;
}

TEST(UtilContour, EmptyContour) {
  Contour c;
  EXPECT_EQ(c(0.5), Pt());
  c.reread();
  EXPECT_TRUE(c.points().empty());
}

struct bad_contour_file {
  const char* name;
  std::string text;
  std::string message;
};

TEST(UtilContour, FileErrorsNameFileAndLine) {
  const std::vector<bad_contour_file> cases = {
      {"empty.con", "\n\n",
       ":2: the file ends where a contour ('cver 1 1', 'version: 1.4' or 'COUNT DIMENSION closed|open') was "
       "expected"},
      {"header.con", "leaf\n",
       ":1: not a contour file: expected 'cver 1 1', 'version: 1.4' or 'COUNT DIMENSION closed|open', found "
       "'leaf'"},
      {"version.con", "cver 2 0\n",
       ":1: unsupported contour file version 'cver 2 0' (supported: cver 1 1, 1 2 and 1 3, version: 1.4 and the "
       "original format)"},
      {"gallery.con", "contourgalleryver 1 1\n",
       ":1: this is a contour gallery (several contours); a contour file holds one"},
      {"v15.con", "version: 1.5\n", ":1: unsupported contour file version 'version: 1.5' (supported: 1.4)"},
      {"points.con", "cver 1 1\nname: a\npoints: 4\n",
       ":3: expected 'points: N TOTAL' (point lines, sum of multiplicities), found '4'"},
      {"type11.con", "cver 1 1\nname: a\npoints: 4 4\ntype: cr\n",
       ":4: type: must be 'closed' or 'open' in cver 1 1, found 'cr'"},
      {"type12.con", "cver 1 2\nname: a\npoints: 4 4\ntype: closed\n",
       ":4: type: must be two letters, c or o (closed, open) then e or r (endpoint-interpolating, regular), "
       "found 'closed'"},
      {"total.con", "cver 1 1\nname: a\npoints: 4 4\ntype: open\n0 0 0 1\n1 0 0 2\n1 1 0 1\n0 1 0 1\n",
       ":3: points: says the multiplicities add up to 4, the points' add up to 5"},
      {"short.con", "cver 1 1\nname: a\npoints: 4 4\ntype: open\n0 0 0 1\n1 0 0 1\n1 1 0 1\n",
       ":7: the file ends where control point 4 of the 4 announced on line 3 was expected"},
      {"long.con", "4 2 open\n0 0\n1 0\n1 1\n0 1\n5 5\n", ":6: text after the 4 control points announced on line 1: '5 5'"},
      {"column.con", "cver 1 1\nname: a\npoints: 4 4\ntype: open\n0 0 0 1\n1 0 1\n1 1 0 1\n0 1 0 1\n",
       ":6: expected a control point 'x y z multiplicity', found '1 0 1'"},
      {"dimension.con", "4 2 open\n0 0\n1 0 0\n1 1\n0 1\n",
       ":3: expected a control point with 2 coordinates, found '1 0 0'"},
      {"number.con", "4 2 open\n0 0\n1 zero\n1 1\n0 1\n", ":3: y 'zero' is not a number"},
      {"mult.con", "cver 1 1\nname: a\npoints: 4 3\ntype: open\n0 0 0 1\n1 0 0 0\n1 1 0 1\n0 1 0 1\n",
       ":6: the multiplicity '0' is not a whole number from 1 to 1000"},
      {"kind.con", "4 2 round\n", ":1: the curve type must be 'closed' or 'open', found 'round'"},
      {"dim1.con", "4 1 open\n", ":1: the dimension must be at least 2 (x y), found 1"},
      {"few.con", "3 2 open\n0 0\n1 0\n1 1\n",
       ":1: an open contour needs at least 4 control points (counting multiplicity), this one has 3"},
      {"fewclosed.con", "cver 1 1\nname: a\npoints: 2 2\ntype: closed\n0 0 0 1\n1 0 0 1\n",
       ":1: a closed contour needs at least 3 control points (counting multiplicity), this one has 2"},
      {"v14type.con",
       "version: 1.4\ncontact: 0 0 0\nend: 0 0 0\nheading: 0 1 0\nup: 0 0 -1\nsize: 1\npoints: 4\n"
       "range: 0.0 1.0\ndimension: 4\ntype: bezier\n",
       ":10: type: must be 'bspline', found 'bezier'"},
  };
  for (const bad_contour_file& c : cases) {
    const std::string path = write_scratch(c.name, c.text);
    EXPECT_EQ(contour_read_error(path), path + c.message) << c.name;
  }
}

TEST(UtilContour, RereadKeepsLastGoodValuesAndTakesGoodEdits) {
  const std::string path = write_scratch("live.con", square_cver);
  Contour c(path);
  write_scratch("live.con", "cver 1 1\nname: square\npoints: 4 4\ntype: closed\n1 1 0 1\n1 -1 0 1\n");
  try {
    c.reread();
    FAIL() << "truncated file accepted";
  } catch (const vv::error& e) {
    EXPECT_EQ(std::string(e.what()), path + ":6: the file ends where control point 3 of the 4 announced on line 3 was expected");
  }
  expect_square(c);
  write_scratch("live.con", "4 2 closed\n2 2\n2 -2\n-2 -2\n-2 2\n");
  c.reread();
  expect_point(c(0), 4.0 / 3.0, -4.0 / 3.0);
  EXPECT_EQ(c.version(), util::vlab::contour_file::format::original);
}

}  // namespace
