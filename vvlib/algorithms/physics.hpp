// Mass-spring physics on vertex-vertex meshes: springs along the edges with
// rest lengths, drag, pressure, explicit Euler steps and a settled test.
//
// Vertices need two properties of one point type (util::Point<double>):
// `pos` and `vel`. A step reads only the old state saved by its own
// synchronise, so its result does not depend on the order of the mesh, and
// it runs on the context's threads (vv/parallel.hpp) with the same result
// for any number of them. The callables it is given (rest lengths, forces)
// run on those threads too: like the body of a `parallel forall`, they
// must only read, and not create vertices or edit.
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
#include <cstdint>
#include <type_traits>
#include <utility>

#include <vv/edges.hpp>
#include <vv/iteration.hpp>
#include <vv/mesh.hpp>
#include <vv/parallel.hpp>
#include <vv/queries.hpp>
#include <vector>

namespace algorithms {

//! The point type of a vertex type's `pos`.
template <class V>
using point_of = std::decay_t<decltype(std::declval<typename V::traits_type::vertex_props&>().pos)>;

//! Rest length from the old half-edge record v->n: its field `rest`.
//! (MassSpring hands it the record directly; the form with two vertices
//! finds it.)
struct RestFromRecords {
  template <class V>
  double operator()(const V& v, const V& n) const {
    return vv::edge(vv::old(v), n).rest;
  }
  template <class Record>
  double from_record(const Record& r) const {
    return r.rest;
  }
};

//! The same rest length for every spring.
struct UniformRest {
  double length;
  //! The fields, for a model's checkpoint (model/state_values.hpp).
  template <class F>
  void vv_fields(F&& f) {
    f("length", length);
  }
  template <class V>
  double operator()(const V&, const V&) const {
    return length;
  }
  template <class Record>
  double from_record(const Record&) const {
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
// A rest-length callable that reads the old record itself (from_record)
// spares the search for n in v's old neighbourhood.
template <class Rest, class Record, class = void>
struct reads_records : std::false_type {};
template <class Rest, class Record>
struct reads_records<Rest, Record,
                     std::void_t<decltype(std::declval<const Rest&>().from_record(std::declval<const Record&>()))>>
    : std::true_type {};

// The old neighbourhood of a vertex read in place: neighbour slots, their
// old positions and the old records, without handles or a snapshot. For
// the inner loops of a step, which change nothing while they read.
template <class Tr>
class old_fan {
 public:
  using context_type = vv::context<Tr>;
  using entry_traits = typename context_type::entry_traits;
  explicit old_fan(const vv::vertex<Tr>& v) : ctx_(v.ctx()), nb_(&ctx_->old_nb(v.slot())) {}
  explicit old_fan(const vv::old_vertex<Tr>& v) : ctx_(v.ctx()), nb_(&ctx_->old_nb(v.slot())) {}
  std::uint32_t size() const noexcept { return nb_->size(); }
  std::uint32_t slot(std::uint32_t i) const noexcept { return entry_traits::id((*nb_)[i]); }
  const auto& pos(std::uint32_t i) const noexcept { return ctx_->old_props(slot(i)).pos; }
  const auto& record(std::uint32_t i) const noexcept {
    return entry_traits::rec((*nb_)[i], ctx_->empty_record());
  }
  vv::vertex<Tr> neighbour(std::uint32_t i) const noexcept { return vv::vertex<Tr>::from_slot(ctx_, slot(i)); }

 private:
  context_type* ctx_;
  const typename context_type::nb_type* nb_;
};
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
  auto add_arm = [&](const P& arm) {
    if (first) first_arm = arm, first = false;
    else sum += previous_arm.cross(arm);
    previous_arm = arm;
  };
  if constexpr (std::is_same_v<VL, vv::old_vertex<typename VL::traits_type>>) {
    const detail::old_fan<typename VL::traits_type> fan(v);
    for (std::uint32_t i = 0; i < fan.size(); ++i) add_arm(fan.pos(i) - centre);
  } else {
    for (auto n : vv::each(v)) add_arm(n->pos - centre);
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

  //! The fields, for a model's checkpoint (model/state_values.hpp).
  template <class F>
  void vv_fields(F&& f) {
    f("stiffness", stiffness), f("drag", drag), f("mass", mass), f("dt", dt);
  }

  //! The springs' force on v, in the old state.
  template <class Rest>
  point spring_force(const V& v, Rest rest) const {
    using Tr = typename V::traits_type;
    using record = typename Tr::edge_props;
    const point centre = vv::old(v)->pos;
    point force;
    const detail::old_fan<Tr> fan(v);
    for (std::uint32_t i = 0; i < fan.size(); ++i) {
      const point d = fan.pos(i) - centre;
      const double length = d.length();
      if (!(length > 0)) continue;
      double r;
      if constexpr (detail::reads_records<Rest, record>::value) r = rest.from_record(fan.record(i));
      else r = rest(v, fan.neighbour(i));
      force += (stiffness * (length - r) / length) * d;
    }
    return force;
  }

  //! v's acceleration in the old state.
  template <class Rest, class Force = NoForce>
  point acceleration(const V& v, Rest rest, Force force = Force()) const {
    return (spring_force(v, rest) + force(v) - drag * vv::old(v)->vel) / mass;
  }

  //! One explicit Euler step of every vertex of the mesh (it synchronises
  //! the mesh first), on the context's threads. Returns the largest speed
  //! after the step.
  template <class Mesh, class Rest, class Force = NoForce>
  double step(Mesh& mesh, Rest rest, Force force = Force(), vv::where w = vv::where::here()) const {
    vv::synchronise(mesh, w);
    auto* ctx = mesh.ctx();
    if (!ctx) return 0;
    // The largest speed of each thread's vertices (a maximum does not
    // depend on how the vertices were shared out).
    struct alignas(64) fastest_of_thread {
      double speed = 0;
    };
    std::vector<fastest_of_thread> fastest(vv::detail::team_size(*ctx, mesh.slots().size()));
    vv::detail::for_each_member(*ctx, mesh.slots(), static_cast<unsigned>(fastest.size()), w,
                                [&](V v, unsigned thread) {
                                  const point a = acceleration(v, rest, force);
                                  v->pos = vv::old(v)->pos + dt * vv::old(v)->vel;
                                  v->vel = vv::old(v)->vel + dt * a;
                                  fastest[thread].speed = std::max(fastest[thread].speed, v->vel.length());
                                });
    double result = 0;
    for (const fastest_of_thread& f : fastest) result = std::max(result, f.speed);
    return result;
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
