// util::Function: evaluation against values worked out by hand, both VLAB
// function formats, writing and reading back, every file error with its
// file:line message, and rereading after good and bad edits.
#include <util/function.hpp>

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "test_files.hpp"

namespace {

using test_files::write_scratch;
using util::Function;

std::string fver(const std::string& points_block, const std::string& samples = "10") {
  return "fver 1 1\nname: test\nsamples: " + samples + "\nflip: off\n" + points_block;
}

// The message a bad file gives, "" if it reads.
std::string function_read_error(const std::string& path) {
  try {
    Function f(path);
  } catch (const vv::error& e) {
    return e.what();
  }
  return "";
}

// For control points on a line y = a x + b every point of the spline is an
// affine combination of them (the B-spline weights sum to 1), so
// y(t) = a x(t) + b whatever t solves x(t) = x: f is the line itself, to
// rounding. The x spacing is uneven, so x(t) is not linear in t and the
// solver has real work.
TEST(UtilFunction, PointsOnALineGiveThatLine) {
  Function twice(write_scratch("twice.func", fver("points: 5\n0 0\n0.1 0.2\n0.7 1.4\n0.8 1.6\n1 2\n")));
  Function falling(write_scratch("falling.func", fver("points: 4\n0 0.5\n0.2 0.45\n0.9 0.275\n1 0.25\n")));
  for (int i = 0; i <= 40; ++i) {
    const double x = i / 40.0;
    EXPECT_NEAR(twice(x), 2 * x, 1e-15) << "x = " << x;
    EXPECT_NEAR(falling(x), 0.5 - 0.25 * x, 1e-15) << "x = " << x;
  }
}

// Four points make one cubic Bézier segment (knots 0 0 0 0 1 1 1 1).
// Points (0,0) (1/3,1/9) (2/3,4/9) (1,1) lie on y = x²; evenly spaced x gives
// x(t) = t, and
//   y(t) = 3t(1-t)²·1/9 + 3t²(1-t)·4/9 + t³
//        = t/3 - 2t²/3 + t³/3 + 4t²/3 - 4t³/3 + t³ = t/3 + 2t²/3,
// so f(1/2) = 1/6 + 1/6 = 1/3 and f(1/4) = 1/12 + 1/24 = 1/8 (not x²).
TEST(UtilFunction, ParabolaOneSegmentByHand) {
  Function f(write_scratch("bezier.func", fver("points: 4\n0 0\n0.3333333333333333 0.1111111111111111\n"
                                                "0.6666666666666666 0.4444444444444444\n1 1\n")));
  EXPECT_NEAR(f(0.5), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(f(0.25), 1.0 / 8.0, 1e-15);
  EXPECT_NEAR(f(0.75), 0.25 + 2.0 / 3.0 * 0.5625, 1e-15);  // t/3 + 2t²/3 at t = 3/4
}

// Five points: knots 0 0 0 0 1 2 2 2 2, t in [0, 2]. The x are the knot
// averages (Greville abscissae) 0, 1/3, 1, 5/3, 2, so x(t) = t; y = x² there:
// 0, 1/9, 1, 25/9, 4. De Boor's algorithm by hand (P0..P4 the y values,
// alpha = (t - t_j) / (t_{j+4-r} - t_j)):
//
// t = 1/2, span [0,1], P0..P3:
//   r=1: alpha 1/4 1/4 1/2 -> d3 = 3/4·1 + 1/4·25/9 = 13/9,
//        d2 = 3/4·1/9 + 1/4·1 = 1/3, d1 = 1/2·0 + 1/2·1/9 = 1/18
//   r=2: alpha 1/4 1/2 -> d3 = 3/4·1/3 + 1/4·13/9 = 11/18, d2 = (1/18 + 1/3)/2 = 7/36
//   r=3: alpha 1/2 -> (7/36 + 11/18)/2 = 29/72
// t = 1, span [1,2], P1..P4:
//   r=1: alpha 0 1/2 1/2 -> d4 = P3 = 25/9, d3 = (1 + 25/9)/2, d2 = (1/9 + 1)/2
//   r=2: alpha 0 1/2 -> d4 = (1 + 25/9)/2, d3 = (1/9 + 2 + 25/9)/4
//   r=3: alpha 0 -> (1/9 + 2 + 25/9)/4 = 11/9
// t = 3/2, span [1,2], P1..P4:
//   r=1: alpha 1/2 3/4 3/4 -> d4 = (25/9 + 4)/2 = 61/18,
//        d3 = 1/4·1 + 3/4·25/9 = 7/3, d2 = 1/4·1/9 + 3/4·1 = 7/9
//   r=2: alpha 1/2 3/4 -> d4 = (7/3 + 61/18)/2 = 103/36, d3 = 1/4·7/9 + 3/4·7/3 = 35/18
//   r=3: alpha 1/2 -> (35/18 + 103/36)/2 = 173/72
TEST(UtilFunction, ParabolaTwoSegmentsByHand) {
  Function f(write_scratch("greville.func", fver("points: 5\n0 0\n0.3333333333333333 0.1111111111111111\n"
                                                  "1 1\n1.6666666666666667 2.7777777777777777\n2 4\n")));
  EXPECT_NEAR(f(0.5), 29.0 / 72.0, 1e-14);
  EXPECT_NEAR(f(1.0), 11.0 / 9.0, 1e-14);
  EXPECT_NEAR(f(1.5), 173.0 / 72.0, 1e-14);
  EXPECT_EQ(f(0.0), 0.0);  // the ends are the first and last points
  EXPECT_EQ(f(2.0), 4.0);
}

// x not linear in t: points (0,0) (0,1) (1,1) (1,1) give
// x(t) = 3t²(1-t) + t³ = 3t² - 2t³ and y(t) = 3t(1-t)² + 3t²(1-t) + t³.
// x = 1/2 needs t = 1/2: y = 3/8 + 3/8 + 1/8 = 7/8.
// x = 5/32 needs t = 1/4 (3/16 - 2/64 = 5/32): y = 27/64 + 9/64 + 1/64 = 37/64.
TEST(UtilFunction, SolvesForTWhereXIsNotLinear) {
  Function f(write_scratch("ease.func", fver("points: 4\n0 0\n0 1\n1 1\n1 1\n")));
  EXPECT_NEAR(f(0.5), 7.0 / 8.0, 1e-15);
  EXPECT_NEAR(f(5.0 / 32.0), 37.0 / 64.0, 1e-15);
}

TEST(UtilFunction, OutsideTheDomainTheEndValues) {
  Function f(write_scratch("ends.func", fver("points: 4\n0.2 3\n0.4 1\n0.6 2\n0.8 -1\n")));
  EXPECT_EQ(f(-5), 3.0);
  EXPECT_EQ(f(0.2), 3.0);
  EXPECT_EQ(f(0.8), -1.0);
  EXPECT_EQ(f(7), -1.0);
}

TEST(UtilFunction, MinMaxAreTheControlPointBox) {
  Function f(write_scratch("box.func", fver("points: 4\n0.2 3\n0.4 1\n0.6 2\n0.8 -1\n")));
  EXPECT_EQ(f.getMin(), util::Point<double>(0.2, -1));
  EXPECT_EQ(f.getMax(), util::Point<double>(0.8, 3));
}

// A point of multiplicity m stands m times in the control polygon.
TEST(UtilFunction, MultiplicityRepeatsThePoint) {
  Function marked(write_scratch("marked.func", fver("points: 4\n0 0\n0.4 1 2\n0.6 0\n1 1\n")));
  Function repeated(write_scratch("repeated.func", fver("points: 5\n0 0\n0.4 1\n0.4 1\n0.6 0\n1 1\n")));
  ASSERT_EQ(marked.points().size(), 4u);
  EXPECT_EQ(marked.points()[1].multiplicity, 2u);
  for (int i = 0; i <= 20; ++i) EXPECT_EQ(marked(i / 20.0), repeated(i / 20.0)) << i;
}

TEST(UtilFunction, SamplesAreKeptNotUsed) {
  Function coarse(write_scratch("coarse.func", fver("points: 4\n0 0\n0 1\n1 1\n1 1\n", "2")));
  Function fine(write_scratch("fine.func", fver("points: 4\n0 0\n0 1\n1 1\n1 1\n", "5000")));
  EXPECT_EQ(coarse.samples(), 2u);
  EXPECT_EQ(fine.samples(), 5000u);
  for (int i = 0; i <= 20; ++i) EXPECT_EQ(coarse(i / 20.0), fine(i / 20.0)) << i;
}

TEST(UtilFunction, OriginalFormat) {
  const std::string path = write_scratch("stem.func", "range: 0.0 1.0\npoints: 4\n0.0 0.0\n0.3 0.1\n0.6 0.9\n1.0 0.3\n");
  Function f(path);
  EXPECT_EQ(f.version(), util::vlab::function_file::format::original);
  EXPECT_EQ(f.name(), "stem");  // the file name, as funcedit names it
  EXPECT_EQ(f.samples(), 10u);
  EXPECT_FALSE(f.flip());
  ASSERT_EQ(f.points().size(), 4u);
  EXPECT_EQ(f.points()[2].pos, util::Point<double>(0.6, 0.9));
  EXPECT_EQ(f.path(), path);
  EXPECT_EQ(f.getFilename(), path);

  // The same points in fver 1 1 give the same function.
  Function same(write_scratch("same.func", fver("points: 4\n0.0 0.0\n0.3 0.1\n0.6 0.9\n1.0 0.3\n")));
  for (int i = 0; i <= 20; ++i) EXPECT_EQ(f(i / 20.0), same(i / 20.0)) << i;
}

TEST(UtilFunction, Fver11AllStatements) {
  Function f(write_scratch("full.func",
                           "fver 1 1\r\nname: branch length\r\nsamples: 64\r\n\r\nbackground: leaf.png\r\n"
                           "backgroundXY: 0.25 -0.5\r\nflip: on\r\npoints: 4\r\n0 1\r\n0.5 2 3\r\n0.5 2\r\n1 4\r\n"));
  EXPECT_EQ(f.version(), util::vlab::function_file::format::fver_1_1);
  EXPECT_EQ(f.name(), "branch length");
  EXPECT_EQ(f.samples(), 64u);
  EXPECT_TRUE(f.flip());
  ASSERT_EQ(f.points().size(), 4u);
  EXPECT_EQ(f.points()[1].multiplicity, 3u);
  EXPECT_EQ(f(0), 1.0);
  EXPECT_EQ(f(1), 4.0);
}

TEST(UtilFunction, WriteIsFver11AndReadsBackTheSame) {
  const std::string from = write_scratch(
      "edit.func", "fver 1 1\nname: growth\nsamples: 30\nbackground: sketch.png\nbackgroundXY: 0.1 0.2\n"
                   "flip: on\npoints: 5\n0 0.1\n0.1 0.30000000000000004\n0.3333333333333333 1e-07 2\n0.9 -2.5\n1 1\n");
  Function f(from);
  const std::string to = test_files::scratch_dir() + "edit-copy.func";
  f.write(to);
  EXPECT_EQ(test_files::slurp(to),
            "fver 1 1\nname: growth\nsamples: 30\nbackground: sketch.png\nbackgroundXY: 0.1 0.2\nflip: on\n"
            "points: 5\n0 0.1\n0.1 0.30000000000000004\n0.3333333333333333 1e-07 2\n0.9 -2.5\n1 1\n");
  Function back(to);
  EXPECT_EQ(back.points(), f.points());
  EXPECT_EQ(back.name(), "growth");
  EXPECT_EQ(back.samples(), 30u);
  EXPECT_TRUE(back.flip());
  for (int i = 0; i <= 20; ++i) EXPECT_EQ(back(i / 20.0), f(i / 20.0)) << i;
}

TEST(UtilFunction, OriginalFormatIsWrittenAsFver11) {
  Function f(write_scratch("old.func", "range: 0.0 1.0\npoints: 4\n0 0\n0.3 0.1\n0.6 0.9\n1 0.3\n"));
  const std::string to = test_files::scratch_dir() + "old-as-new.func";
  f.write(to);
  EXPECT_EQ(test_files::slurp(to), "fver 1 1\nname: old\nsamples: 10\nflip: off\npoints: 4\n0 0\n0.3 0.1\n0.6 0.9\n1 0.3\n");
}

TEST(UtilFunction, EditAndSave) {
  const std::string path = write_scratch("editor.func", fver("points: 4\n0 0\n0.3 0.1\n0.6 0.9\n1 0.3\n"));
  Function f(path);
  std::vector<Function::ControlPoint> points = f.points();
  points[1].pos.y(2);
  points[2].multiplicity = 2;
  f.setPoints(points);
  f.setName("  edited ");
  f.setSamples(7);
  f.setFlip(true);
  EXPECT_EQ(f.points(), points);
  f.write();
  Function back(path);
  EXPECT_EQ(back.points(), points);
  EXPECT_EQ(back.name(), "edited");
  EXPECT_EQ(back.samples(), 7u);
  EXPECT_TRUE(back.flip());
  EXPECT_EQ(back.getMax().y(), 2.0);

  points[2].pos.x(0.2);  // now x decreases at point 3
  try {
    f.setPoints(points);
    FAIL() << "decreasing x accepted";
  } catch (const vv::error& e) {
    EXPECT_EQ(std::string(e.what()),
              path + ": control point 3: x decreases from 0.3 to 0.2: a function's control points must have "
                     "non-decreasing x");
  }
  EXPECT_EQ(f.points()[2].pos.x(), 0.6);  // unchanged
  EXPECT_THROW(f.setPoints({}), vv::error);
  EXPECT_THROW(f.setSamples(0), vv::error);
  EXPECT_THROW(f.setName("two\nlines"), vv::error);
}

TEST(UtilFunction, EmptyFunction) {
  Function f;
  EXPECT_EQ(f(0.5), 0.0);
  EXPECT_EQ(f.path(), "");
  f.reread();  // no file: nothing to do
  EXPECT_TRUE(f.points().empty());
  EXPECT_THROW(f.write(test_files::scratch_dir() + "nothing.func"), vv::error);
}

struct bad_function_file {
  const char* name;
  std::string text;
  std::string message;  // after "path"
};

TEST(UtilFunction, FileErrorsNameFileAndLine) {
  const std::string good_points = "points: 4\n0 0\n0.3 0.1\n0.6 0.9\n1 0.3\n";
  const std::vector<bad_function_file> cases = {
      {"empty.func", "", ": the file ends where 'fver 1 1' or 'range:' was expected"},
      {"header.func", "\n  hello world\n", ":2: not a function file: expected 'fver 1 1' or 'range:', found 'hello world'"},
      {"version.func", "fver 1 2\n",
       ":1: unsupported function file version 'fver 1 2' (supported: 'fver 1 1' and the original format starting "
       "with 'range:')"},
      {"gallery.func", "funcgalleryver 1 1\nitems: 1\n",
       ":1: this is a function gallery (several functions); a function file holds one"},
      {"range.func", "range: 0 one\n" + good_points, ":1: range 'one' is not a number"},
      {"range2.func", "range: 0\n" + good_points, ":1: expected 'range: MIN MAX', found 'range: 0'"},
      {"noname.func", "fver 1 1\nsamples: 10\n", ":2: expected 'name: NAME', found 'samples: 10'"},
      {"samples.func", "fver 1 1\nname: a\nsamples: many\n", ":3: samples: expects a whole number, found 'many'"},
      {"samples0.func", "fver 1 1\nname: a\nsamples: 0\n", ":3: samples: must be at least 1"},
      {"flip.func", "fver 1 1\nname: a\nsamples: 10\nflip: yes\n", ":4: flip: must be 'on' or 'off', found 'yes'"},
      {"nobgxy.func", "fver 1 1\nname: a\nsamples: 10\nbackground: x.png\nflip: off\n",
       ":5: expected 'backgroundXY: X Y' after 'background:', found 'flip: off'"},
      {"nopoints.func", fver("0 0\n"), ":5: expected 'points: N', found '0 0'"},
      {"count.func", fver("points: four\n"), ":5: points: expects a whole number, found 'four'"},
      {"three.func", fver("points: 3\n0 0\n0.5 1\n1 0\n"),
       ":5: a function needs at least 4 control points, 'points:' says 3"},
      {"short.func", fver("points: 4\n0 0\n0.3 0.1\n\n0.6 0.9\n"),
       ":9: the file ends where control point 4 of the 4 that 'points:' on line 5 announces was expected"},
      {"long.func", fver(good_points + "2 2\n"),
       ":10: text after the 4 control points that 'points:' on line 5 announces: '2 2'"},
      {"nan.func", fver("points: 4\n0 0\n0.3 x\n0.6 0.9\n1 0.3\n"), ":7: y 'x' is not a number"},
      {"inf.func", fver("points: 4\n0 0\n0.3 inf\n0.6 0.9\n1 0.3\n"), ":7: y 'inf' is not a number"},
      {"column.func", fver("points: 4\n0 0\n0.3\n0.6 0.9\n1 0.3\n"),
       ":7: expected a control point 'x y' or 'x y multiplicity', found '0.3'"},
      {"columns.func", fver("points: 4\n0 0\n0.3 0.1 1 1\n0.6 0.9\n1 0.3\n"),
       ":7: expected a control point 'x y' or 'x y multiplicity', found '0.3 0.1 1 1'"},
      {"mult.func", fver("points: 4\n0 0\n0.3 0.1 0\n0.6 0.9\n1 0.3\n"),
       ":7: the multiplicity '0' is not a whole number from 1 to 1000"},
      {"decreasing.func", fver("points: 4\n0 0\n0.6 0.1\n0.5 0.9\n1 0.3\n"),
       ":8: x decreases from 0.6 (line 7) to 0.5: a function's control points must have non-decreasing x"},
  };
  for (const bad_function_file& c : cases) {
    const std::string path = write_scratch(c.name, c.text);
    EXPECT_EQ(function_read_error(path), path + c.message) << c.name;
  }
  const std::string missing = test_files::scratch_dir() + "missing.func";
  EXPECT_EQ(function_read_error(missing), missing + ": cannot open: No such file or directory");
  EXPECT_EQ(function_read_error(test_files::scratch_dir()),
            test_files::scratch_dir() + ": cannot open: it is a folder, not a file");
}

TEST(UtilFunction, ErrorsCarryFileAndLine) {
  const std::string path = write_scratch("located.func", fver("points: 4\n0 0\n0.6 0.1\n0.5 0.9\n1 0.3\n"));
  try {
    Function f(path);
    FAIL() << "read";
  } catch (const vv::error& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_EQ(e.line(), 8);
  }
}

TEST(UtilFunction, RereadKeepsLastGoodValuesAndTakesGoodEdits) {
  const std::string path = write_scratch("edited.func", fver("points: 4\n0 0\n0.3 0.6\n0.6 1.2\n1 2\n"));
  Function f(path);
  EXPECT_NEAR(f(0.5), 1.0, 1e-15);

  write_scratch("edited.func", fver("points: 4\n0 0\n0.3 0.6\n0.2 1.2\n1 2\n"));  // a slip while editing
  try {
    f.reread();
    FAIL() << "bad edit accepted";
  } catch (const vv::error& e) {
    EXPECT_EQ(std::string(e.what()),
              path + ":8: x decreases from 0.3 (line 7) to 0.2: a function's control points must have "
                     "non-decreasing x");
  }
  EXPECT_NEAR(f(0.5), 1.0, 1e-15);  // still the last good function
  EXPECT_EQ(f.points()[2].pos.x(), 0.6);

  write_scratch("edited.func", fver("points: 4\n0 1\n0.3 1\n0.6 1\n1 1\n", "20"));
  f.reread();
  EXPECT_DOUBLE_EQ(f(0.5), 1.0);
  EXPECT_DOUBLE_EQ(f(0.1), 1.0);
  EXPECT_EQ(f.samples(), 20u);
}

}  // namespace
