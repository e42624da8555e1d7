#pragma once
// Heap bytes currently allocated through glibc malloc, used to attribute
// memory to a mesh structure by taking a difference around its lifetime.
#include <cstddef>
#include <malloc.h>

inline std::size_t heap_in_use()
{
  const struct mallinfo2 info = mallinfo2();
  // uordblks: arena chunks in use; hblkhd: large blocks served by mmap.
  return info.uordblks + info.hblkhd;
}
