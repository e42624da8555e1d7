// The engine of parallel loops (vv/parallel.hpp) and of a large
// synchronise: runs a function over positions 0..n-1 on the context's
// threads, with OpenMP.
//
// Results do not depend on the threads: each position's work must touch
// only its own vertex (the rules of LANGUAGE.md section 6.1), positions are
// handed out in blocks to whichever thread is free, and when positions
// fail the error of the first of them (in position order) is the one
// reported, as a run in order would report it. Without OpenMP (a C++
// user's build without -fopenmp) every loop runs in order.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "../vertex.hpp"
#include "run_allocator.hpp"

namespace vv::detail {

//! The machine's cores (the default thread count).
inline unsigned machine_threads() noexcept {
  unsigned n = std::thread::hardware_concurrency();
  return n ? n : 1;
}

//! Positions handed to a thread at a time.
constexpr std::size_t parallel_block = 1024;

//! The fewest iterations per thread worth starting threads for: smaller
//! loops run in order on the calling thread, as starting the others would
//! cost more than they save. 512, or VV_PARALLEL_GRAIN from the
//! environment (the tests set 1 to run the examples' small loops on every
//! thread).
inline std::size_t parallel_grain() {
  static const std::size_t grain = [] {
    const char* text = std::getenv("VV_PARALLEL_GRAIN");
    const long n = text ? std::atol(text) : 0;
    return n > 0 ? static_cast<std::size_t>(n) : std::size_t(512);
  }();
  return grain;
}

//! Threads a loop of n positions on ctx uses: 1 inside another loop, in
//! strict mode, without OpenMP, and when the loop copies handles
//! (copies_handles) in a model without parallel loops (Tr::parallel_loops);
//! fewer for a loop of fewer than parallel_grain() (times grain_factor)
//! positions per thread.
template <class Tr>
unsigned team_size(const context<Tr>& ctx, std::size_t n, std::size_t grain_factor = 1, bool copies_handles = true) {
#ifdef _OPENMP
  if (ctx.parallel_loop() || ctx.strict_parallel) return 1;
  if (copies_handles && !Tr::parallel_loops) return 1;
  std::size_t t = ctx.threads ? ctx.threads : machine_threads();
  t = std::min(t, std::max<std::size_t>(1, n / (parallel_grain() * grain_factor)));
  return static_cast<unsigned>(t);
#else
  (void)ctx, (void)n, (void)grain_factor, (void)copies_handles;
  return 1;
#endif
}

//! The failure of the first position (in order) that failed.
class first_failure {
 public:
  //! Positions after a known failure need not run.
  bool after_failure(std::size_t pos) const noexcept { return pos > at_.load(std::memory_order_relaxed); }
  void record(std::size_t pos, std::exception_ptr e) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (pos < at_.load(std::memory_order_relaxed)) {
      at_.store(pos, std::memory_order_relaxed);
      error_ = std::move(e);
    }
  }
  void rethrow() const {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  std::atomic<std::size_t> at_{std::numeric_limits<std::size_t>::max()};
  std::mutex mutex_;
  std::exception_ptr error_;
};

//! The context in a parallel scope for the life of this object.
template <class Tr>
class parallel_scope {
 public:
  parallel_scope(context<Tr>& ctx, parallel_loop& loop) noexcept : ctx_(ctx) { ctx.begin_parallel(loop); }
  parallel_scope(const parallel_scope&) = delete;
  parallel_scope& operator=(const parallel_scope&) = delete;
  ~parallel_scope() { ctx_.end_parallel(); }

 private:
  context<Tr>& ctx_;
};

//! Runs visit(pos, thread) for every pos in [0, n) on `team` threads
//! (thread < team), in a parallel scope the caller has entered. Counts
//! are kept apart meanwhile, unless visit copies no handle
//! (copies_handles false); the first failure is thrown again after.
template <class Tr, class Visit>
void run_on_team(context<Tr>& ctx, std::size_t n, unsigned team, Visit&& visit, bool copies_handles = true) {
#ifdef _OPENMP
  const bool apart = Tr::parallel_loops && copies_handles;
  if (apart) ctx.count_apart(team);
  first_failure failure;
  const std::ptrdiff_t blocks = static_cast<std::ptrdiff_t>((n + parallel_block - 1) / parallel_block);
#pragma omp parallel num_threads(team)
  {
    const unsigned thread = static_cast<unsigned>(omp_get_thread_num());
    if (apart) ctx.thread_count_tables().bind(thread);
#pragma omp for schedule(dynamic, 1)
    for (std::ptrdiff_t b = 0; b < blocks; ++b) {
      const std::size_t first = static_cast<std::size_t>(b) * parallel_block;
      const std::size_t last = std::min(n, first + parallel_block);
      for (std::size_t pos = first; pos < last && !failure.after_failure(pos); ++pos) {
        try {
          visit(pos, thread);
        } catch (...) {
          failure.record(pos, std::current_exception());
          break;
        }
      }
    }
    thread_count_tables::unbind();
  }
  if (apart) ctx.merge_thread_counts();
  failure.rethrow();
#else
  (void)team, (void)ctx, (void)copies_handles;
  for (std::size_t pos = 0; pos < n; ++pos) visit(pos, 0u);
#endif
}

//! Vertex id's properties and records changed in strict mode's watch:
//! the error, at the first use.
template <class Tr>
void check_strict_iteration(context<Tr>& ctx, const parallel_loop& loop, std::vector<unsigned char>& now) {
  for (const strict_watch::use* u = loop.strict->begin_uses(); u != loop.strict->end_uses(); ++u) {
    ctx.snapshot(u->id, now);
    if (now == u->before) continue;
    throw error(u->at, "parallel forall",
                "vertex " + std::to_string(ctx.label(u->id)) + " was changed by the iteration of vertex " +
                    std::to_string(ctx.label(loop.strict->own())) + " of " + loop_name(loop) +
                    ", which may change only the properties of its own vertex (strict mode; first used here)");
  }
}

//! The loop over a mesh's member slots: fn(vertex, thread) for each
//! member, thread < team (see team_size). Inside another parallel loop it
//! runs in order under that loop's rules; in strict mode in order, each
//! iteration checked.
template <class Tr, class Fn>
void for_each_member(context<Tr>& ctx, const slot_list& slots, unsigned team, const where& w,
                     Fn&& fn) {
  const std::size_t n = slots.size();
  if (ctx.parallel_loop()) {
    for (std::size_t pos = 0; pos < n; ++pos)
      if (std::uint32_t id = slots[pos]) fn(vertex<Tr>::borrowed(&ctx, id), 0u);
    return;
  }
  parallel_loop loop{w};
  if (ctx.strict_parallel) {
    strict_watch watch;
    loop.strict = &watch;
    parallel_scope<Tr> scope(ctx, loop);
    ctx.watch_props(true);
    std::vector<unsigned char> now;
    for (std::size_t pos = 0; pos < n; ++pos) {
      std::uint32_t id = slots[pos];
      if (!id) continue;
      watch.begin(id);
      fn(vertex<Tr>::borrowed(&ctx, id), 0u);
      check_strict_iteration(ctx, loop, now);
    }
    return;
  }
  parallel_scope<Tr> scope(ctx, loop);
  if (team <= 1) {
    for (std::size_t pos = 0; pos < n; ++pos)
      if (std::uint32_t id = slots[pos]) fn(vertex<Tr>::borrowed(&ctx, id), 0u);
    return;
  }
  run_on_team(ctx, n, team, [&](std::size_t pos, unsigned thread) {
    if (std::uint32_t id = slots[pos]) fn(vertex<Tr>::borrowed(&ctx, id), thread);
  });
}

//! synchronise: the old state of every member made a copy of its current
//! one, on the context's threads when the mesh is large.
template <class Tr>
void synchronise_members(context<Tr>& ctx, const slot_list& slots) {
  auto copy = [&](std::uint32_t id) {
    ctx.writable_old_nb(id) = ctx.nb(id);
    ctx.writable_old_props(id) = ctx.props(id);
  };
  // A copy is cheap: it takes more of them to be worth a thread. Copying
  // properties and records of plain data copies no handle: no count
  // changes, so it may be shared out in any model.
  using Props = typename Tr::vertex_props;
  using Records = typename Tr::edge_props;
  constexpr bool plain = std::is_trivially_copyable<Props>::value && std::is_trivially_copyable<Records>::value;
  const unsigned team = team_size(ctx, slots.size(), 8, !plain);
  if (team <= 1) {
    for (std::uint32_t id : slots)
      if (id) copy(id);
    return;
  }
  // The old blocks are made first, in order: making one is not thread-safe.
  for (std::uint32_t id : slots)
    if (id) ctx.make_old_state(id);
  parallel_loop loop{where{}};
  parallel_scope<Tr> scope(ctx, loop);
  run_on_team(
      ctx, slots.size(), team,
      [&](std::size_t pos, unsigned) {
        if (std::uint32_t id = slots[pos]) copy(id);
      },
      !plain);
}

}  // namespace vv::detail
