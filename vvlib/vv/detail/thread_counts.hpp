// Reference counts kept apart per thread while a parallel loop runs.
//
// A handle copied on two threads at once would lose one of two plain
// increments of the shared count, and atomic increments cost tens of
// cycles each (a loop body copies a handle per neighbour it visits). So
// each thread of a loop adds its changes to a table of its own, found
// through a thread-local pointer, and the context adds the tables to its
// counts when the loop ends. The collector is paused meanwhile, so no
// count needs to be right before then. A table is a delta per slot and a
// byte per block of slots that says the block was touched: adding the
// tables up costs the blocks touched, not the whole context.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace vv::detail {

//! The table the current thread counts into (inside a parallel loop).
struct thread_counts {
  static constexpr unsigned block_bits = 8;
  std::int32_t* delta = nullptr;  // by slot
  unsigned char* touched = nullptr;  // by block of 2^block_bits slots
  void change(std::uint32_t id, std::int32_t by) noexcept {
    delta[id] += by;
    touched[id >> block_bits] = 1;
  }
};

//! Set on each thread of a parallel loop while it runs iterations.
//! Initial-exec: a model is a dlopen'd library, where the default model
//! makes every access a call to __tls_get_addr (it doubled the CPU time of
//! a smoothing loop on 2 threads); 16 bytes fit glibc's static TLS surplus.
inline thread_local thread_counts this_thread_counts __attribute__((tls_model("initial-exec")));

//! The tables of one context's loop threads; kept (all zero) between loops.
class thread_count_tables {
 public:
  //! Room for `threads` tables over `slots` slots.
  void prepare(std::size_t threads, std::size_t slots) {
    const std::size_t blocks = (slots >> thread_counts::block_bits) + 1;
    if (tables_.size() < threads) tables_.resize(threads);
    for (table& t : tables_) {
      if (t.delta.size() < blocks << thread_counts::block_bits) t.delta.resize(blocks << thread_counts::block_bits, 0);
      if (t.touched.size() < blocks) t.touched.resize(blocks, 0);
    }
    if (union_.size() < blocks) union_.resize(blocks, 0);
  }
  //! Makes table `thread` the calling thread's (prepare first).
  void bind(std::size_t thread) noexcept {
    this_thread_counts = {tables_[thread].delta.data(), tables_[thread].touched.data()};
  }
  static void unbind() noexcept { this_thread_counts = {}; }

  //! Adds every table to counts and zeroes it. on_zero() is called once for
  //! each slot whose count changed and ends at zero, whatever the threads'
  //! share of the changes was.
  template <class OnZero>
  void merge(std::uint32_t* counts, OnZero&& on_zero) noexcept {
    for (table& t : tables_)
      for (std::size_t b = 0; b < t.touched.size(); ++b) union_[b] |= t.touched[b];
    for (std::size_t b = 0; b < union_.size(); ++b) {
      if (!union_[b]) continue;
      union_[b] = 0;
      const std::size_t first = b << thread_counts::block_bits, last = first + (std::size_t(1) << thread_counts::block_bits);
      for (std::size_t id = first; id < last; ++id) {
        std::int32_t sum = 0;
        for (table& t : tables_)
          if (b < t.touched.size() && t.touched[b]) sum += t.delta[id], t.delta[id] = 0;
        if (sum == 0) continue;
        counts[id] += static_cast<std::uint32_t>(sum);
        if (counts[id] == 0) on_zero();
      }
      for (table& t : tables_)
        if (b < t.touched.size()) t.touched[b] = 0;
    }
  }

 private:
  struct table {
    std::vector<std::int32_t> delta;
    std::vector<unsigned char> touched;
  };
  std::vector<table> tables_;
  std::vector<unsigned char> union_;
};

}  // namespace vv::detail
