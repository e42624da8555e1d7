// Mass-spring physics on vertex-vertex meshes: springs along the edges with
// rest lengths, drag, pressure, explicit Euler steps and a settled test.
//
// Vertices need two properties of one point type (util::Point<double>):
// `pos` and `vel`. A step reads only the old state saved by its own
// synchronise, so its result does not depend on the order of the mesh.
//
// Rest lengths are the program's choice, passed as a callable
// `rest(v, n)` giving the rest length of the spring v-n (read it from the
// old state). Two are provided: RestFromRecords reads the field `rest` of
// the old half-edge record v->n (declare `edge { double rest; }` and set
// both halves, e.g. `(a|b).rest = L;`); UniformRest gives every spring one
// length. Extra forces (pressure, gravity) are a callable `force(v)` on
// the old state, added to the springs'.
#pragma once

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

#include <vv/edges.hpp>
#include <vv/iteration.hpp>
#include <vv/mesh.hpp>
#include <vv/queries.hpp>

namespace algorithms {

//! The point type of a vertex type's `pos`.
template <class V>
using point_of = std::decay_t<decltype(std::declval<typename V::traits_type::vertex_props&>().pos)>;

//! Rest length from the old half-edge record v->n: its field `rest`.
struct RestFromRecords {
  template <class V>
  double operator()(const V& v, const V& n) const {
    return vv::edge(vv::old(v), n).rest;
  }
};

//! The same rest length for every spring.
struct UniformRest {
  double length;
  template <class V>
  double operator()(const V&, const V&) const {
    return length;
  }
};

//! No force besides springs and drag.
struct NoForce {
  template <class V>
  point_of<V> operator()(const V&) const {
    return point_of<V>();
  }
};

namespace detail {
// The position of neighbour n in the state v is viewed in.
template <class Tr>
const auto& position_in(const vv::vertex<Tr>&, const vv::vertex<Tr>& n) {
  return n->pos;
}
template <class Tr>
const auto& position_in(const vv::old_vertex<Tr>&, const vv::vertex<Tr>& n) {
  return vv::old(n)->pos;
}
}  // namespace detail

//! Σ (n_i - v) x (n_i+1 - v) over consecutive neighbours of v, the fan
//! closed from the last neighbour to the first: twice the fan's area
//! vector. v is a vertex (current state) or `vv::old(v)` (old state). On a
//! closed triangle mesh it is 6 times the gradient of the enclosed volume
//! with respect to v.
template <class VL>
auto fan_cross_sum(const VL& v) {
  using P = std::decay_t<decltype(v->pos)>;
  const P centre = v->pos;
  P sum, first_arm, previous_arm;
  bool first = true;
  for (auto n : vv::each(v)) {
    const P arm = detail::position_in(v, n) - centre;
    if (first) first_arm = arm, first = false;
    else sum += previous_arm.cross(arm);
    previous_arm = arm;
  }
  if (!first) sum += previous_arm.cross(first_arm);
  return sum;
}

//! The unit normal of the fan around v (current state, or `vv::old(v)`).
//! With counter-clockwise neighbourhoods it points outwards. Zero when the
//! fan has no area (fewer than two neighbours, or flat and folded).
template <class VL>
auto vertex_normal(const VL& v) {
  auto n = fan_cross_sum(v);
  const double length = n.length();
  if (length > 0) n /= length;
  return n;
}

//! Pressure on a closed surface, at v (usually `vv::old(v)`): pressure
//! times the gradient of the enclosed volume, a force along the normal
//! whose size is pressure times a third of the fan's area.
template <class VL>
auto surface_pressure(const VL& v, double pressure) {
  return (pressure / 6.0) * fan_cross_sum(v);
}

//! Pressure of planar cells on their walls, at vertex v of a planar
//! tissue in the xy plane (old state). `pressure(v, n)` is the pressure in
//! the cell on the left of the half-edge v->n (0 for the outside). Each
//! cell pushes v by pressure times the gradient of its area: p/2 times the
//! outward normal of each of its two walls at v, as long as the wall. Where
//! every cell has the same pressure the pushes across inner walls cancel
//! and what is left acts along the outward normal of the boundary edges.
template <class V, class Pressure>
point_of<V> wall_pressure(const V& v, Pressure pressure) {
  using P = point_of<V>;
  P force;
  V first, previous;
  // The cell on the left of v->n_i has the corner (n_i+1, v, n_i).
  auto push = [&](const V& next, const V& prev) {
    const double p = pressure(v, next);
    if (p == 0) return;
    const P a = vv::old(next)->pos, b = vv::old(prev)->pos;
    force += (p / 2) * P(a.y() - b.y(), b.x() - a.x(), 0.0);
  };
  for (V n : vv::each(vv::old(v))) {
    if (!first) first = n;
    else push(previous, n);
    previous = n;
  }
  if (first && previous != first) push(previous, first);
  return force;
}

//! Springs along the edges, drag, and explicit Euler:
//!   a = (Σ_n k (|d| - rest) d/|d| + force(v) - drag vel) / mass,
//!   d = pos_n - pos_v, all from the old state; then
//!   pos' = pos + dt vel,  vel' = vel + dt a.
template <class V>
class MassSpring {
 public:
  using point = point_of<V>;
  double stiffness = 1;  // k: force per unit of stretch
  double drag = 0;       // force -drag * velocity
  double mass = 1;
  double dt = 0.01;

  //! The springs' force on v, in the old state.
  template <class Rest>
  point spring_force(const V& v, Rest rest) const {
    const point centre = vv::old(v)->pos;
    point force;
    for (V n : vv::each(vv::old(v))) {
      const point d = vv::old(n)->pos - centre;
      const double length = d.length();
      if (length > 0) force += (stiffness * (length - rest(v, n)) / length) * d;
    }
    return force;
  }

  //! v's acceleration in the old state.
  template <class Rest, class Force = NoForce>
  point acceleration(const V& v, Rest rest, Force force = Force()) const {
    return (spring_force(v, rest) + force(v) - drag * vv::old(v)->vel) / mass;
  }

  //! One explicit Euler step of every vertex of the mesh (it synchronises
  //! the mesh first). Returns the largest speed after the step.
  template <class Mesh, class Rest, class Force = NoForce>
  double step(Mesh& mesh, Rest rest, Force force = Force()) const {
    vv::synchronise(mesh);
    double fastest = 0;
    for (V v : vv::each(mesh)) {
      const point a = acceleration(v, rest, force);
      v->pos = vv::old(v)->pos + dt * vv::old(v)->vel;
      v->vel = vv::old(v)->vel + dt * a;
      fastest = std::max(fastest, v->vel.length());
    }
    return fastest;
  }

  //! Steps until settled (the largest speed after a step below
  //! `threshold`), at most max_steps. Returns the steps taken; at least one
  //! is taken, so a mesh at rest but out of balance starts moving.
  template <class Mesh, class Rest, class Force = NoForce>
  unsigned relax(Mesh& mesh, Rest rest, double threshold, unsigned max_steps, Force force = Force()) const {
    unsigned steps = 0;
    while (steps < max_steps) {
      ++steps;
      if (step(mesh, rest, force) < threshold) break;
    }
    return steps;
  }
};

//! The largest speed |vel| over a mesh's vertices (current state).
template <class Mesh>
double max_speed(const Mesh& mesh) {
  double fastest = 0;
  for (auto v : vv::each(mesh)) fastest = std::max(fastest, v->vel.length());
  return fastest;
}

//! Settled: every vertex slower than threshold.
template <class Mesh>
bool settled(const Mesh& mesh, double threshold) {
  return max_speed(mesh) < threshold;
}

}  // namespace algorithms
