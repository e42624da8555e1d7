// Neighbourhood queries and selections (LANGUAGE.md section 4, first
// table). Each works on a current state (`v`) or an old one (`` `v ``); a
// null target is an error, a missing neighbour gives the null vertex.
#pragma once

#include "detail/inline.hpp"

#include <cstddef>
#include <cstdint>

#include "detail/nb_access.hpp"

namespace vv {

//! `valence v`
template <class V, detail::if_vertex_like<V> = 0>
VV_INLINE std::size_t valence(const V& v, where w = where::here()) {
  return detail::view(v, "valence", w).nb->size();
}

//! `is x in v`: x is a neighbour of v.
template <class V, detail::if_vertex_like<V> = 0>
VV_INLINE bool is_in(const vertex<typename V::traits_type>& x, const V& v, where w = where::here()) {
  auto s = detail::view(v, "is ... in", w);
  std::uint32_t id = detail::slot_in(x, s.ctx);
  return id != 0 && detail::find(*s.nb, id) >= 0;
}

//! `any in v`: the first neighbour, or null when there is none.
template <class V, detail::if_vertex_like<V> = 0>
VV_INLINE vertex<typename V::traits_type> any_in(const V& v, where w = where::here()) {
  using vx = vertex<typename V::traits_type>;
  auto s = detail::view(v, "any in", w);
  if (s.nb->empty()) return vx();
  return vx::from_slot(s.ctx, detail::entry_id((*s.nb)[0]));
}

namespace detail {
// The position `count` places after (forward) or before pos in a cyclic
// list of n entries (pos < n). Without a division when count < n, as it
// is for nextto/prevto: a 64-bit division costs tens of cycles, several
// per edge in a subdivision step. The wrap-around is a select, not a
// branch: whether a step wraps depends on the data, and a mispredicted
// branch costs more than the arithmetic.
inline std::uint32_t cyclic_step(std::uint32_t pos, std::uint32_t n, unsigned long count,
                                 bool forward) noexcept {
  const std::uint32_t k =
      __builtin_expect(count < n, 1) ? static_cast<std::uint32_t>(count) : static_cast<std::uint32_t>(count % n);
  // pos < n and k < n, so r < 2n.
  const std::uint32_t r = pos + (forward ? k : n - k);
  return r - (n & (0u - static_cast<std::uint32_t>(r >= n)));
}

// The neighbour `count` places after (forward) or before x around v,
// cyclically, by its slot (null: {nullptr, 0}). count >= 1; taken modulo
// the valence first, so no sum overflows however large it is.
template <class V>
VV_INLINE vertex_ref<typename V::traits_type> step_ref(const vertex<typename V::traits_type>& x, const V& v,
                                                 unsigned long count, bool forward, const char* op,
                                                 const where& w) {
  auto s = view(v, op, w);
  // A null or foreign x has slot 0, which no entry holds.
  std::int32_t pos = find(*s.nb, slot_in(x, s.ctx));
  if (pos < 0) return {nullptr, 0};
  return {s.ctx, entry_id((*s.nb)[cyclic_step(static_cast<std::uint32_t>(pos), s.nb->size(), count, forward)])};
}
template <class V>
VV_INLINE vertex<typename V::traits_type> step_from(const vertex<typename V::traits_type>& x, const V& v,
                                          unsigned long count, bool forward, const char* op, const where& w) {
  const auto r = step_ref(x, v, count, forward, op, w);
  return vertex<typename V::traits_type>::from_slot(r.ctx, r.id);
}

// The count of next(i)to / prev(i)to: 1 or more.
inline unsigned long step_count(long i, const char* op, const where& w) {
  if (i < 1)
    raise(w, op, [&] { return "the count must be 1 or more, not " + std::to_string(i); });
  return static_cast<unsigned long>(i);
}
}  // namespace detail

//! `next(i)to x in v` (i = 1: `nextto`): the neighbour i places after x
//! in v's rotation, counted cyclically; null when x is not a neighbour of
//! v. i < 1 is an error.
template <class V, detail::if_vertex_like<V> = 0>
VV_INLINE vertex<typename V::traits_type> next_to(const vertex<typename V::traits_type>& x, const V& v,
                                        long i, where w = where::here()) {
  return detail::step_from(x, v, detail::step_count(i, "next(i)to", w), true, "next(i)to", w);
}
template <class V, detail::if_vertex_like<V> = 0>
VV_INLINE vertex<typename V::traits_type> next_to(const vertex<typename V::traits_type>& x, const V& v,
                                        where w = where::here()) {
  return detail::step_from(x, v, 1UL, true, "nextto", w);
}

//! `prev(i)to x in v` (i = 1: `prevto`); i < 1 is an error.
template <class V, detail::if_vertex_like<V> = 0>
VV_INLINE vertex<typename V::traits_type> prev_to(const vertex<typename V::traits_type>& x, const V& v,
                                        long i, where w = where::here()) {
  return detail::step_from(x, v, detail::step_count(i, "prev(i)to", w), false, "prev(i)to", w);
}
template <class V, detail::if_vertex_like<V> = 0>
VV_INLINE vertex<typename V::traits_type> prev_to(const vertex<typename V::traits_type>& x, const V& v,
                                        where w = where::here()) {
  return detail::step_from(x, v, 1UL, false, "prevto", w);
}

//! `flagged in v`: the neighbour at the flagged position, or null.
template <class V, detail::if_vertex_like<V> = 0>
vertex<typename V::traits_type> flagged_in(const V& v, where w = where::here()) {
  using vx = vertex<typename V::traits_type>;
  auto s = detail::view(v, "flagged in", w);
  std::int32_t f = s.nb->flag();
  if (f < 0) return vx();
  return vx::from_slot(s.ctx, detail::entry_id((*s.nb)[static_cast<std::uint32_t>(f)]));
}

namespace detail {
template <class V>
vertex<typename V::traits_type> beside_flag(const V& v, int step, const char* op,
                                            const where& w) {
  using vx = vertex<typename V::traits_type>;
  auto s = view(v, op, w);
  std::int32_t f = s.nb->flag();
  if (f < 0) throw error(w, op, "no flag is set in the neighbourhood");
  std::uint32_t k = cyclic_step(static_cast<std::uint32_t>(f), s.nb->size(), 1, step > 0);
  return vx::from_slot(s.ctx, entry_id((*s.nb)[k]));
}
}  // namespace detail

//! `nextto flag in v`
template <class V, detail::if_vertex_like<V> = 0>
vertex<typename V::traits_type> next_to_flag(const V& v, where w = where::here()) {
  return detail::beside_flag(v, 1, "nextto flag", w);
}

//! `prevto flag in v`
template <class V, detail::if_vertex_like<V> = 0>
vertex<typename V::traits_type> prev_to_flag(const V& v, where w = where::here()) {
  return detail::beside_flag(v, -1, "prevto flag", w);
}

}  // namespace vv
