// util::Function: a VLAB function file (function_file.hpp) as a function of
// one variable, y = f(x), re-read on the host's "reread files".
//
//   util::Function growth("growth.func");   // relative to the model's folder
//   double rate = growth(v$age);
//
// The function is the clamped cubic B-spline (x(t), y(t)) over the control
// points (bspline.hpp): it passes through the first and the last point, and
// x(t) never decreases because the points' x never decrease. f(x) solves
// x(t) = x by bisection to the last bit of t and returns y(t): it is exact
// to rounding and does not depend on `samples` (vv 1.1 interpolated in a
// table of samples; the value is kept for the editor and for lpfg).
// Outside [first x, last x], f is the first or the last point's y.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <vv/error.hpp>
#include <model/registered_file.hpp>

#include "bspline.hpp"
#include "function_file.hpp"
#include "point.hpp"

namespace util {

namespace function_detail {
//! A function's contents: the file and the spline made from it.
struct curve {
  vlab::function_file file;
  std::vector<Point<double>> polygon;  //!< control points repeated by multiplicity
  std::vector<double> knot_x;          //!< x(t) at the knots 0, 1, ..., n-2
  Point<double> min, max;

  template <class F>
  void vv_fields(F&& f) {
    f("file", file), f("polygon", polygon), f("knot_x", knot_x), f("min", min), f("max", max);
  }
};
}  // namespace function_detail

class Function : public vv::model::registered_file<Function, vv::file_kind::functions, function_detail::curve> {
 public:
  using ControlPoint = bspline::control_point;

  //! No file: f(x) is 0 everywhere and reread() does nothing.
  Function() = default;

  //! Reads `path`; throws vv::error "file:line: problem" if it cannot.
  //! reread() reads it again; on an error the function keeps its values.
  explicit Function(const std::string& path) : registered_file(path) {}

  //! The file's function (model/registered_file.hpp calls it).
  static function_detail::curve read(const std::string& path) { return made(vlab::read_function_file(path)); }

  double operator()(double x) const {
    const std::vector<Point<double>>& polygon = contents().polygon;
    const std::vector<double>& knot_x = contents().knot_x;
    if (polygon.empty()) return 0.0;
    if (x <= polygon.front().x()) return polygon.front().y();
    if (x >= polygon.back().x()) return polygon.back().y();
    // The knot span whose x range holds x, then bisection inside it.
    auto above = std::upper_bound(knot_x.begin(), knot_x.end(), x);
    const std::size_t span =
        std::min<std::size_t>(static_cast<std::size_t>(above - knot_x.begin()) - 1, knot_x.size() - 2);
    double lo = static_cast<double>(span), hi = lo + 1.0;
    for (;;) {
      const double mid = lo + (hi - lo) / 2.0;
      if (mid <= lo || mid >= hi) break;  // lo and hi are neighbouring doubles
      (bspline::clamped(polygon, mid).x() < x ? lo : hi) = mid;
    }
    const Point<double> a = bspline::clamped(polygon, lo), b = bspline::clamped(polygon, hi);
    return (x - a.x() <= b.x() - x ? a : b).y();
  }

  //! The smallest and largest x and y of the control points (z = 0): the
  //! domain is [getMin().x(), getMax().x()] and the curve stays inside the box.
  const Point<double>& getMin() const { return contents().min; }
  const Point<double>& getMax() const { return contents().max; }

  const std::vector<ControlPoint>& points() const { return contents().file.points; }
  const std::string& name() const { return contents().file.name; }
  unsigned samples() const { return contents().file.samples; }
  bool flip() const { return contents().file.flip; }
  //! Whether the file was in the original format (`range:`) or `fver 1 1`.
  vlab::function_file::format version() const { return contents().file.version; }

  //! Editing, for a function editor; write() saves the result.
  void setPoints(std::vector<ControlPoint> points) {
    vlab::function_points_problem bad = vlab::check_function_points(points);
    if (!bad.problem.empty())
      throw vv::error(path(), 0, "control point " + std::to_string(bad.point + 1) + ": " + bad.problem);
    vlab::function_file f = contents().file;
    f.points = std::move(points);
    contents() = made(std::move(f));
  }
  void setName(const std::string& name) {
    if (name.find_first_of("\r\n") != std::string::npos)
      throw vv::error(path(), 0, "a function's name is one line");
    contents().file.name = std::string(vlab::trim(name));
  }
  //! vv 1.1's name. The value is only kept and written: f(x) is exact.
  void setSamples(std::size_t n) {
    if (n < 1 || n > 1000000000u) throw vv::error(path(), 0, "samples must be from 1 to 1000000000");
    contents().file.samples = static_cast<unsigned>(n);
  }
  void setFlip(bool on) { contents().file.flip = on; }

  //! Writes the function in the `fver 1 1` format (to this object's file
  //! without an argument); reading it back gives the same function.
  void write(const std::string& to) const {
    if (contents().file.points.empty()) throw vv::error(to, 0, "cannot write a function without control points");
    vlab::write_bytes(to, vlab::function_file_text(contents().file));
  }
  void write() const { write(path()); }

 private:
  // The spline of a complete, checked file; nothing before this can fail halfway.
  static function_detail::curve made(vlab::function_file f) {
    function_detail::curve c;
    c.polygon = bspline::expand(f.points);
    for (double u = 0; u <= bspline::clamped_end(c.polygon); u += 1.0)
      c.knot_x.push_back(bspline::clamped(c.polygon, u).x());
    Point<double> lo = c.polygon.front(), hi = c.polygon.front();
    for (const Point<double>& p : c.polygon)
      for (std::size_t i = 0; i < 2; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
    c.file = std::move(f);
    c.min = lo, c.max = hi;
    return c;
  }
};

}  // namespace util
