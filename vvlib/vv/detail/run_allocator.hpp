// An allocator for the large arrays of vertex storage (counts and labels by
// slot, a mesh's member list and index): arrays of a MiB or more are
// mapped in whole runs (page_runs.hpp), smaller ones come from the heap.
// A tail in small pages would cost a fault per 4 KiB again; rounding up
// to whole runs adds less than a run (at most doubling an array of a MiB).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <new>
#include <vector>

#include "page_runs.hpp"

namespace vv::detail {

template <class T>
struct run_allocator {
  using value_type = T;
  //! Arrays of this many bytes and more are mapped.
  static std::size_t mapped_from() noexcept { return huge_pages_offered() ? std::size_t{1} << 20 : ~std::size_t{0}; }

  run_allocator() noexcept = default;
  template <class U>
  run_allocator(const run_allocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > std::numeric_limits<std::size_t>::max() / sizeof(T)) throw std::bad_array_new_length();
    const std::size_t bytes = n * sizeof(T);
    if (bytes < mapped_from()) return static_cast<T*>(heap_block(bytes, alignof(T)));
    return static_cast<T*>(map_run(whole_runs(bytes)));
  }
  void deallocate(T* p, std::size_t n) noexcept {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < mapped_from()) free_heap_block(p, alignof(T));
    else unmap_run(p, whole_runs(bytes));
  }

  template <class U>
  bool operator==(const run_allocator<U>&) const noexcept { return true; }
  template <class U>
  bool operator!=(const run_allocator<U>&) const noexcept { return false; }
};

//! Vertex slots, or numbers by slot, in large arrays.
using slot_list = std::vector<std::uint32_t, run_allocator<std::uint32_t>>;

}  // namespace vv::detail
