// Runs of memory on 2 MiB boundaries, marked for transparent huge pages.
//
// A subdivision step that makes 600,000 vertices writes some 60 MB of new
// storage (blocks of vertices, counts, labels, member lists). In 4 KiB
// pages that is one page fault per 4 KiB, a third of the step's time on a
// virtual machine, and the reads that follow miss the TLB. Mapped in runs
// of 2 MiB marked MADV_HUGEPAGE, where the kernel offers transparent huge
// pages ("madvise" or "always"), each run is one page and one fault.
//
// Small storage stays on the heap, so a small model holds no 2 MiB page;
// so does all of it where the kernel offers no huge pages, and under
// AddressSanitizer, so that every block is checked.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#ifndef VV_STORAGE_IN_RUNS
#if defined(__SANITIZE_ADDRESS__) || !defined(__linux__)
#define VV_STORAGE_IN_RUNS 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define VV_STORAGE_IN_RUNS 0
#endif
#endif
#endif
#ifndef VV_STORAGE_IN_RUNS
#define VV_STORAGE_IN_RUNS 1
#endif

namespace vv::detail {

//! A run's alignment, and the size of a huge page on x86-64 (and on
//! AArch64 with 4 KiB pages).
inline constexpr std::size_t run_bytes = std::size_t{2} << 20;

//! True where the kernel backs memory marked MADV_HUGEPAGE with huge
//! pages. Where it does not, runs would only be ordinary pages mapped and
//! unmapped anew each time, slower than the heap, which reuses its pages.
inline bool huge_pages_offered() noexcept {
#if VV_STORAGE_IN_RUNS
  static const bool offered = [] {
    std::FILE* f = std::fopen("/sys/kernel/mm/transparent_hugepage/enabled", "r");
    if (!f) return false;
    char text[128] = {};
    const std::size_t n = std::fread(text, 1, sizeof text - 1, f);
    std::fclose(f);
    text[n] = 0;
    return std::strstr(text, "[always]") != nullptr || std::strstr(text, "[madvise]") != nullptr;
  }();
  return offered;
#else
  return false;
#endif
}

//! `bytes` rounded up to whole runs.
constexpr std::size_t whole_runs(std::size_t bytes) noexcept {
  return (bytes + run_bytes - 1) / run_bytes * run_bytes;
}

//! `size` bytes of zeroed memory (whole runs) on a run_bytes boundary.
//! Throws std::bad_alloc.
inline void* map_run(std::size_t size) {
#if defined(__linux__)
  if (size > ~std::size_t{0} - 2 * run_bytes) throw std::bad_alloc();
  // Map a run more than asked and give back what lies outside the boundary.
  void* raw = ::mmap(nullptr, size + run_bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const auto low = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t start = (low + run_bytes - 1) / run_bytes * run_bytes;
  const std::uintptr_t high = low + size + run_bytes;
  if (start > low) (void)::munmap(raw, start - low);
  if (high > start + size) (void)::munmap(reinterpret_cast<void*>(start + size), high - (start + size));
#if defined(MADV_HUGEPAGE)
  // Advice only: refused or ignored, the run is ordinary pages.
  (void)::madvise(reinterpret_cast<void*>(start), size, MADV_HUGEPAGE);
#endif
  return reinterpret_cast<void*>(start);
#else
  (void)size;
  throw std::bad_alloc();  // no runs without mmap
#endif
}

//! `bytes` from operator new, aligned to `align` (a power of two); the
//! plain form where it aligns enough, so that a replaced operator new sees
//! every block.
inline void* heap_block(std::size_t bytes, std::size_t align) {
  if (align <= __STDCPP_DEFAULT_NEW_ALIGNMENT__) return ::operator new(bytes);
  return ::operator new(bytes, std::align_val_t(align));
}
inline void free_heap_block(void* p, std::size_t align) noexcept {
  if (align <= __STDCPP_DEFAULT_NEW_ALIGNMENT__) ::operator delete(p);
  else ::operator delete(p, std::align_val_t(align));
}

//! Gives back a run of map_run.
inline void unmap_run(void* start, std::size_t size) noexcept {
#if defined(__linux__)
  (void)::munmap(start, size);
#else
  (void)start;
  (void)size;
#endif
}

}  // namespace vv::detail
