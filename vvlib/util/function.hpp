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
#include <vv/file_objects.hpp>

#include "bspline.hpp"
#include "function_file.hpp"
#include "point.hpp"

namespace util {

class Function : public vv::registered_file<vv::file_kind::functions> {
 public:
  using ControlPoint = bspline::control_point;

  //! No file: f(x) is 0 everywhere and reread() does nothing.
  Function() = default;

  //! Reads `path`; throws vv::error "file:line: problem" if it cannot.
  explicit Function(std::string path) : registered_file(std::move(path)) { reread(); }

  // Copies register too; a move is a copy (see registered_file).
  Function(const Function&) = default;
  Function& operator=(const Function&) = default;

  //! Reads the file again. On an error the function keeps its values and
  //! the error (vv::error, with the file and line) is thrown.
  void reread() override {
    if (path().empty()) return;
    adopt(vlab::read_function_file(path()));
  }

  double operator()(double x) const {
    if (polygon_.empty()) return 0.0;
    if (x <= polygon_.front().x()) return polygon_.front().y();
    if (x >= polygon_.back().x()) return polygon_.back().y();
    // The knot span whose x range holds x, then bisection inside it.
    auto above = std::upper_bound(knot_x_.begin(), knot_x_.end(), x);
    const std::size_t span =
        std::min<std::size_t>(static_cast<std::size_t>(above - knot_x_.begin()) - 1, knot_x_.size() - 2);
    double lo = static_cast<double>(span), hi = lo + 1.0;
    for (;;) {
      const double mid = lo + (hi - lo) / 2.0;
      if (mid <= lo || mid >= hi) break;  // lo and hi are neighbouring doubles
      (bspline::clamped(polygon_, mid).x() < x ? lo : hi) = mid;
    }
    const Point<double> a = bspline::clamped(polygon_, lo), b = bspline::clamped(polygon_, hi);
    return (x - a.x() <= b.x() - x ? a : b).y();
  }

  //! The smallest and largest x and y of the control points (z = 0): the
  //! domain is [getMin().x(), getMax().x()] and the curve stays inside the box.
  const Point<double>& getMin() const { return min_; }
  const Point<double>& getMax() const { return max_; }

  const std::vector<ControlPoint>& points() const { return file_.points; }
  const std::string& name() const { return file_.name; }
  unsigned samples() const { return file_.samples; }
  bool flip() const { return file_.flip; }
  //! Whether the file was in the original format (`range:`) or `fver 1 1`.
  vlab::function_file::format version() const { return file_.version; }

  //! Editing, for a function editor; write() saves the result.
  void setPoints(std::vector<ControlPoint> points) {
    vlab::function_points_problem bad = vlab::check_function_points(points);
    if (!bad.problem.empty())
      throw vv::error(path(), 0, "control point " + std::to_string(bad.point + 1) + ": " + bad.problem);
    vlab::function_file f = file_;
    f.points = std::move(points);
    adopt(std::move(f));
  }
  void setName(const std::string& name) {
    if (name.find_first_of("\r\n") != std::string::npos)
      throw vv::error(path(), 0, "a function's name is one line");
    file_.name = std::string(vlab::trim(name));
  }
  //! vv 1.1's name. The value is only kept and written: f(x) is exact.
  void setSamples(std::size_t n) {
    if (n < 1 || n > 1000000000u) throw vv::error(path(), 0, "samples must be from 1 to 1000000000");
    file_.samples = static_cast<unsigned>(n);
  }
  void setFlip(bool on) { file_.flip = on; }

  //! Writes the function in the `fver 1 1` format (to this object's file
  //! without an argument); reading it back gives the same function.
  void write(const std::string& to) const {
    if (file_.points.empty()) throw vv::error(to, 0, "cannot write a function without control points");
    vlab::write_bytes(to, vlab::function_file_text(file_));
  }
  void write() const { write(path()); }

 private:
  // Takes a complete, checked file; nothing before this can fail halfway.
  void adopt(vlab::function_file f) {
    std::vector<Point<double>> polygon = bspline::expand(f.points);
    std::vector<double> knot_x;
    for (double u = 0; u <= bspline::clamped_end(polygon); u += 1.0)
      knot_x.push_back(bspline::clamped(polygon, u).x());
    Point<double> lo = polygon.front(), hi = polygon.front();
    for (const Point<double>& p : polygon)
      for (std::size_t i = 0; i < 2; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
    file_ = std::move(f);
    polygon_ = std::move(polygon);
    knot_x_ = std::move(knot_x);
    min_ = lo, max_ = hi;
  }

  vlab::function_file file_;
  std::vector<Point<double>> polygon_;  //!< control points repeated by multiplicity
  std::vector<double> knot_x_;          //!< x(t) at the knots 0, 1, ..., n-2
  Point<double> min_, max_;
};

}  // namespace util
