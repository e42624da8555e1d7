// Recycled storage for short vectors of vertex handles.
//
// A program that collects a face's corners or a cell's wall in a
// std::vector<vertex> makes and frees one to four small blocks each time
// (the vector grows 1, 2, 4, 8): a subdivision step calls malloc and free
// millions of times for them, a tenth of its instructions. The context
// keeps the freed blocks of those four sizes and hands them out again; a
// pop or a push costs a few instructions.
//
// Only a translated program's handles use it (vertex.hpp: their traits
// name the model's context), and only outside parallel loops, whose
// threads allocate with operator new; a block may be freed either way,
// since every block comes from operator new. Under AddressSanitizer
// nothing is recycled, so a use after free is still reported.
#pragma once

#include <cstddef>
#include <cstdint>
#include <new>

#ifndef VV_RECYCLE_HANDLE_BLOCKS
#if defined(__SANITIZE_ADDRESS__)
#define VV_RECYCLE_HANDLE_BLOCKS 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define VV_RECYCLE_HANDLE_BLOCKS 0
#endif
#endif
#endif
#ifndef VV_RECYCLE_HANDLE_BLOCKS
#define VV_RECYCLE_HANDLE_BLOCKS 1
#endif

namespace vv::detail {

class handle_blocks {
 public:
  //! Blocks of 1, 2, 4 and 8 handles are recycled.
  static constexpr std::size_t classes = 4;
  //! At most this many freed blocks of each size are kept.
  static constexpr unsigned kept = 256;

  handle_blocks() = default;
  handle_blocks(const handle_blocks&) = delete;
  handle_blocks& operator=(const handle_blocks&) = delete;
  ~handle_blocks() { release(); }

  //! The class of a block of n handles, or -1 when n is not recycled.
  static int class_of(std::size_t n) noexcept {
    // A power of two up to 8 is class log2(n). No switch: a growing vector
    // asks for 1, 2, 4, 8 in turn, which a jump mispredicts every time.
    if (__builtin_expect(n == 0 || n > 8 || (n & (n - 1)) != 0, 0)) return -1;
    return __builtin_ctzll(n);
  }

  //! A kept block of class c, or null.
  void* take(int c) noexcept {
    free_block* b = heads_[c];
    if (!b) return nullptr;
    heads_[c] = b->next;
    --counts_[c];
    return b;
  }
  //! Keeps block p of class c; false when the class is full or the owner
  //! no longer takes blocks back (the caller frees it).
  bool keep(void* p, int c) noexcept {
    if (!open_ || counts_[c] == kept) return false;
    heads_[c] = ::new (p) free_block{heads_[c]};
    ++counts_[c];
    return true;
  }

  //! Frees every kept block and takes none back from now on (the context
  //! is being destroyed).
  void close() noexcept {
    open_ = false;
    release();
  }

 private:
  // A freed block holds the link to the next; the smallest block (one
  // handle, 16 bytes) has room for it.
  struct free_block {
    free_block* next;
  };

  void release() noexcept {
    for (std::size_t c = 0; c < classes; ++c) {
      while (free_block* b = heads_[c]) {
        heads_[c] = b->next;
        ::operator delete(b);
      }
      counts_[c] = 0;
    }
  }

  free_block* heads_[classes] = {};
  unsigned counts_[classes] = {};
  bool open_ = true;
};

}  // namespace vv::detail
