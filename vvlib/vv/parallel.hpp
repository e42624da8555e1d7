// Parallel loops over a mesh (LANGUAGE.md section 6.1):
//
//   parallel forall v in M { ... }   vv::parallel_for_each(M, [&](vertex v) { ... });
//
// The iterations run at once on the context's threads (`ctx.threads`, 0:
// the machine's cores; the interpreter's --threads), with OpenMP. The body
// may read anything, and may write only its locals and the properties and
// own half-edge records of its vertex. Then the result does not depend on
// the number of threads.
//
// Checked in every build, as errors naming the line of the offending
// operation and the loop's: editing a neighbourhood, setting a flag,
// creating a vertex, changing a mesh (add, remove, merge, clear,
// assignment, synchronise, reading a file into it), `(a|b)` (it writes b's
// record), drawing the context's random numbers. In strict mode
// (`ctx.strict_parallel`, the interpreter's --strict) the iterations run
// in order, and one that changed the properties, neighbourhood or records
// of a vertex other than its own, through `v$x`, `v->x` or `(a^b)`, is an
// error naming the line where that vertex was first used. Not checked:
// writing a global, or through a reference or pointer taken outside the
// loop; reading a property that another iteration writes (its own vertex's
// current state) is allowed and gives a result that depends on timing: read
// the old state of others.
//
// A parallel loop inside another one runs its iterations in order. Errors:
// the one of the first failing iteration in the mesh's order, whichever
// thread met it.
#pragma once

#include "detail/nb_access.hpp"
#include "detail/parallel_run.hpp"
#include "mesh.hpp"

namespace vv {

//! fn(v) for every member v of m, on the context's threads.
//! \throw what the first failing iteration (in m's order) threw.
template <class Tr, class Fn>
void parallel_for_each(const mesh<Tr>& m, Fn&& fn, where w = where::here()) {
  context<Tr>* ctx = m.ctx();
  if (!ctx) return;  // no context: no member
  const unsigned team = detail::team_size(*ctx, m.slots().size());
  // Each iteration's vertex is a borrowed handle (vertex::borrowed), passed
  // on as one: a body taking `vertex v` by value counts nothing.
  detail::for_each_member(*ctx, m.slots(), team, w,
                          [&](const vertex<Tr>& v, unsigned) { fn(vertex<Tr>::borrowed(v.ctx(), v.slot())); });
}
//! The translated form of `parallel forall v in M`: the loop's line first.
template <class Tr, class Fn>
void parallel_for_each(where w, const mesh<Tr>& m, Fn&& fn) {
  parallel_for_each(m, std::forward<Fn>(fn), w);
}

namespace detail {
template <class T>
constexpr bool always_false = false;
}
//! `parallel forall x in v` over a vertex: refused when compiled (vvc
//! refuses the operands it can see are vertices).
template <class V, class Fn, detail::if_vertex_like<V> = 0>
void parallel_for_each(where, const V&, Fn&&) {
  static_assert(detail::always_false<V>,
                "only a loop over a mesh can be parallel: this is a vertex (drop 'parallel' to visit its neighbours)");
}

//! The threads a loop over m would use now (1 inside another parallel
//! loop, in strict mode, for a small mesh, or without OpenMP).
template <class Tr>
unsigned parallel_threads(const mesh<Tr>& m) {
  return m.ctx() ? detail::team_size(*m.ctx(), m.slots().size()) : 1u;
}

}  // namespace vv
