// context::block_scope: while a translated program's block runs, handles on
// its stack below the block's frame hold no count and the collector waits
// for the block's end; handles anywhere else are counted as always.
#include <gtest/gtest.h>

#include <cstdint>
#include <thread>
#include <utility>
#include <vector>

#include <vv/detail/thread_stack.hpp>
#include <vv/vv.hpp>

namespace {

struct block_props {
  double x = 0;
};
using block_graph = vv::graph<block_props>;
using block_vertex = block_graph::vertex;

// Runs fn as a block, as model/program.hpp runs one: the scope's frame is
// this function's, so the caller's handles are above it.
template <class Fn>
[[gnu::noinline]] void run_as_block(block_graph::context& ctx, Fn&& fn) {
  block_graph::context::block_scope block(ctx, vv::detail::thread_stack_low(), __builtin_frame_address(0));
  fn();
}

// Whether a local at `at` is on this thread's stack (not on the heap, where
// AddressSanitizer puts locals when it checks uses after return): only
// there does a block leave handles uncounted.
bool on_this_stack(const void* at) {
  const auto a = reinterpret_cast<std::uintptr_t>(at);
  // Within a MiB above this frame: the test's own frames.
  const auto frame = reinterpret_cast<std::uintptr_t>(__builtin_frame_address(0));
  return a >= vv::detail::thread_stack_low() && a < frame + (std::uintptr_t(1) << 20);
}

}  // namespace

TEST(BlockScope, TheThreadsStackIsKnown) {
  const std::uintptr_t low = vv::detail::thread_stack_low();
  ASSERT_NE(low, 0u);
  EXPECT_LT(low, reinterpret_cast<std::uintptr_t>(__builtin_frame_address(0)));
  vv::detail::thread_stack_cache cache;
  EXPECT_EQ(cache.low(), low);
  std::uintptr_t other = 0;
  std::thread([&] { other = cache.low(); }).join();
  EXPECT_NE(other, 0u);
  EXPECT_NE(other, low) << "asked again on another thread";
  EXPECT_EQ(cache.low(), low);
}

TEST(BlockScope, HandlesOnTheBlocksStackHoldNoCountAndOthersDo) {
  block_graph::context ctx;
  block_graph::mesh M(ctx);
  block_vertex kept = ctx.new_vertex();
  M.add(kept);
  const std::uint32_t id = kept.slot();
  ASSERT_EQ(ctx.refs(id), 2u);  // the handle and the membership
  run_as_block(ctx, [&] {
    block_vertex copy = kept;
    if (!on_this_stack(&copy)) GTEST_SKIP() << "locals are not on the thread's stack here";
    block_vertex assigned;
    assigned = copy;
    block_vertex moved = std::move(copy);
    EXPECT_EQ(ctx.refs(id), 2u) << "the block's own handles";
    std::vector<block_vertex> held{kept, assigned};
    EXPECT_EQ(ctx.refs(id), 4u) << "a vector's handles are on the heap";
    // A counted handle moved onto the stack keeps its count until it goes.
    {
      block_vertex taken = std::move(held[0]);
      EXPECT_EQ(ctx.refs(id), 4u);
    }
    EXPECT_EQ(ctx.refs(id), 3u);
    EXPECT_TRUE(moved == kept && assigned == kept);
  });
  EXPECT_EQ(ctx.refs(id), 2u);
}

TEST(BlockScope, AHandleOutsideTheBlockAssignedInsideItIsCounted) {
  block_graph::context ctx;
  block_vertex outer;
  run_as_block(ctx, [&] {
    block_vertex made = ctx.new_vertex();
    made->x = 3;
    outer = made;
  });
  ASSERT_TRUE(outer);
  EXPECT_EQ(ctx.refs(outer.slot()), 1u);
  EXPECT_EQ(ctx.collect_garbage(), 0u);
  EXPECT_EQ(outer->x, 3);
}

TEST(BlockScope, HandlesOnAnotherThreadsStackAreCounted) {
  block_graph::context ctx;
  block_vertex kept = ctx.new_vertex();
  const std::uint32_t id = kept.slot();
  std::uint32_t seen = 0;
  run_as_block(ctx, [&] {
    std::thread other([&] {
      block_vertex copy = kept;
      seen = ctx.refs(id);
    });
    other.join();
  });
  EXPECT_EQ(seen, 2u);
  EXPECT_EQ(ctx.refs(id), 1u);
}

TEST(BlockScope, TheCollectorWaitsForTheBlocksEndAndThenFreesItsGarbage) {
  block_graph::context ctx;
  block_graph::mesh M(ctx);
  M.add(ctx.new_vertex());
  run_as_block(ctx, [&] {
    // Held by this stack alone, through more garbage than a pass waits for.
    block_vertex only = ctx.new_vertex();
    only->x = 7;
    for (int i = 0; i < 40000; ++i) {
      block_vertex garbage = ctx.new_vertex();
      garbage->x = i;
    }
    EXPECT_EQ(ctx.collect_garbage(), 0u) << "no pass inside a block";
    EXPECT_TRUE(ctx.is_live(only.slot()));
    EXPECT_EQ(only->x, 7);
    EXPECT_EQ(ctx.live_vertices(), 40002u);
  });
  // The vertices the block made and nothing holds are the pass's suspects.
  ctx.collect_if_due();
  EXPECT_EQ(ctx.live_vertices(), 1u);
}

TEST(BlockScope, NestedBlocksCollectOnlyAtTheOutermostEnd) {
  block_graph::context ctx;
  run_as_block(ctx, [&] {
    block_vertex only = ctx.new_vertex();
    run_as_block(ctx, [&] {
      for (int i = 0; i < 40000; ++i) block_vertex garbage = ctx.new_vertex();
    });
    ctx.collect_if_due();
    EXPECT_TRUE(ctx.is_live(only.slot())) << "the outer block's stack still holds it";
    if (on_this_stack(&only)) {
      EXPECT_EQ(ctx.refs(only.slot()), 0u);
    }
  });
  ctx.collect_if_due();
  EXPECT_EQ(ctx.live_vertices(), 0u);
}
