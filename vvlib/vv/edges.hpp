// Half-edge records (LANGUAGE.md section 4.2): `(a^b)`, `(a|b)` and their
// read-only old-state forms.
#pragma once

#include <cstdint>

#include "detail/nb_access.hpp"

namespace vv {

namespace detail {

template <class Tr, class NB>
auto& record_at(context<Tr>* ctx, NB& nb, const vertex<Tr>& a, const vertex<Tr>& b,
                const char* op, const where& w) {
  std::int32_t pos = find(nb, slot_in(b, ctx));
  if (pos < 0 || !b)
    raise(w, op, [&] {
      return "there is no half-edge from " + name_of(a) + " to " + name_of(b) + ": " + name_of(b) +
             " is not a neighbour";
    });
  using entry_traits = typename context<Tr>::entry_traits;
  return entry_traits::rec(nb[static_cast<std::uint32_t>(pos)], ctx->empty_record());
}

//! Lives until the end of the full expression that used `(a|b)`, then
//! copies the record a->b onto b->a when a is a neighbour of b.
template <class Tr>
class symmetric_sync {
 public:
  symmetric_sync() noexcept = default;
  symmetric_sync(const symmetric_sync&) = delete;
  symmetric_sync& operator=(const symmetric_sync&) = delete;
  ~symmetric_sync() {
    if (!a_) return;
    context<Tr>* ctx = a_.ctx();
    auto& from_nb = ctx->nb(a_.slot());
    auto& to_nb = ctx->nb(b_.slot());
    std::int32_t from = find(from_nb, b_.slot());
    std::int32_t to = find(to_nb, a_.slot());
    if (from < 0 || to < 0) return;
    using entry_traits = typename context<Tr>::entry_traits;
    entry_traits::rec(to_nb[static_cast<std::uint32_t>(to)], ctx->empty_record()) =
        entry_traits::rec(from_nb[static_cast<std::uint32_t>(from)], ctx->empty_record());
  }
  void arm(const vertex<Tr>& a, const vertex<Tr>& b, const where& w) {
    // It writes b's record: another vertex's, which a parallel loop's
    // iteration must leave alone.
    if (a.ctx()->parallel_loop()) a.ctx()->refuse_in_parallel(w, "|", "write the record of another vertex's half-edge");
    a_ = a;
    b_ = b;
  }

 private:
  vertex<Tr> a_, b_;
};

}  // namespace detail

//! `(a^b)`: the record of the half-edge a->b (error if b is not in a*).
template <class Tr>
typename Tr::edge_props& edge(const vertex<Tr>& a, const vertex<Tr>& b, where w = where::here()) {
  auto s = detail::view(a, "^", w);
  s.ctx->note_props_use(a.slot(), w);
  auto& nb = a.ctx()->nb(a.slot());
  return detail::record_at(s.ctx, nb, a, b, "^", w);
}

//! `` ((`a)^b) `` and `` ((`a)|b) ``: the synchronised record, read-only.
template <class Tr>
const typename Tr::edge_props& edge(const old_vertex<Tr>& a, const vertex<Tr>& b,
                                    where w = where::here()) {
  auto& nb = a.ctx()->old_nb(a.slot());
  return detail::record_at(a.ctx(), nb, a.current(), b, "^", w);
}

//! `(a|b)`: the record a->b; at the end of the full expression that uses
//! it, b->a is set equal to it (when a is in b*), so both stay the same.
template <class Tr>
typename Tr::edge_props& sym_edge(const vertex<Tr>& a, const vertex<Tr>& b, where w = where::here(),
                                  detail::symmetric_sync<Tr>&& sync = detail::symmetric_sync<Tr>()) {
  auto& rec = edge(a, b, w);
  sync.arm(a, b, w);
  return rec;
}
template <class Tr>
const typename Tr::edge_props& sym_edge(const old_vertex<Tr>& a, const vertex<Tr>& b,
                                        where w = where::here()) {
  return edge(a, b, w);
}

}  // namespace vv
