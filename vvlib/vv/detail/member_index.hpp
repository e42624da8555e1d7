// The membership index of a mesh: from a vertex slot to its position in
// the mesh's insertion-order list.
//
// Two representations, chosen by density:
//   * dense — a table over a window of slots [base, base + size) (position
//     + 1, 0 = absent): one subtraction and one load per lookup, 4 bytes
//     per slot of the window. Used when the members fill a good share of
//     the slots between the lowest and the highest. A subdivision step's
//     new meshes (its edge or face points, created one after another) are
//     dense from their first members, over their own slots only, not over
//     the whole context.
//   * hashed — open addressing with linear probing, load at most 1/2,
//     storing position + 1; the key is read back from the order list. Used
//     for meshes spread thinly over the slots (a cell's wall in a tissue),
//     where a dense window would waste memory.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "inline.hpp"
#include "run_allocator.hpp"

namespace vv::detail {

class member_index {
 public:
  using order_list = slot_list;  // slots, 0 for holes

  //! Position of slot id in order, or -1.
  std::ptrdiff_t find(std::uint32_t id, const order_list& order) const noexcept {
    if (dense_) {
      // Below base the difference wraps around past the window's size.
      const std::uint32_t i = id - base_;
      return i < table_.size() ? std::ptrdiff_t(table_[i]) - 1 : -1;
    }
    std::size_t s;
    return find_hashed(id, order, s) ? std::ptrdiff_t(table_[s]) - 1 : -1;
  }

  //! Records that order[pos] == id (id not yet indexed); `members` counts
  //! the members after the insert, `slots` bounds the context's slot ids.
  VV_INLINE void insert(std::uint32_t id, std::size_t pos, const order_list& order, std::size_t members,
                        std::size_t slots) {
    low_ = std::min(low_, id);
    high_ = std::max(high_, id);
    const std::uint32_t i = id - base_;
    if (dense_ && i < table_.size()) {
      table_[i] = static_cast<std::uint32_t>(pos + 1);
      return;
    }
    insert_elsewhere(id, pos, order, members, slots);
  }

  //! Forgets slot id (which is indexed). The span of slots is not
  //! narrowed: it bounds the members from outside, which is all it is for.
  void erase(std::uint32_t id, const order_list& order) noexcept {
    if (dense_) {
      table_[id - base_] = 0;
      return;
    }
    std::size_t s;
    if (find_hashed(id, order, s)) erase_hashed_slot(s, order);
  }

  //! Re-indexes every member of order, choosing the representation anew.
  void rebuild(const order_list& order, std::size_t members) {
    low_ = no_slot;
    high_ = 0;
    for (std::uint32_t id : order)
      if (id) low_ = std::min(low_, id), high_ = std::max(high_, id);
    if (members >= dense_min && dense_enough(members)) make_dense(order, false);
    else rehash(order, members);
  }

  //! Forgets every member; the representation stays.
  void clear() noexcept {
    std::fill(table_.begin(), table_.end(), 0u);
    low_ = no_slot;
    high_ = 0;
  }
  std::size_t bytes() const noexcept { return table_.capacity() * sizeof(std::uint32_t); }
  void swap(member_index& o) noexcept {
    table_.swap(o.table_);
    std::swap(dense_, o.dense_);
    std::swap(bits_, o.bits_);
    std::swap(base_, o.base_);
    std::swap(low_, o.low_);
    std::swap(high_, o.high_);
  }

 private:
  static constexpr std::size_t dense_min = 256;
  static constexpr std::uint32_t no_slot = std::numeric_limits<std::uint32_t>::max();

  // The members fill at least a quarter of the slots from the lowest to
  // the highest: a dense window then costs at most 16 bytes per member, as
  // a hash table at its lowest load does.
  bool dense_enough(std::size_t members) const noexcept {
    return low_ <= high_ && members * 4 >= std::size_t(high_ - low_) + 1;
  }

  // insert() off its common path: outside a dense window, or hashed.
  [[gnu::noinline]] void insert_elsewhere(std::uint32_t id, std::size_t pos, const order_list& order,
                                          std::size_t members, std::size_t slots) {
    if (dense_) {
      if (!dense_enough(members)) return rehash(order, members);
      return widen_to(id, pos, order, slots);
    }
    if (members >= dense_min && dense_enough(members)) return make_dense(order, true);
    if (members * 2 > table_.size()) return rehash(order, members);
    put_hashed(id, pos, order);
  }

  static std::size_t hash(std::uint32_t id, unsigned bits) noexcept {
    return static_cast<std::size_t>((id * 2654435769u) >> (32 - bits));
  }

  // A window over [low_, high_], filled from order. A mesh still growing
  // gets room for half as many slots again on each side (new vertices take
  // the next slots, reused ones lie below); a rebuilt one (a copy, a
  // compaction) gets just its span.
  void make_dense(const order_list& order, bool growing) {
    dense_ = true;
    const std::uint32_t room = growing ? (high_ - low_) / 2 + 1 : 0;
    base_ = low_ > room ? low_ - room : 0;
    table_.assign(std::size_t(high_ - base_) + 1 + room, 0u);
    for (std::size_t pos = 0; pos < order.size(); ++pos)
      if (order[pos]) table_[order[pos] - base_] = static_cast<std::uint32_t>(pos + 1);
  }

  // The window must take in [low_, high_]. Upwards it takes in every slot
  // the context has (a merge of many new vertices grows it once, to just
  // what it needs) and grows by half again at least (a mesh growing a slot
  // at a time is copied O(log n) times); downwards it is made anew with
  // room below.
  void widen_to(std::uint32_t id, std::size_t pos, const order_list& order, std::size_t slots) {
    if (low_ < base_) return make_dense(order, true);
    const std::size_t needed = std::max<std::size_t>(std::size_t(high_ - base_) + 1, slots - base_);
    table_.resize(std::max(needed, table_.size() + table_.size() / 2), 0u);
    table_[id - base_] = static_cast<std::uint32_t>(pos + 1);
  }

  void rehash(const order_list& order, std::size_t members) {
    dense_ = false;
    bits_ = 4;
    while ((std::size_t(1) << bits_) < members * 2) ++bits_;
    table_.assign(std::size_t(1) << bits_, 0u);
    for (std::size_t pos = 0; pos < order.size(); ++pos)
      if (order[pos]) put_hashed(order[pos], pos, order);
  }

  bool find_hashed(std::uint32_t id, const order_list& order, std::size_t& s) const noexcept {
    if (table_.empty()) return false;
    std::size_t mask = table_.size() - 1;
    for (s = hash(id, bits_);; s = (s + 1) & mask) {
      std::uint32_t p = table_[s];
      if (p == 0) return false;
      if (order[p - 1] == id) return true;
    }
  }

  void put_hashed(std::uint32_t id, std::size_t pos, const order_list&) noexcept {
    std::size_t mask = table_.size() - 1;
    std::size_t s = hash(id, bits_);
    while (table_[s] != 0) s = (s + 1) & mask;
    table_[s] = static_cast<std::uint32_t>(pos + 1);
  }

  // Backward-shift deletion keeps every probe sequence unbroken.
  void erase_hashed_slot(std::size_t s, const order_list& order) noexcept {
    std::size_t mask = table_.size() - 1;
    std::size_t hole = s;
    for (std::size_t j = (s + 1) & mask; table_[j] != 0; j = (j + 1) & mask) {
      std::size_t home = hash(order[table_[j] - 1], bits_);
      // j may move into the hole unless its home lies cyclically in (hole, j].
      bool stays = hole <= j ? (home > hole && home <= j) : (home > hole || home <= j);
      if (!stays) {
        table_[hole] = table_[j];
        hole = j;
      }
    }
    table_[hole] = 0;
  }

  slot_list table_;
  bool dense_ = false;
  unsigned bits_ = 0;
  std::uint32_t base_ = 0;       // dense: the slot of table_[0]
  std::uint32_t low_ = no_slot;  // the lowest and highest slot inserted
  std::uint32_t high_ = 0;       // since the last rebuild or clear
};

}  // namespace vv::detail
