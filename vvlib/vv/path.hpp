// Path expressions (LANGUAGE.md section 4.1): walk a pair of vertices with
// next / prev / swap over current or old neighbourhoods.
//
//   @(a, b) swap next @      vv::path(a, b).swap().next().second()
//   `@(a, b) ... @           vv::old_path(a, b)...
//   @&(a, b) ... @           vv::path_into(a, b)....store()
//
// A walk is a view for use within one expression, as a translated program
// uses it (like `` `v ``): it holds the pair as slots without counting them,
// so a step costs a neighbour search and no reference counts. Nothing in a
// path expression creates a vertex, so the collector cannot run while the
// walk's slots are in use; first() and second() hand out counted handles,
// and store() writes counted handles into the two variables. Do not keep a walk beyond the handles it started from.
#pragma once

#include "detail/inline.hpp"

#include <cstdint>
#include <utility>

#include "queries.hpp"

namespace vv {

template <class Tr>
class path_walk {
 public:
  VV_INLINE path_walk(const vertex<Tr>& a, const vertex<Tr>& b, bool on_old, where w) noexcept
      : a_{a.ctx(), a.slot()}, b_{b.ctx(), b.slot()}, old_(on_old), w_(w) {}

  //! (a, b) -> (a, nextto b in a)
  VV_INLINE path_walk& next() {
    step(true);
    return *this;
  }
  //! (a, b) -> (a, prevto b in a)
  VV_INLINE path_walk& prev() {
    step(false);
    return *this;
  }
  //! (a, b) -> (b, a)
  VV_INLINE path_walk& swap() noexcept {
    std::swap(a_, b_);
    return *this;
  }

  vertex<Tr> first() const noexcept { return vertex<Tr>::from_slot(a_.ctx, a_.id); }
  //! The value of the path: the second vertex of the final pair.
  vertex<Tr> second() const noexcept { return vertex<Tr>::from_slot(b_.ctx, b_.id); }

 protected:
  struct end {
    context<Tr>* ctx;
    std::uint32_t id;  // 0: the null vertex
  };

  // b becomes the neighbour after (or before) b in a's current or old
  // neighbourhood, or null when b is not a neighbour of a.
  VV_INLINE void step(bool forward) {
    context<Tr>* ctx = a_.ctx;
    if (!a_.id || (old_ && ctx->strict_old_state)) return checked_step(forward);
    const auto& nb = old_ ? ctx->old_nb(a_.id) : ctx->nb(a_.id);
    // A null b, or one of another context, is no neighbour of a.
    const std::int32_t pos = detail::find(nb, b_.ctx == ctx ? b_.id : 0u);
    if (pos < 0) {
      b_ = end{nullptr, 0};
      return;
    }
    const std::uint32_t k = detail::cyclic_step(static_cast<std::uint32_t>(pos), nb.size(), 1, forward);
    b_ = end{ctx, detail::entry_id(nb[k])};
  }

  // The step through the queries themselves, for their errors (a null a;
  // an old state never synchronised, in strict mode).
  [[gnu::noinline]] void checked_step(bool forward) {
    const vertex<Tr> a = first(), b = second();
    vertex<Tr> r = old_ ? (forward ? next_to(b, old(a, w_), w_) : prev_to(b, old(a, w_), w_))
                        : (forward ? next_to(b, a, w_) : prev_to(b, a, w_));
    b_ = end{r.ctx(), r.slot()};
  }

  end a_, b_;
  bool old_;
  where w_;
};

//! A walk that assigns the final pair back to the two variables it started
//! from (`@&(a, b) ... @`).
template <class Tr>
class path_into_walk : public path_walk<Tr> {
 public:
  VV_INLINE path_into_walk(vertex<Tr>& a, vertex<Tr>& b, bool on_old, where w) noexcept
      : path_walk<Tr>(a, b, on_old, w), a_ref_(a), b_ref_(b) {}
  VV_INLINE path_into_walk& next() { return path_walk<Tr>::next(), *this; }
  VV_INLINE path_into_walk& prev() { return path_walk<Tr>::prev(), *this; }
  VV_INLINE path_into_walk& swap() noexcept { return path_walk<Tr>::swap(), *this; }
  //! Writes the pair back and gives the second vertex: the variable it
  //! was written to, so a walk whose value is unused makes no handle.
  VV_INLINE const vertex<Tr>& store() {
    // The walk's slots are uncounted, and nothing here can run the
    // collector, so each variable may let go of what it held first.
    a_ref_.assign_slot(this->a_.ctx, this->a_.id);
    b_ref_.assign_slot(this->b_.ctx, this->b_.id);
    return b_ref_;
  }

 private:
  vertex<Tr>& a_ref_;
  vertex<Tr>& b_ref_;
};

template <class Tr>
VV_INLINE path_walk<Tr> path(const vertex<Tr>& a, const vertex<Tr>& b, where w = where::here()) {
  return path_walk<Tr>(a, b, false, w);
}
template <class Tr>
VV_INLINE path_walk<Tr> old_path(const vertex<Tr>& a, const vertex<Tr>& b, where w = where::here()) {
  return path_walk<Tr>(a, b, true, w);
}
template <class Tr>
VV_INLINE path_into_walk<Tr> path_into(vertex<Tr>& a, vertex<Tr>& b, where w = where::here()) {
  return path_into_walk<Tr>(a, b, false, w);
}
template <class Tr>
VV_INLINE path_into_walk<Tr> old_path_into(vertex<Tr>& a, vertex<Tr>& b, where w = where::here()) {
  return path_into_walk<Tr>(a, b, true, w);
}

}  // namespace vv
