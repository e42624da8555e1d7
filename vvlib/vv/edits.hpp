// Neighbourhood edits (LANGUAGE.md section 4, second table). Each changes
// one neighbourhood: the target's current state (a target written `` `v ``
// edits v's current state too).
//
// [decision] Check order: a null target is an error; then an anchor that is
// not a neighbour makes the edit a no-op; only then is the inserted vertex
// checked (null, the target itself, or already a neighbour: errors).
#pragma once

#include "detail/inline.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iterator>
#include <vector>

#include "detail/nb_access.hpp"
#include "detail/repeated_ids.hpp"

namespace vv {

namespace detail {

template <class Tr>
VV_INLINE auto& mutable_nb(const vertex<Tr>& v) {
  return v.ctx()->nb(v.slot());
}

// Insert x at position pos of v*, keeping the flag on its entry.
template <class Tr>
VV_INLINE void insert_at(const vertex<Tr>& v, std::uint32_t pos, const vertex<Tr>& x) {
  using entry_traits = typename context<Tr>::entry_traits;
  auto& nb = mutable_nb(v);
  nb.insert(pos, entry_traits::make(x.slot()));
  if (nb.flag() >= static_cast<std::int32_t>(pos)) nb.set_flag(nb.flag() + 1);
}

template <class Tr>
void erase_at(const vertex<Tr>& v, std::uint32_t pos) {
  auto& nb = mutable_nb(v);
  nb.erase(pos);
  std::int32_t f = nb.flag();
  std::int32_t p = static_cast<std::int32_t>(pos);
  if (f == p) nb.set_flag(nb.no_flag);
  else if (f > p) nb.set_flag(f - 1);
}

template <class Tr>
std::uint32_t flag_position(const vertex<Tr>& v, const char* op, const where& w) {
  std::int32_t f = mutable_nb(v).flag();
  if (f < 0) throw error(w, op, "no flag is set in the neighbourhood of " + name_of(v));
  return static_cast<std::uint32_t>(f);
}

// Why x may not be in the list for v (the first of: null, of another
// context, v itself). Off the hot path: make's loop tests the three at once.
template <class Tr>
[[noreturn, gnu::noinline, gnu::cold]] void refuse_in_make(const vertex<Tr>& v, const vertex<Tr>& x,
                                                           const where& w) {
  if (!x) raise(w, "make", [&] { return "the list for " + name_of(v) + " contains the null vertex"; });
  if (x.ctx() != v.ctx())
    raise(w, "make", [&] { return name_of(x) + " belongs to another context than " + name_of(v); });
  raise(w, "make", [&] { return name_of(v) + " cannot be its own neighbour"; });
}

template <class Tr>
[[noreturn, gnu::noinline, gnu::cold]] void listed_twice(const vertex<Tr>& v, std::uint32_t id, const where& w) {
  throw error(w, "make", name_of(vertex<Tr>::from_slot(v.ctx(), id)) + " is listed twice for " + name_of(v));
}

// The first id of a list of n that an earlier entry names too (off the
// hot path: the list is refused).
[[gnu::cold]] inline std::uint32_t first_repeated(const std::uint32_t* ids, std::size_t n) noexcept {
  for (std::size_t i = 1; i < n; ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (ids[i] == ids[j]) return ids[i];
  return 0;
}

// A list of up to eight vertices, without half-edge records (the common
// `make`): checked without a branch per pair, and copied into the inline
// storage whole.
template <class Tr, class It>
VV_INLINE void make_short_neighbourhood(const vertex<Tr>& v, It first, std::size_t n, const where& w) {
  alignas(16) std::uint32_t ids[repeat_check_lanes] = {};
  context<Tr>* const ctx = v.ctx();
  const std::uint32_t self = v.slot();
  for (std::size_t k = 0; k < n; ++k, ++first) {
    const vertex<Tr>& x = static_cast<const vertex<Tr>&>(*first);
    // Null, of another context, or v itself: one test on the common path.
    if (__builtin_expect(!x || x.ctx() != ctx || x.slot() == self, 0)) refuse_in_make(v, x, w);
    ids[k] = x.slot();
  }
  if (__builtin_expect(repeats_among(ids, n), 0)) listed_twice(v, first_repeated(ids, n), w);
  auto& nb = ctx->nb(self);
  nb.assign(ids, static_cast<std::uint32_t>(n), repeat_check_lanes);
  nb.set_flag(nb.no_flag);
}

template <class Tr, class It>
void make_neighbourhood(const vertex<Tr>& v, It first, It last, const where& w) {
  using entry_traits = typename context<Tr>::entry_traits;
  using entry = typename context<Tr>::entry;
  constexpr std::size_t small = 16;  // lists up to this long need no allocation
  std::size_t n = static_cast<std::size_t>(std::distance(first, last));
  if constexpr (std::is_same<entry, std::uint32_t>::value)
    if (n <= repeat_check_lanes) return make_short_neighbourhood(v, first, n, w);
  entry local[small];
  std::vector<entry> spilled;
  entry* entries = local;
  if (n > small) {
    spilled.resize(n);
    entries = spilled.data();
  }
  context<Tr>* const ctx = v.ctx();
  const std::uint32_t self = v.slot();
  std::size_t k = 0;
  // One bit per slot modulo 64: two entries can only be the same vertex
  // when their bits collide, so most lists skip the pairwise search.
  std::uint64_t seen = 0;
  bool maybe_twice = false;
  for (It it = first; it != last; ++it, ++k) {
    const vertex<Tr>& x = static_cast<const vertex<Tr>&>(*it);
    // Null, of another context, or v itself: one test on the common path.
    if (__builtin_expect(!x || x.ctx() != ctx || x.slot() == self, 0)) refuse_in_make(v, x, w);
    entries[k] = entry_traits::make(x.slot());
    const std::uint64_t bit = std::uint64_t(1) << (x.slot() & 63u);
    maybe_twice |= (seen & bit) != 0;
    seen |= bit;
  }
  if (!maybe_twice) {
    // No two entries share a bit: no duplicates.
  } else if (n <= small) {
    for (std::size_t i = 1; i < n; ++i)
      for (std::size_t j = 0; j < i; ++j)
        if (entry_id(entries[i]) == entry_id(entries[j])) listed_twice(v, entry_id(entries[i]), w);
  } else {
    std::vector<std::uint32_t> ids;
    ids.reserve(n);
    for (std::size_t i = 0; i < n; ++i) ids.push_back(entry_id(entries[i]));
    std::sort(ids.begin(), ids.end());
    auto dup = std::adjacent_find(ids.begin(), ids.end());
    if (dup != ids.end()) listed_twice(v, *dup, w);
  }
  auto& nb = ctx->nb(self);
  nb.assign(entries, static_cast<std::uint32_t>(n));
  nb.set_flag(nb.no_flag);
}

//! An entry of a `make` list: the vertex it names, not a copy. The list and
//! the temporaries its entries name live to the end of the statement, so
//! building it costs no reference counts (a list of handles would count
//! every entry twice, in and out).
template <class Tr>
class make_item {
 public:
  make_item(const vertex<Tr>& v) noexcept : v_(&v) {}
  make_item(std::nullptr_t) noexcept : v_(&null_vertex()) {}  // `make {0} ...`: an error, named
  operator const vertex<Tr>&() const noexcept { return *v_; }

 private:
  static const vertex<Tr>& null_vertex() noexcept {
    static const vertex<Tr> null;
    return null;
  }
  const vertex<Tr>* v_;
};

}  // namespace detail

//! `make {a, b, c} nb_of v;`
template <class V, detail::if_vertex_like<V> = 0>
VV_INLINE void make_nb(const V& target, std::initializer_list<detail::make_item<typename V::traits_type>> list,
             where w = where::here()) {
  const auto& v = detail::edit_target(target, "make", w);
  detail::make_neighbourhood(v, list.begin(), list.end(), w);
}
//! `make` from any sequence of vertices.
template <class V, class Range, detail::if_vertex_like<V> = 0>
void make_nb_from(const V& target, const Range& list, where w = where::here()) {
  const auto& v = detail::edit_target(target, "make", w);
  detail::make_neighbourhood(v, std::begin(list), std::end(list), w);
}

//! `erase x from v;` (no effect when x is not a neighbour)
template <class V, detail::if_vertex_like<V> = 0>
VV_INLINE void erase_from(const vertex<typename V::traits_type>& x, const V& target,
                where w = where::here()) {
  const auto& v = detail::edit_target(target, "erase", w);
  std::int32_t pos = detail::find(detail::mutable_nb(v), detail::slot_in(x, v.ctx()));
  if (pos >= 0 && x) detail::erase_at(v, static_cast<std::uint32_t>(pos));
}

//! `replace a with x in v;` — x takes a's place and keeps its record.
template <class V, detail::if_vertex_like<V> = 0>
VV_INLINE void replace_in(const vertex<typename V::traits_type>& a, const vertex<typename V::traits_type>& x,
                const V& target, where w = where::here()) {
  const auto& v = detail::edit_target(target, "replace", w);
  auto& nb = detail::mutable_nb(v);
  std::int32_t pos = detail::find(nb, detail::slot_in(a, v.ctx()));
  if (pos < 0 || !a) return;
  detail::check_insertable(x, v, nb, "replace", w);
  using entry_traits = typename context<typename V::traits_type>::entry_traits;
  entry_traits::set_id(nb[static_cast<std::uint32_t>(pos)], x.slot());
}

//! `splice x after a in v;`
template <class V, detail::if_vertex_like<V> = 0>
VV_INLINE void splice_after(const vertex<typename V::traits_type>& x, const vertex<typename V::traits_type>& a,
                  const V& target, where w = where::here()) {
  const auto& v = detail::edit_target(target, "splice", w);
  auto& nb = detail::mutable_nb(v);
  std::int32_t pos = detail::find(nb, detail::slot_in(a, v.ctx()));
  if (pos < 0 || !a) return;
  detail::check_insertable(x, v, nb, "splice", w);
  detail::insert_at(v, static_cast<std::uint32_t>(pos) + 1, x);
}

//! `splice x before a in v;`
template <class V, detail::if_vertex_like<V> = 0>
VV_INLINE void splice_before(const vertex<typename V::traits_type>& x,
                   const vertex<typename V::traits_type>& a, const V& target,
                   where w = where::here()) {
  const auto& v = detail::edit_target(target, "splice", w);
  auto& nb = detail::mutable_nb(v);
  std::int32_t pos = detail::find(nb, detail::slot_in(a, v.ctx()));
  if (pos < 0 || !a) return;
  detail::check_insertable(x, v, nb, "splice", w);
  detail::insert_at(v, static_cast<std::uint32_t>(pos), x);
}

//! `flag b in a;` — marks b's position; a null b unsets the flag; no
//! effect when b is not a neighbour.
template <class V, detail::if_vertex_like<V> = 0>
void flag_in(const vertex<typename V::traits_type>& b, const V& target, where w = where::here()) {
  const auto& a = detail::edit_target(target, "flag", w);
  auto& nb = detail::mutable_nb(a);
  if (!b) {
    nb.set_flag(nb.no_flag);
    return;
  }
  std::int32_t pos = detail::find(nb, detail::slot_in(b, a.ctx()));
  if (pos >= 0) nb.set_flag(pos);
}

//! `splice b after flag in a;`
template <class V, detail::if_vertex_like<V> = 0>
void splice_after_flag(const vertex<typename V::traits_type>& b, const V& target,
                       where w = where::here()) {
  const auto& a = detail::edit_target(target, "splice after flag", w);
  std::uint32_t f = detail::flag_position(a, "splice after flag", w);
  detail::check_insertable(b, a, detail::mutable_nb(a), "splice after flag", w);
  detail::insert_at(a, f + 1, b);
}

//! `splice b before flag in a;`
template <class V, detail::if_vertex_like<V> = 0>
void splice_before_flag(const vertex<typename V::traits_type>& b, const V& target,
                        where w = where::here()) {
  const auto& a = detail::edit_target(target, "splice before flag", w);
  std::uint32_t f = detail::flag_position(a, "splice before flag", w);
  detail::check_insertable(b, a, detail::mutable_nb(a), "splice before flag", w);
  detail::insert_at(a, f, b);
}

//! `replace flag with b in a;` — the flag stays on the position.
template <class V, detail::if_vertex_like<V> = 0>
void replace_flag(const vertex<typename V::traits_type>& b, const V& target,
                  where w = where::here()) {
  const auto& a = detail::edit_target(target, "replace flag", w);
  std::uint32_t f = detail::flag_position(a, "replace flag", w);
  auto& nb = detail::mutable_nb(a);
  detail::check_insertable(b, a, nb, "replace flag", w);
  using entry_traits = typename context<typename V::traits_type>::entry_traits;
  entry_traits::set_id(nb[f], b.slot());
}

//! `erase flag from a;` — removes the flagged entry and unsets the flag.
template <class V, detail::if_vertex_like<V> = 0>
void erase_flag(const V& target, where w = where::here()) {
  const auto& a = detail::edit_target(target, "erase flag", w);
  std::uint32_t f = detail::flag_position(a, "erase flag", w);
  detail::erase_at(a, f);
}

}  // namespace vv
