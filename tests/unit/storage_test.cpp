// Pooled storage and lifetime: no heap allocation per vertex or per
// neighbourhood in the common case, freed vertices are reused, long chains
// of garbage are collected without recursion, contexts are independent.
//
// This executable replaces the global operator new to count allocations.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include <vv/vv.hpp>

namespace {
std::atomic<std::size_t> allocations{0};
}  // namespace

void* operator new(std::size_t n) {
  ++allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
// Not inlined: where GCC sees free() called on what the (not inlined)
// operator new returned, it warns of a mismatched pair (at -O1).
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace {

struct props {
  double x = 0;
};
using graph = vv::graph<props>;
using vertex = graph::vertex;

}  // namespace

TEST(Storage, CreatingVerticesWithSmallNeighbourhoodsDoesNotAllocatePerVertex) {
  graph::context ctx;
  graph::mesh M(ctx);
  std::vector<vertex> ring;
  ring.reserve(20000);
  for (int i = 0; i < 20000; ++i) ring.push_back(ctx.new_vertex());
  M.add(ring[0]);  // the set's first tables
  const std::size_t before = allocations;
  for (int i = 0; i < 20000; ++i) {
    vertex v = ring[std::size_t(i)];
    // Six neighbours, as in a triangle mesh; then an edit of each kind.
    vv::make_nb(v, {ring[std::size_t((i + 1) % 20000)], ring[std::size_t((i + 2) % 20000)],
                    ring[std::size_t((i + 3) % 20000)], ring[std::size_t((i + 4) % 20000)],
                    ring[std::size_t((i + 5) % 20000)], ring[std::size_t((i + 6) % 20000)]});
    vv::erase_from(ring[std::size_t((i + 6) % 20000)], v);
    vv::splice_after(ring[std::size_t((i + 7) % 20000)], ring[std::size_t((i + 1) % 20000)], v);
    M.add(v);
  }
  vv::synchronise(M);
  const std::size_t used = allocations - before;
  // Only the set's tables grow (geometrically): a few dozen blocks at most.
  EXPECT_LT(used, 64u) << used << " allocations for 20000 vertices";
}

TEST(Storage, CreatingVerticesAllocatesOnlyWholeChunks) {
  graph::context ctx;
  const std::size_t before = allocations;
  std::vector<vertex> keep;
  keep.reserve(100000);
  const std::size_t after_reserve = allocations;
  for (int i = 0; i < 100000; ++i) keep.push_back(ctx.new_vertex());
  const std::size_t chunks = (100000 + graph::context::chunk_size) / graph::context::chunk_size;
  // One block per chunk, plus the geometric growth of the chunk table and
  // of the count and label arrays.
  EXPECT_LE(allocations - after_reserve, chunks + 48);
  EXPECT_GE(allocations - before, 1u);
}

TEST(Storage, LargeNeighbourhoodsSpillAndComeBack) {
  graph::context ctx;
  vertex hub = ctx.new_vertex();
  std::vector<vertex> spokes;
  for (int i = 0; i < 100; ++i) spokes.push_back(ctx.new_vertex());
  vv::make_nb(hub, {spokes[0]});
  for (int i = 1; i < 100; ++i) vv::splice_after(spokes[std::size_t(i)], spokes[std::size_t(i - 1)], hub);
  EXPECT_EQ(vv::valence(hub), 100u);
  for (int i = 0; i < 100; ++i)
    EXPECT_EQ(vv::next_to(spokes[std::size_t(i)], hub), spokes[std::size_t((i + 1) % 100)]);
  vv::flag_in(spokes[50], hub);
  for (int i = 99; i >= 3; --i)
    if (i != 50) vv::erase_from(spokes[std::size_t(i)], hub);
  EXPECT_EQ(vv::valence(hub), 4u);
  EXPECT_EQ(vv::flagged_in(hub), spokes[50]);
  EXPECT_EQ(vv::next_to(spokes[2], hub), spokes[50]);
  EXPECT_EQ(vv::next_to(spokes[50], hub), spokes[0]);
}

TEST(Storage, FreedSlotsAreReused) {
  graph::context ctx;
  for (int i = 0; i < 1000000; ++i) {
    vertex a = ctx.new_vertex(), b = ctx.new_vertex();
    vv::make_nb(a, {b});
    vv::make_nb(b, {a});  // a two-vertex cycle, garbage once a and b go
  }
  ctx.collect_garbage();
  EXPECT_EQ(ctx.live_vertices(), 0u);
  // Collection ran along the way, so the pool stayed far below 2 million.
  EXPECT_LT(ctx.slot_count(), 200000u);
}

TEST(Storage, LongGarbageChainsAreCollectedWithoutRecursion) {
  graph::context ctx;
  {
    vertex head = ctx.new_vertex();
    vertex prev = head;
    for (int i = 0; i < 300000; ++i) {
      vertex next = ctx.new_vertex();
      vv::make_nb(prev, {next});
      prev = next;
    }
    ctx.collect_garbage();
    EXPECT_EQ(ctx.live_vertices(), 300001u);  // all reachable from head
  }
  EXPECT_EQ(ctx.collect_garbage(), 300001u);
  EXPECT_EQ(ctx.live_vertices(), 0u);
}

TEST(Storage, LabelsKeepIncreasingWhenSlotsAreReused) {
  graph::context ctx;
  unsigned last = 0;
  for (int round = 0; round < 3; ++round) {
    for (int i = 0; i < 5000; ++i) {
      vertex v = ctx.new_vertex();
      EXPECT_GT(v.label(), last);
      last = v.label();
    }
    ctx.collect_garbage();
  }
  EXPECT_EQ(last, 15000u);
}

TEST(Storage, ContextsAreIndependent) {
  graph::context a, b;
  vertex x = a.new_vertex(), y = a.new_vertex();
  vertex z = b.new_vertex();
  EXPECT_EQ(x.label(), 1u);
  EXPECT_EQ(y.label(), 2u);
  EXPECT_EQ(z.label(), 1u);  // labels are per model, not per process
  EXPECT_EQ(a.live_vertices(), 2u);
  EXPECT_EQ(b.live_vertices(), 1u);
  EXPECT_THROW(vv::make_nb(x, {z}), vv::error);  // no mixing of models
  graph::mesh M(a);
  EXPECT_THROW(M.add(z), vv::error);
}

// Old state is kept per chunk of vertices, made when one of its vertices is
// first synchronised: vertices never synchronised (those a subdivision step
// just created) cost none.
TEST(Storage, OldStateIsStoredOnlyForChunksWithSynchronisedVertices) {
  graph::context ctx;
  const std::uint32_t per_chunk = graph::context::chunk_size;
  std::vector<vertex> vs;
  for (std::uint32_t i = 0; i < 3 * per_chunk; ++i) vs.push_back(ctx.new_vertex());
  graph::mesh first(ctx), second(ctx), again(ctx);
  first.add(vs[1]);
  second.add(vs[2 * per_chunk]);
  again.add(vs[2]);  // in the chunk of vs[1]

  const std::size_t before = ctx.storage_bytes();
  vv::synchronise(first);
  const std::size_t one_block = ctx.storage_bytes() - before;
  EXPECT_GE(one_block, per_chunk * (sizeof(props) + 8)) << "the chunk's old properties and neighbourhoods";
  vv::synchronise(again);
  EXPECT_EQ(ctx.storage_bytes() - before, one_block) << "the same chunk needs no second block";
  vv::synchronise(second);
  EXPECT_EQ(ctx.storage_bytes() - before, 2 * one_block);
}

// A vertex of a chunk that has old state but was not synchronised itself
// still reads as never synchronised: an empty neighbourhood and
// value-initialised properties, and so does a freed and reused slot.
TEST(Storage, UnsynchronisedVerticesBesideSynchronisedOnesReadAsNeverSynchronised) {
  graph::context ctx;
  graph::mesh M(ctx);
  vertex a = ctx.new_vertex(), b = ctx.new_vertex(), c = ctx.new_vertex();
  a->x = 1;
  vv::make_nb(a, {b});
  M.add(a);
  vv::synchronise(M);
  EXPECT_TRUE(vv::old(a).synchronised());
  EXPECT_EQ(vv::old(a).props().x, 1);
  EXPECT_EQ(vv::valence(vv::old(a)), 1u);
  c->x = 5;
  EXPECT_FALSE(vv::old(c).synchronised());
  EXPECT_EQ(vv::old(c).props().x, 0);
  EXPECT_EQ(vv::valence(vv::old(c)), 0u);

  // Free a (its slot keeps the chunk's old block) and reuse the slot.
  M.clear();
  a = vertex();
  b = vertex();
  EXPECT_EQ(ctx.collect_garbage(), 2u);
  vertex reused = ctx.new_vertex();
  EXPECT_FALSE(vv::old(reused).synchronised());
  EXPECT_EQ(vv::old(reused).props().x, 0);
  EXPECT_EQ(vv::valence(vv::old(reused)), 0u);
}
