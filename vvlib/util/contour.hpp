// util::Contour: a VLAB contour file (contour_file.hpp) as a curve
// c(t), t in [0, 1], re-read on the host's "reread files".
//
//   util::Contour leaf("leaf.con");
//   util::Point<double> p = leaf(0.25);
//
// The curve is the one VLAB's contour editor draws (bspline.hpp): the
// uniform cubic B-spline over the control points (a closed contour repeats
// its first three points, so c(0) = c(1)), or for endpoint-interpolating
// contours (cver 1 2/1 3 type "?e") the clamped one, which starts at the
// first point and ends at the last (a closed one at the first again). t is
// shared equally among the spline's segments and clamped to [0, 1].
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <vv/file_objects.hpp>

#include "bspline.hpp"
#include "contour_file.hpp"
#include "point.hpp"

namespace util {

class Contour : public vv::registered_file<vv::file_kind::contours> {
 public:
  using ControlPoint = bspline::control_point;

  //! No file: c(t) is the origin and reread() does nothing.
  Contour() = default;

  //! Reads `path`; throws vv::error "file:line: problem" if it cannot.
  explicit Contour(std::string path) : registered_file(std::move(path)) { reread(); }

  // Copies register too; a move is a copy (see registered_file).
  Contour(const Contour&) = default;
  Contour& operator=(const Contour&) = default;

  //! Reads the file again. On an error the contour keeps its values and the
  //! error (vv::error, with the file and line) is thrown.
  void reread() override {
    if (path().empty()) return;
    adopt(vlab::read_contour_file(path()));
  }

  Point<double> operator()(double t) const {
    if (polygon_.empty()) return Point<double>();
    if (file_.endpoint_interpolating) return bspline::clamped(polygon_, std::clamp(t, 0.0, 1.0) * bspline::clamped_end(polygon_));
    return bspline::uniform(polygon_, t);
  }

  //! The corners of the box around the control points; the curve lies
  //! inside it (vv 1.1's meaning, with z as well).
  const Point<double>& getMin() const { return min_; }
  const Point<double>& getMax() const { return max_; }

  const std::vector<ControlPoint>& points() const { return file_.points; }
  bool closed() const { return file_.closed; }
  bool endpointInterpolating() const { return file_.endpoint_interpolating; }
  const std::string& name() const { return file_.name; }
  unsigned samples() const { return file_.samples; }
  vlab::contour_file::format version() const { return file_.version; }

 private:
  // Takes a complete, checked file.
  void adopt(vlab::contour_file c) {
    std::vector<Point<double>> polygon = bspline::expand(c.points);
    Point<double> lo = polygon.front(), hi = polygon.front();
    for (const Point<double>& p : polygon)
      for (std::size_t i = 0; i < 3; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
    if (c.closed && c.endpoint_interpolating) {
      // Back to the first point, as often as it stands at the start.
      polygon.insert(polygon.end(), c.points.front().multiplicity, c.points.front().pos);
    } else if (c.closed) {
      // The first three again: the last segments join the first smoothly.
      for (std::size_t i = 0; i < 3; ++i) polygon.push_back(polygon[i]);
    }
    file_ = std::move(c);
    polygon_ = std::move(polygon);
    min_ = lo, max_ = hi;
  }

  vlab::contour_file file_;
  std::vector<Point<double>> polygon_;  //!< the spline's polygon (closed: extended)
  Point<double> min_, max_;
};

}  // namespace util
