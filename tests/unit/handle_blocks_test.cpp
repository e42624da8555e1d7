// Vectors of handles (vv/handle_vector.hpp) and their recycled storage
// (vv/detail/handle_blocks.hpp): a vector of vertices is a standard vector
// whose first push makes room for four; a translated program's vectors
// reuse freed blocks of 1, 2, 4 and 8 handles; other sizes, other traits
// and parallel loops use the heap; the handles stay counted right
// throughout; a context's destruction frees what it kept.
//
// The recycling is turned on here even under AddressSanitizer (where the
// library leaves it off), so that the sanitizer build checks its logic too.
// This executable replaces the global operator new and delete to count
// the blocks in use.
#define VV_RECYCLE_HANDLE_BLOCKS 1

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#include <vv/vv.hpp>

namespace {
std::atomic<long> blocks_in_use{0};
std::atomic<long> blocks_made{0};
}  // namespace

void* operator new(std::size_t n) {
  if (void* p = std::malloc(n ? n : 1)) {
    ++blocks_in_use;
    ++blocks_made;
    return p;
  }
  throw std::bad_alloc();
}
// Not inlined: where GCC sees free() called on what the (not inlined)
// operator new returned, it warns of a mismatched pair (at -O1).
[[gnu::noinline]] void operator delete(void* p) noexcept {
  if (p) --blocks_in_use;
  std::free(p);
}
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept {
  if (p) --blocks_in_use;
  std::free(p);
}

namespace {

struct props {
  double value = 0;
  // A wall of handles in the properties, as a tissue model's cells have.
  std::vector<vv::vertex<struct model_traits>> wall;
};

// As vvc writes a translated program's traits: they name the one context.
struct model_traits : vv::traits<props> {
  static vv::context<model_traits>& context();
};
// A translated program's context is a global object, which its traits
// still name while it is destroyed (its properties' vectors are freed
// then): so is this one, until its destructor has returned.
vv::context<model_traits>* the_context = nullptr;
vv::context<model_traits>& model_traits::context() { return *the_context; }
void make_context() { the_context = new vv::context<model_traits>(); }
void destroy_context() {
  delete the_context;
  the_context = nullptr;
}

using vertex = vv::vertex<model_traits>;
using mesh = vv::mesh<model_traits>;

// Each test gets a fresh model context.
class HandleBlocks : public ::testing::Test {
 protected:
  void SetUp() override { make_context(); }
  void TearDown() override { destroy_context(); }
  vv::context<model_traits>& ctx() { return *the_context; }
};

static_assert(vv::detail::has_default_context<model_traits>::value);
static_assert(!vv::detail::has_default_context<vv::traits<props>>::value);

TEST_F(HandleBlocks, AFreedBlockOfEachRecycledSizeIsHandedOutAgain) {
  vertex v = ctx().new_vertex();
  for (std::size_t n : {1u, 2u, 4u, 8u}) {
    const vertex* first;
    {
      std::vector<vertex> corners(n, v);
      first = corners.data();
    }
    const long made = blocks_made;
    std::vector<vertex> again(n, v);
    EXPECT_EQ(again.data(), first) << n << " handles";
    EXPECT_EQ(blocks_made, made) << "a vector of " << n << " handles came from the heap";
  }
}

TEST_F(HandleBlocks, AGrowingVectorOfHandlesReachesTheHeapOnlyBeyondEight) {
  vertex v = ctx().new_vertex();
  {
    // The first time, each size comes from the heap once.
    std::vector<vertex> corners;
    for (int i = 0; i < 8; ++i) corners.push_back(v);
  }
  const long made = blocks_made;
  for (int round = 0; round < 100; ++round) {
    std::vector<vertex> corners;
    for (int i = 0; i < 8; ++i) corners.push_back(v);
  }
  EXPECT_EQ(blocks_made, made);
  std::vector<vertex> longer(9, v);
  EXPECT_EQ(blocks_made, made + 1);
}

TEST_F(HandleBlocks, TheFirstPushMakesRoomForFourHandlesFromAKeptBlock) {
  vertex v = ctx().new_vertex();
  const vertex* kept;
  {
    std::vector<vertex> corners(4, v);
    kept = corners.data();
  }
  const long made = blocks_made;
  std::vector<vertex> pushed;
  EXPECT_EQ(pushed.capacity(), 0u);  // an empty vector holds no block
  pushed.push_back(v);
  EXPECT_EQ(pushed.capacity(), 4u);
  EXPECT_EQ(pushed.data(), kept);
  EXPECT_EQ(blocks_made, made);
  for (int i = 0; i < 3; ++i) pushed.push_back(v);
  EXPECT_EQ(pushed.data(), kept) << "four handles fit without moving";
  EXPECT_EQ(pushed.size(), 4u);

  std::vector<vertex> emplaced;
  emplaced.emplace_back(v);
  EXPECT_EQ(emplaced.capacity(), 4u);
  std::vector<vertex> moved_in;
  moved_in.push_back(vertex(v));
  EXPECT_EQ(moved_in.capacity(), 4u);
  EXPECT_EQ(ctx().refs(v.slot()), 1u + 4u + 1u + 1u);  // v and the three vectors
}

TEST_F(HandleBlocks, AVectorOfHandlesIsAStandardVector) {
  using vector = std::vector<vertex>;
  // Its allocator rebinds to itself, so the vector's blocks are recycled.
  static_assert(std::is_same<std::allocator_traits<vector::allocator_type>::rebind_alloc<vertex>,
                             vector::allocator_type>::value);
  static_assert(std::is_same<vector::value_type, vertex>::value);
  static_assert(std::is_nothrow_move_constructible<vector>::value);
  vertex a = ctx().new_vertex(), b = ctx().new_vertex(), c = ctx().new_vertex();
  vector list{a, b};
  std::vector deduced{a, b};  // deduced as std::vector<vertex>
  static_assert(std::is_same<decltype(deduced), vector>::value);
  EXPECT_EQ(list, deduced);
  list.insert(list.begin() + 1, c);
  EXPECT_EQ(list, (vector{a, c, b}));
  EXPECT_NE(list, deduced);
  EXPECT_TRUE(deduced < list);  // a = a, then b (label 2) < c (label 3)
  list.erase(list.begin());
  EXPECT_EQ(list, (vector{c, b}));
  vector copy = list;
  list = {a};
  EXPECT_EQ(copy, (vector{c, b}));
  std::swap(list, copy);
  EXPECT_EQ(list, (vector{c, b}));
  EXPECT_EQ(copy, (vector{a}));
  vector moved = std::move(list);
  EXPECT_TRUE(list.empty());
  EXPECT_EQ(moved.size(), 2u);
  moved.resize(5);
  EXPECT_EQ(moved[4], vertex());
  moved.clear();
  moved.shrink_to_fit();
  // a: a, copy, deduced; b: b, deduced; c: c.
  EXPECT_EQ(ctx().refs(a.slot()), 3u);
  EXPECT_EQ(ctx().refs(b.slot()), 2u);
  EXPECT_EQ(ctx().refs(c.slot()), 1u);
}

TEST_F(HandleBlocks, OtherSizesAndOtherTraitsUseTheHeap) {
  vertex v = ctx().new_vertex();
  const vertex* four;
  {
    std::vector<vertex> corners(4, v);
    four = corners.data();
  }
  // A block of 4 handles is kept now. Three handles: not a recycled size,
  // a block from the heap.
  long made = blocks_made;
  { std::vector<vertex> three(3, v); }
  EXPECT_EQ(blocks_made, made + 1);

  // A library user's traits name no context: from the heap too, and the
  // model's kept block stays kept.
  using plain = vv::graph<props>;
  plain::context other;
  plain::vertex w = other.new_vertex();
  made = blocks_made;
  { std::vector<plain::vertex> list(4, w); }
  EXPECT_EQ(blocks_made, made + 1);
  std::vector<vertex> corners(4, v);
  EXPECT_EQ(corners.data(), four);
}

TEST_F(HandleBlocks, HandlesInRecycledBlocksAreCountedRight) {
  mesh S;
  std::vector<vertex> kept;
  for (int i = 0; i < 100; ++i) kept.push_back(ctx().new_vertex());
  // Growing vectors (1, 2, 4, 8, then the heap) made and freed many times.
  for (int round = 0; round < 50; ++round) {
    std::vector<vertex> corners;
    for (int i = 0; i < 12; ++i) corners.push_back(kept[(round + i) % kept.size()]);
    EXPECT_EQ(corners[11], kept[(round + 11) % kept.size()]);
  }
  // Only `kept` holds them: dropping it frees them all.
  for (const vertex& v : kept) EXPECT_EQ(ctx().refs(v.slot()), 1u);
  kept.clear();
  EXPECT_EQ(ctx().collect_garbage(), 100u);
  EXPECT_EQ(ctx().live_vertices(), 0u);
}

TEST_F(HandleBlocks, ParallelLoopsAllocateAndFreeVectorsOnTheirThreads) {
  ctx().threads = 2;
  mesh S;
  std::vector<vertex> ring;
  constexpr int n = 4096;
  for (int i = 0; i < n; ++i) {
    vertex v = ctx().new_vertex();
    v->value = i;
    S.add(v);
    ring.push_back(v);
  }
  for (int i = 0; i < n; ++i) vv::make_nb(ring[i], {ring[(i + 1) % n], ring[(i + n - 1) % n]});
  vv::synchronise(S);
  // Each iteration collects its neighbours into a vector of its own (1, 2
  // and 4 handles) on whichever thread runs it.
  vv::parallel_for_each(S, [](vertex v) {
    std::vector<vertex> around;
    for (vertex x : vv::each(vv::old(v))) around.push_back(x);
    around.push_back(v);
    around.push_back(v);
    double sum = 0;
    for (const vertex& x : around) sum += vv::old(x)->value;
    v->value = sum;
  });
  for (int i = 0; i < n; ++i)
    EXPECT_EQ(ring[i]->value, ((i + 1) % n) + ((i + n - 1) % n) + 2.0 * i) << "vertex " << i;
  // Their counts came back to what they were: the ring and the mesh.
  for (const vertex& v : ring) EXPECT_EQ(ctx().refs(v.slot()), 2u);
}

TEST_F(HandleBlocks, TheContextFreesWhatItKeptAndWhatThePropertiesHold) {
  // Vertices whose properties hold walls of handles, and kept blocks of
  // every size, when the context goes: every block made since it was made
  // is freed.
  destroy_context();
  const long before = blocks_in_use;
  make_context();
  std::vector<vertex> cells;
  for (int i = 0; i < 10; ++i) cells.push_back(ctx().new_vertex());
  for (int i = 0; i < 10; ++i)
    for (int k = 0; k <= i; ++k) cells[i]->wall.push_back(cells[(i + k) % 10]);
  for (std::size_t n : {1u, 2u, 4u, 8u}) std::vector<vertex> freed(n, cells[0]);
  EXPECT_EQ(cells[9]->wall.size(), 10u);
  std::vector<vertex>().swap(cells);  // its own block too
  EXPECT_GT(blocks_in_use, before);
  destroy_context();
  EXPECT_EQ(blocks_in_use, before);
}

}  // namespace
