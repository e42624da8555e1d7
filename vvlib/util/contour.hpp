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

#include <model/registered_file.hpp>

#include "bspline.hpp"
#include "contour_file.hpp"
#include "point.hpp"

namespace util {

namespace contour_detail {
//! A contour's contents: the file and the spline's polygon.
struct curve {
  vlab::contour_file file;
  std::vector<Point<double>> polygon;  //!< the spline's polygon (closed: extended)
  Point<double> min, max;

  template <class F>
  void vv_fields(F&& f) {
    f("file", file), f("polygon", polygon), f("min", min), f("max", max);
  }
};
}  // namespace contour_detail

class Contour : public vv::model::registered_file<Contour, vv::file_kind::contours, contour_detail::curve> {
 public:
  using ControlPoint = bspline::control_point;

  //! No file: c(t) is the origin and reread() does nothing.
  Contour() = default;

  //! Reads `path`; throws vv::error "file:line: problem" if it cannot.
  //! reread() reads it again; on an error the contour keeps its values.
  explicit Contour(const std::string& path) : registered_file(path) {}

  //! The file's contour (model/registered_file.hpp calls it).
  static contour_detail::curve read(const std::string& path) { return made(vlab::read_contour_file(path)); }

  Point<double> operator()(double t) const {
    const std::vector<Point<double>>& polygon = contents().polygon;
    if (polygon.empty()) return Point<double>();
    if (contents().file.endpoint_interpolating) return bspline::clamped(polygon, std::clamp(t, 0.0, 1.0) * bspline::clamped_end(polygon));
    return bspline::uniform(polygon, t);
  }

  //! The corners of the box around the control points; the curve lies
  //! inside it (vv 1.1's meaning, with z as well).
  const Point<double>& getMin() const { return contents().min; }
  const Point<double>& getMax() const { return contents().max; }

  const std::vector<ControlPoint>& points() const { return contents().file.points; }
  bool closed() const { return contents().file.closed; }
  bool endpointInterpolating() const { return contents().file.endpoint_interpolating; }
  const std::string& name() const { return contents().file.name; }
  unsigned samples() const { return contents().file.samples; }
  vlab::contour_file::format version() const { return contents().file.version; }

 private:
  // The polygon of a complete, checked file.
  static contour_detail::curve made(vlab::contour_file c) {
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
    contour_detail::curve out;
    out.file = std::move(c);
    out.polygon = std::move(polygon);
    out.min = lo, out.max = hi;
    return out;
  }
};

}  // namespace util
