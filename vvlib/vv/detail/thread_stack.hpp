// Where the calling thread's stack begins, for context::block_scope: the
// handles a block makes on its own stack hold no count.
#pragma once

#include <cstdint>

#if defined(__linux__)
#include <pthread.h>
#endif

namespace vv::detail {

//! The lowest address of the calling thread's stack; 0 where unknown (no
//! handle then goes uncounted). Asked once per thread: for the main thread
//! the C library reads the process's memory map.
inline std::uintptr_t thread_stack_low() noexcept {
#if defined(__linux__)
  static thread_local const std::uintptr_t low = [] {
    pthread_attr_t attr;
    if (pthread_getattr_np(pthread_self(), &attr) != 0) return std::uintptr_t(0);
    void* addr = nullptr;
    std::size_t size = 0;
    const bool known = pthread_attr_getstack(&attr, &addr, &size) == 0 && size != 0;
    pthread_attr_destroy(&attr);
    return known ? reinterpret_cast<std::uintptr_t>(addr) : std::uintptr_t(0);
  }();
  return low;
#else
  return 0;
#endif
}

}  // namespace vv::detail
