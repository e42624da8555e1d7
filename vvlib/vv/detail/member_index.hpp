// The membership index of a mesh: from a vertex slot to its position in
// the mesh's insertion-order list.
//
// Two representations, chosen by density:
//   * dense — a table indexed by slot (position + 1, 0 = absent): one load
//     per lookup, 4 bytes per slot of the context. Used when the mesh holds
//     a good share of the context's vertices (subdivision meshes).
//   * hashed — open addressing with linear probing, load at most 1/2,
//     storing position + 1; the key is read back from the order list. Used
//     for small meshes in large contexts (a cell's wall in a tissue), where
//     a dense table would waste memory.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace vv::detail {

class member_index {
 public:
  using order_list = std::vector<std::uint32_t>;  // slots, 0 for holes

  //! Position of slot id in order, or -1.
  std::ptrdiff_t find(std::uint32_t id, const order_list& order) const noexcept {
    if (dense_) return id < table_.size() ? std::ptrdiff_t(table_[id]) - 1 : -1;
    std::size_t s;
    return find_hashed(id, order, s) ? std::ptrdiff_t(table_[s]) - 1 : -1;
  }

  //! Records that order[pos] == id (id not yet indexed). `slots` bounds the
  //! slot ids of the context; `members` counts members after the insert.
  void insert(std::uint32_t id, std::size_t pos, const order_list& order, std::size_t members,
              std::size_t slots) {
    if (!dense_ && members >= dense_min && members * 4 >= slots) return make_dense(order, slots);
    if (dense_) {
      if (id >= table_.size()) {
        // The context grew: stay dense only while the mesh is a good share.
        if (members * 4 < slots) return rehash(order, members);
        table_.resize(std::max<std::size_t>(slots, table_.size() + table_.size() / 2), 0u);
      }
      table_[id] = static_cast<std::uint32_t>(pos + 1);
      return;
    }
    if (members * 2 > table_.size()) return rehash(order, members);
    put_hashed(id, pos, order);
  }

  //! Forgets slot id (which is indexed).
  void erase(std::uint32_t id, const order_list& order) noexcept {
    if (dense_) {
      table_[id] = 0;
      return;
    }
    std::size_t s;
    if (find_hashed(id, order, s)) erase_hashed_slot(s, order);
  }

  //! Re-indexes every member of order, choosing the representation anew.
  void rebuild(const order_list& order, std::size_t members, std::size_t slots) {
    if (members >= dense_min && members * 4 >= slots) make_dense(order, slots);
    else rehash(order, members);
  }

  void clear() noexcept { std::fill(table_.begin(), table_.end(), 0u); }
  std::size_t bytes() const noexcept { return table_.capacity() * sizeof(std::uint32_t); }
  void swap(member_index& o) noexcept {
    table_.swap(o.table_);
    std::swap(dense_, o.dense_);
    std::swap(bits_, o.bits_);
  }

 private:
  static constexpr std::size_t dense_min = 256;

  static std::size_t hash(std::uint32_t id, unsigned bits) noexcept {
    return static_cast<std::size_t>((id * 2654435769u) >> (32 - bits));
  }

  void make_dense(const order_list& order, std::size_t slots) {
    dense_ = true;
    table_.assign(slots, 0u);
    for (std::size_t pos = 0; pos < order.size(); ++pos)
      if (order[pos]) table_[order[pos]] = static_cast<std::uint32_t>(pos + 1);
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

  std::vector<std::uint32_t> table_;
  bool dense_ = false;
  unsigned bits_ = 0;
};

}  // namespace vv::detail
