// Geometry of planar cells: a cell is a face of a planar vertex-vertex
// mesh in the xy plane, given by its wall vertices in counter-clockwise
// order (the face orbit on the left of one of its half-edges).
#pragma once

#include <cstddef>
#include <type_traits>
#include <vector>

#include <vv/error.hpp>
#include <vv/queries.hpp>

namespace algorithms {

//! The corners of the face on the left of the half-edge a->b, starting at
//! a: the orbit (a, b) -> (b, prevto a in b) (current state). Throws
//! vv::error if the orbit does not close.
template <class V>
std::vector<V> cell_corners(const V& a, const V& b, vv::where w = vv::where::here()) {
  std::vector<V> corners;
  V x = a, y = b;
  do {
    corners.push_back(x);
    V z = vv::prev_to(x, y, w);
    if (!z) throw vv::error(w, "cell_corners", "the face after " + vv::name_of(a) + "-" + vv::name_of(b) + " is not closed");
    x = y;
    y = z;
  } while (!(x == a && y == b));
  return corners;
}

//! Signed area of a polygon projected on the xy plane (shoelace formula):
//! positive when its corners turn counter-clockwise.
template <class P>
double polygon_area(const std::vector<P>& corners) {
  double twice = 0;
  for (std::size_t i = 0, k = corners.size(); i < k; ++i) {
    const P& a = corners[i];
    const P& b = corners[(i + 1) % k];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return twice / 2;
}

//! Centroid of the area of a polygon in the xy plane (z = 0). A polygon of
//! no area gives the average of its corners.
template <class P>
P polygon_centroid(const std::vector<P>& corners) {
  double twice_area = 0, cx = 0, cy = 0;
  for (std::size_t i = 0, k = corners.size(); i < k; ++i) {
    const P& a = corners[i];
    const P& b = corners[(i + 1) % k];
    const double cross = a.x() * b.y() - a.y() * b.x();
    twice_area += cross;
    cx += (a.x() + b.x()) * cross;
    cy += (a.y() + b.y()) * cross;
  }
  if (twice_area == 0) {
    P sum;
    for (const P& c : corners) sum += c;
    return corners.empty() ? sum : sum / static_cast<double>(corners.size());
  }
  return P(cx / (3 * twice_area), cy / (3 * twice_area), 0.0);
}

//! True when every corner of the polygon turns left (counter-clockwise)
//! or goes straight on; a polygon of fewer than 3 corners is not convex.
template <class P>
bool polygon_is_convex(const std::vector<P>& corners) {
  const std::size_t k = corners.size();
  if (k < 3) return false;
  for (std::size_t i = 0; i < k; ++i) {
    const P& a = corners[i];
    const P& b = corners[(i + 1) % k];
    const P& c = corners[(i + 2) % k];
    if ((b.x() - a.x()) * (c.y() - b.y()) - (b.y() - a.y()) * (c.x() - b.x()) < 0) return false;
  }
  return true;
}

//! The positions of a cell's wall vertices (current state).
template <class V>
auto positions_of(const std::vector<V>& walls) {
  std::vector<std::decay_t<decltype(walls[0]->pos)>> points;
  points.reserve(walls.size());
  for (const V& v : walls) points.push_back(v->pos);
  return points;
}

//! Area of the cell whose wall vertices are `walls`, counter-clockwise.
template <class V>
double cell_area(const std::vector<V>& walls) {
  return polygon_area(positions_of(walls));
}

//! Centroid of the cell whose wall vertices are `walls`.
template <class V>
auto cell_centroid(const std::vector<V>& walls) {
  return polygon_centroid(positions_of(walls));
}

}  // namespace algorithms
