// The storage of one neighbourhood: a cyclic list of neighbour slots, each
// with its half-edge record, plus the flagged position.
//
// Up to K entries live inline (no allocation for the common valences); a
// longer list moves to the heap and moves back when it shrinks to K again,
// so "size <= K" always means "inline". The whole object is 8 + 4K bytes
// for record-less entries (32 bytes for K = 6).
//
// A reference to a half-edge record (`edge& r = (v^a);`) is valid until the
// next edit of v's neighbourhood, which may move the records. Under
// AddressSanitizer, lists with records live on the heap and every edit
// moves them, so a reference kept past an edit is reported where it is used
// (VV_MOVE_RECORDS_ON_EDIT=0 turns this off).
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

#include "inline.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#ifndef VV_MOVE_RECORDS_ON_EDIT
#if defined(__SANITIZE_ADDRESS__)
#define VV_MOVE_RECORDS_ON_EDIT 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define VV_MOVE_RECORDS_ON_EDIT 1
#endif
#endif
#endif
#ifndef VV_MOVE_RECORDS_ON_EDIT
#define VV_MOVE_RECORDS_ON_EDIT 0
#endif

namespace vv::detail {

//! A neighbour slot with a half-edge record.
template <class E>
struct record_entry {
  std::uint32_t id;
  E rec;
};

//! How to reach the slot id and the record of an entry. When the edge
//! record type is empty, an entry is just the slot id.
template <class E, bool Empty = std::is_empty<E>::value>
struct entry_traits {
  using type = record_entry<E>;
  static std::uint32_t id(const type& e) noexcept { return e.id; }
  static void set_id(type& e, std::uint32_t id) noexcept { e.id = id; }
  static E& rec(type& e, E&) noexcept { return e.rec; }
  static const E& rec(const type& e, const E&) noexcept { return e.rec; }
  static type make(std::uint32_t id) { return type{id, E{}}; }
};

template <class E>
struct entry_traits<E, true> {
  using type = std::uint32_t;
  static std::uint32_t id(type e) noexcept { return e; }
  static void set_id(type& e, std::uint32_t id) noexcept { e = id; }
  // Empty records carry no state: every entry shares the caller's instance.
  static E& rec(type, E& shared) noexcept { return shared; }
  static const E& rec(type, const E& shared) noexcept { return shared; }
  static type make(std::uint32_t id) noexcept { return id; }
};

//! Slot id of a neighbourhood entry, whatever its record type.
inline std::uint32_t entry_id(std::uint32_t e) noexcept { return e; }
template <class E>
std::uint32_t entry_id(const record_entry<E>& e) noexcept {
  return e.id;
}

template <class Entry, unsigned K>
class neighbourhood {
  static_assert(K >= 1, "inline capacity must be at least one entry");
  // Checked builds: lists with records are always on the heap and every
  // edit moves them (see the top of this file).
  static constexpr bool moves_on_edit = VV_MOVE_RECORDS_ON_EDIT && !std::is_same<Entry, std::uint32_t>::value;

 public:
  //! Flag values: an index into the list, or one of these.
  static constexpr std::int32_t no_flag = -1;
  //! Only in an old state: never synchronised (behaves as an empty list).
  static constexpr std::int32_t never_synchronised = -2;

  neighbourhood() noexcept {
    if constexpr (moves_on_edit) set_heap(heap_rep{nullptr, 0});
  }
  //! An empty old state that was never synchronised.
  struct never_synchronised_tag {};
  explicit neighbourhood(never_synchronised_tag) noexcept : neighbourhood() { flag_ = never_synchronised; }
  neighbourhood(const neighbourhood& o) : neighbourhood() {
    flag_ = o.flag_;
    assign(o.data(), o.size_);
  }
  neighbourhood& operator=(const neighbourhood& o) {
    if (this == &o) return *this;
    if (!moves_on_edit && std::is_trivially_copyable<Entry>::value && size_ <= K && o.size_ <= K) {
      // Both inline (the common case, e.g. in synchronise): copy the bytes.
      std::memcpy(static_cast<void*>(this), static_cast<const void*>(&o), sizeof *this);
      return *this;
    }
    assign(o.data(), o.size_);
    flag_ = o.flag_;
    return *this;
  }
  ~neighbourhood() { release(); }

  std::uint32_t size() const noexcept { return size_; }
  bool empty() const noexcept { return size_ == 0; }
  Entry* data() noexcept { return is_inline() ? inline_data() : heap().ptr; }
  const Entry* data() const noexcept {
    return is_inline() ? inline_data() : heap().ptr;
  }
  Entry* begin() noexcept { return data(); }
  Entry* end() noexcept { return data() + size_; }
  const Entry* begin() const noexcept { return data(); }
  const Entry* end() const noexcept { return data() + size_; }
  Entry& operator[](std::uint32_t i) noexcept { return data()[i]; }
  const Entry& operator[](std::uint32_t i) const noexcept { return data()[i]; }

  //! The position of the entry naming slot id, or -1.
  VV_INLINE std::int32_t index_of(std::uint32_t id) const noexcept {
#if defined(__SSE2__)
    if constexpr (std::is_same<Entry, std::uint32_t>::value && K >= 4 && K < 32 && !moves_on_edit) {
      if (is_inline()) return inline_index_of(id);
    }
#endif
    const Entry* d = data();
    for (std::uint32_t i = 0; i < size_; ++i)
      if (entry_id(d[i]) == id) return static_cast<std::int32_t>(i);
    return -1;
  }

  //! Copies the entries' slot ids to dst, which has room for
  //! max(size(), room) ids. A short inline list is copied whole, unused
  //! entries too: one fixed-size copy instead of a loop.
  VV_INLINE void copy_ids(std::uint32_t* dst, std::uint32_t room) const noexcept {
    if constexpr (std::is_same<Entry, std::uint32_t>::value && !moves_on_edit) {
      if (is_inline() && K <= room) {
        std::memcpy(dst, storage_, K * sizeof(std::uint32_t));
        return;
      }
    }
    const Entry* d = data();
    for (std::uint32_t i = 0; i < size_; ++i) dst[i] = entry_id(d[i]);
  }

  std::int32_t flag() const noexcept { return flag_; }
  void set_flag(std::int32_t f) noexcept { flag_ = f; }

  //! Replace the contents by n entries (the flag is left alone).
  VV_INLINE void assign(const Entry* src, std::uint32_t n) {
    if constexpr (!moves_on_edit && std::is_trivially_copyable<Entry>::value) {
      if (n <= K && size_ <= K) {
        // Inline to inline (a `make` of a common valence): a short loop
        // instead of a call to memmove for a few bytes. src is never
        // before the inline storage, so copying forward is safe.
        Entry* d = inline_data();
        for (std::uint32_t i = 0; i < n; ++i) d[i] = src[i];
        size_ = n;
        return;
      }
    }
    assign_elsewhere(src, n);
  }
  //! The same, from a source with `room` readable entries (room >= n): an
  //! inline list of slots is copied whole, K entries at once.
  VV_INLINE void assign(const Entry* src, std::uint32_t n, std::uint32_t room) {
    if constexpr (std::is_same<Entry, std::uint32_t>::value && !moves_on_edit) {
      if (n <= K && size_ <= K && K <= room) {
        std::memcpy(storage_, src, K * sizeof(std::uint32_t));
        size_ = n;
        return;
      }
    }
    assign(src, n);
  }

  //! Insert e before position pos (pos == size() appends).
  void insert(std::uint32_t pos, const Entry& e) {
    Entry copy(e);  // e may live in this list
    if (moves_on_edit || size_ == K || (!is_inline() && size_ == heap().cap)) {
      reallocate_with(pos, std::move(copy));
      return;
    }
    Entry* d = data();
    if constexpr (std::is_trivially_copyable<Entry>::value) {
      // A few entries at most: a short loop, not a call to memmove.
      for (std::uint32_t i = size_; i > pos; --i) d[i] = d[i - 1];
      d[pos] = copy;
    } else if (pos == size_) {
      ::new (static_cast<void*>(d + size_)) Entry(std::move(copy));
    } else {
      ::new (static_cast<void*>(d + size_)) Entry(std::move(d[size_ - 1]));
      std::move_backward(d + pos, d + size_ - 1, d + size_);
      d[pos] = std::move(copy);
    }
    ++size_;
  }

  //! Remove the entry at pos.
  void erase(std::uint32_t pos) {
    if constexpr (moves_on_edit) {
      Entry* old = data();
      Entry* block = allocate(size_ - 1);
      std::uninitialized_move(old, old + pos, block);
      std::uninitialized_move(old + pos + 1, old + size_, block + pos);
      release();
      set_heap(heap_rep{block, size_ - 1});
      --size_;
      return;
    }
    Entry* d = data();
    std::move(d + pos + 1, d + size_, d + pos);
    d[size_ - 1].~Entry();
    --size_;
    if (size_ == K) shrink_to_inline();
  }

  void clear() noexcept {
    release();
    size_ = 0;
    if constexpr (moves_on_edit) set_heap(heap_rep{nullptr, 0});
  }

 private:
  // assign() where either list is on the heap, or records must move.
  [[gnu::noinline]] void assign_elsewhere(const Entry* src, std::uint32_t n) {
    if (src == data() && n == size_) return;
    if constexpr (moves_on_edit) {
      Entry* block = allocate(n);
      std::uninitialized_copy(src, src + n, block);
      release();
      set_heap(heap_rep{block, n});
      size_ = n;
      return;
    }
    destroy_all();
    if (n > K) {
      if (is_inline() || heap().cap < n) {
        release_heap_storage();
        heap_rep h{allocate(n), n};
        set_heap(h);
      }
    } else if (!is_inline()) {
      release_heap_storage();
    }
    size_ = n;  // mode now matches size: inline iff n <= K
    std::uninitialized_copy(src, src + n, data());
  }

  struct heap_rep {
    Entry* ptr;
    std::uint32_t cap;
  };
  static constexpr std::size_t inline_bytes =
      K * sizeof(Entry) > sizeof(heap_rep) ? K * sizeof(Entry) : sizeof(heap_rep);
  static constexpr std::size_t storage_align =
      alignof(Entry) > alignof(heap_rep) ? alignof(Entry) : alignof(heap_rep);

  bool is_inline() const noexcept { return !moves_on_edit && size_ <= K; }

#if defined(__SSE2__)
  // Compares id with the whole inline list, four entries at a time (the
  // last four overlap the ones before when K is no multiple of four), and
  // keeps the matches below size_: no branch on where the match is, which a
  // scan mispredicts about once per search.
  VV_INLINE std::int32_t inline_index_of(std::uint32_t id) const noexcept {
    const __m128i key = _mm_set1_epi32(static_cast<int>(id));
    unsigned matches = 0;
    for (unsigned first = 0; first < K; first += 4) {
      const unsigned at = first + 4 <= K ? first : K - 4;
      const __m128i four = _mm_loadu_si128(reinterpret_cast<const __m128i*>(storage_ + at * sizeof(Entry)));
      matches |= static_cast<unsigned>(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(four, key)))) << at;
    }
    matches &= (1u << size_) - 1u;
    return matches ? static_cast<std::int32_t>(__builtin_ctz(matches)) : -1;
  }
#endif
  Entry* inline_data() noexcept { return std::launder(reinterpret_cast<Entry*>(storage_)); }
  const Entry* inline_data() const noexcept {
    return std::launder(reinterpret_cast<const Entry*>(storage_));
  }
  heap_rep heap() const noexcept {
    heap_rep h;
    std::memcpy(&h, storage_, sizeof h);
    return h;
  }
  void set_heap(const heap_rep& h) noexcept { std::memcpy(storage_, &h, sizeof h); }

  static Entry* allocate(std::uint32_t n) {
    return n == 0 ? nullptr : static_cast<Entry*>(::operator new(sizeof(Entry) * n));
  }

  void destroy_all() noexcept { std::destroy(data(), data() + size_); }

  void release_heap_storage() noexcept {
    if (!is_inline()) ::operator delete(heap().ptr);
  }

  void release() noexcept {
    destroy_all();
    release_heap_storage();
  }

  // The list is full: move it to a heap block twice as large, with e
  // placed at pos. Afterwards size_ > K, which marks heap mode.
  void reallocate_with(std::uint32_t pos, Entry&& e) {
    std::uint32_t new_cap = moves_on_edit ? size_ + 1 : size_ * 2;
    Entry* block = allocate(new_cap);
    Entry* old = data();
    std::uninitialized_move(old, old + pos, block);
    ::new (static_cast<void*>(block + pos)) Entry(std::move(e));
    std::uninitialized_move(old + pos, old + size_, block + pos + 1);
    std::destroy(old, old + size_);
    if (!is_inline()) ::operator delete(heap().ptr);
    set_heap(heap_rep{block, new_cap});
    ++size_;
  }

  void shrink_to_inline() noexcept {
    heap_rep h = heap();
    Entry* src = h.ptr;
    Entry* dst = inline_data();
    std::uninitialized_move(src, src + size_, dst);
    std::destroy(src, src + size_);
    ::operator delete(h.ptr);
  }

  std::uint32_t size_ = 0;
  std::int32_t flag_ = no_flag;
  alignas(storage_align) unsigned char storage_[inline_bytes];
};

}  // namespace vv::detail
