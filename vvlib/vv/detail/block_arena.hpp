// Memory for a context's blocks of vertices: its chunks and their old
// state, which live as long as the context does. The first MiB of blocks
// comes from the heap, one block at a time; after it, blocks are carved
// one after another from runs (page_runs.hpp), a few dozen to a run.
// Where runs are not used, every block comes from the heap. A block of
// more than half a run (a thousand vertices of over a KiB of properties
// each) leaves the rest of its run unused.
#pragma once

#include <cstddef>
#include <cstdint>
#include <new>
#include <vector>

#include "page_runs.hpp"

namespace vv::detail {

class block_arena {
 public:
  //! Blocks up to this many bytes in all come from the heap.
  static std::size_t default_heap_bytes() noexcept {
    return huge_pages_offered() ? std::size_t{1} << 20 : ~std::size_t{0};
  }

  block_arena() noexcept : heap_left_(default_heap_bytes()) {}
  explicit block_arena(std::size_t heap_bytes) noexcept : heap_left_(heap_bytes) {}
  block_arena(const block_arena&) = delete;
  block_arena& operator=(const block_arena&) = delete;
  ~block_arena() {
    for (const piece& p : pieces_) {
      if (p.mapped) unmap_run(p.start, p.bytes);
      else free_heap_block(p.start, p.align);
    }
  }

  //! Memory for a block of `bytes` aligned to `align` (a power of two, at
  //! most run_bytes), kept until the arena goes. Throws std::bad_alloc.
  void* take(std::size_t bytes, std::size_t align) {
    // Room to record a piece first, so that recording it cannot throw.
    if (pieces_.size() == pieces_.capacity()) pieces_.reserve(2 * pieces_.size() + 8);
    if (bytes <= heap_left_) {
      void* p = heap_block(bytes, align);
      heap_left_ -= bytes;
      pieces_.push_back({p, bytes, align, false});
      return p;
    }
    heap_left_ = 0;  // from the first run on, every block is carved from runs
    std::size_t pad = (align - reinterpret_cast<std::uintptr_t>(next_) % align) % align;
    if (next_ == nullptr || pad + bytes > left_) {
      // What is left of the current run is given up: less than a block.
      const std::size_t size = whole_runs(bytes);
      next_ = static_cast<char*>(map_run(size));
      pieces_.push_back({next_, size, run_bytes, true});
      left_ = size;
      pad = 0;
    }
    void* p = next_ + pad;
    next_ += pad + bytes;
    left_ -= pad + bytes;
    return p;
  }

  //! Bytes mapped in runs.
  std::size_t mapped_bytes() const noexcept {
    std::size_t n = 0;
    for (const piece& p : pieces_)
      if (p.mapped) n += p.bytes;
    return n;
  }

 private:
  struct piece {
    void* start;
    std::size_t bytes;
    std::size_t align;
    bool mapped;
  };

  std::vector<piece> pieces_;
  char* next_ = nullptr;  // the free part of the current run
  std::size_t left_ = 0;
  std::size_t heap_left_;
};

}  // namespace vv::detail
