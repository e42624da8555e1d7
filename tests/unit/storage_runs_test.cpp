// Vertex storage in runs of 2 MiB (vv/detail/page_runs.hpp, block_arena.hpp,
// run_allocator.hpp): runs lie on 2 MiB boundaries, zeroed and marked for
// huge pages; the arena carves blocks from them without overlap once its
// heap allowance is spent; large arrays are mapped and small ones are not;
// a context whose storage lives in runs keeps every vertex intact.
//
// Runs are turned on here even under AddressSanitizer (where the library
// leaves them off), so that the sanitizer build checks their logic too.
#define VV_STORAGE_IN_RUNS 1

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <sys/mman.h>

#include <vv/vv.hpp>

#include "../bench/heap_usage.hpp"  // huge_page_mappings()

namespace storage_runs {

using vv::detail::block_arena;
using vv::detail::run_bytes;

std::uintptr_t address(const void* p) { return reinterpret_cast<std::uintptr_t>(p); }

// The VmFlags of the mapping that holds p, from /proc/self/smaps ("" if
// no mapping holds it).
std::string mapping_flags(const void* p) {
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  bool inside = false;
  while (std::getline(smaps, line)) {
    unsigned long low = 0, high = 0;
    char dash = 0;
    std::istringstream header(line);
    if (line.rfind("VmFlags:", 0) == 0) {
      if (inside) return line;
    } else if (header >> std::hex >> low >> dash >> high && dash == '-') {
      inside = low <= address(p) && address(p) < high;
    }
  }
  return "";
}

bool all_zero(const unsigned char* p, std::size_t n) {
  return std::all_of(p, p + n, [](unsigned char c) { return c == 0; });
}

TEST(StorageRuns, ARunLiesOnARunBoundaryZeroedWritableAndMarkedForHugePages) {
  const std::size_t size = 2 * run_bytes;
  auto* p = static_cast<unsigned char*>(vv::detail::map_run(size));
  EXPECT_EQ(address(p) % run_bytes, 0u);
  EXPECT_TRUE(all_zero(p, size));
  p[0] = 1;
  p[size - 1] = 2;
  EXPECT_EQ(p[0] + p[size - 1], 3);
  // A kernel built without transparent huge pages refuses the advice.
  if (std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled")) {
    const std::string flags = mapping_flags(p);
    EXPECT_NE(flags.find(" hg"), std::string::npos) << "mapping flags: " << flags;
  }
  vv::detail::unmap_run(p, size);
  // msync of memory no mapping holds fails with ENOMEM.
  errno = 0;
  EXPECT_EQ(::msync(p, 4096, MS_ASYNC), -1) << "the run is given back";
  EXPECT_EQ(errno, ENOMEM);
}

// Runs are used only where the kernel backs them with huge pages.
TEST(StorageRuns, RunsAreUsedWhereTheKernelOffersHugePages) {
  std::ifstream setting("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string text;
  std::getline(setting, text);
  const bool offered = text.find("[always]") != std::string::npos || text.find("[madvise]") != std::string::npos;
  EXPECT_EQ(vv::detail::huge_pages_offered(), offered) << "the kernel's setting: " << text;
  EXPECT_EQ(block_arena::default_heap_bytes() < (std::size_t{1} << 30), offered);
  EXPECT_EQ(vv::detail::run_allocator<std::uint32_t>::mapped_from() < (std::size_t{1} << 30), offered);
}

TEST(StorageRuns, WholeRunsRoundUp) {
  EXPECT_EQ(vv::detail::whole_runs(1), run_bytes);
  EXPECT_EQ(vv::detail::whole_runs(run_bytes), run_bytes);
  EXPECT_EQ(vv::detail::whole_runs(run_bytes + 1), 2 * run_bytes);
}

// Blocks the size of a chunk: 36 fit in a run, so 100 take three runs.
TEST(StorageRuns, TheArenaCarvesBlocksFromRunsWithoutOverlap) {
  block_arena arena(0);
  const std::size_t bytes = 57344, align = 64;
  std::vector<unsigned char*> blocks;
  for (int i = 0; i < 100; ++i) {
    auto* b = static_cast<unsigned char*>(arena.take(bytes, align));
    ASSERT_EQ(address(b) % align, 0u);
    ASSERT_TRUE(all_zero(b, bytes)) << "block " << i << " is fresh memory";
    std::memset(b, i + 1, bytes);
    blocks.push_back(b);
  }
  EXPECT_EQ(arena.mapped_bytes(), 3 * run_bytes);
  std::vector<unsigned char*> sorted = blocks;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 1; i < sorted.size(); ++i) EXPECT_GE(address(sorted[i]), address(sorted[i - 1]) + bytes);
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    EXPECT_EQ(blocks[i][0], i + 1);
    EXPECT_EQ(blocks[i][bytes - 1], i + 1) << "no later block wrote over block " << i;
    // No block straddles the end of its run.
    EXPECT_EQ(address(blocks[i]) / run_bytes, (address(blocks[i]) + bytes - 1) / run_bytes);
  }
}

TEST(StorageRuns, TheArenaKeepsToAlignmentBetweenSizes) {
  block_arena arena(0);
  std::uintptr_t end = 0;
  for (std::size_t i = 0; i < 200; ++i) {
    const std::size_t align = std::size_t{8} << (i % 5), bytes = 24 + 40 * i;
    void* b = arena.take(bytes, align);
    EXPECT_EQ(address(b) % align, 0u) << "block " << i;
    if (address(b) / run_bytes == end / run_bytes) {
      EXPECT_GE(address(b), end) << "block " << i;
    }
    end = address(b) + bytes;
  }
  EXPECT_EQ(arena.mapped_bytes(), run_bytes) << "200 small blocks fit in one run";
}

TEST(StorageRuns, ABlockLargerThanARunHasRunsOfItsOwn) {
  block_arena arena(0);
  void* small = arena.take(100, 16);
  auto* big = static_cast<unsigned char*>(arena.take(run_bytes + 1, 16));
  EXPECT_EQ(address(big) % run_bytes, 0u);
  big[run_bytes] = 7;
  EXPECT_EQ(big[run_bytes], 7);
  EXPECT_EQ(arena.mapped_bytes(), 3 * run_bytes);
  EXPECT_NE(address(small) / run_bytes, address(big) / run_bytes);
}

TEST(StorageRuns, TheFirstBlocksComeFromTheHeapUpToTheAllowance) {
  block_arena arena(1200);
  void* a = arena.take(600, 16);
  void* b = arena.take(400, 16);
  EXPECT_EQ(arena.mapped_bytes(), 0u) << "1000 bytes fit in the allowance";
  EXPECT_EQ(mapping_flags(a).find(" hg"), std::string::npos);
  void* c = arena.take(600, 16);  // more than the 200 bytes left
  EXPECT_EQ(arena.mapped_bytes(), run_bytes);
  EXPECT_EQ(address(c) % run_bytes, 0u);
  // Once runs have begun, a block that would fit what is left of the
  // allowance still comes from the run.
  void* d = arena.take(8, 8);
  EXPECT_EQ(address(d), address(c) + 600);
  EXPECT_NE(a, b);
}

TEST(StorageRuns, LargeArraysAreMappedAndSmallOnesAreNot) {
  using list = vv::detail::slot_list;
  list small(1000, 5u);
  EXPECT_EQ(mapping_flags(small.data()).find(" hg"), std::string::npos);
  list large;
  for (std::uint32_t i = 0; i < 1000000; ++i) large.push_back(i);  // grows through both kinds
  if (vv::detail::huge_pages_offered()) {
    EXPECT_EQ(address(large.data()) % run_bytes, 0u) << "mapped";
  }
  for (std::uint32_t i = 0; i < 1000000; i += 997) ASSERT_EQ(large[i], i);
  large.resize(10);
  large.shrink_to_fit();  // back to the heap, contents kept
  EXPECT_EQ(large, list({0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
  EXPECT_EQ(std::count(small.begin(), small.end(), 5u), 1000);
}

struct props {
  double x = 0;
  std::uint32_t tag = 0;
};
using graph = vv::graph<props>;
using vertex = graph::vertex;

// 200,000 vertices in a ring, each seeing the next two: past the heap
// allowance, so where huge pages are offered their blocks, old state,
// counts, labels and member lists are in runs. Every property,
// neighbourhood and old neighbourhood reads back; the context's runs are
// all given back when it goes (LeakSanitizer checks what the heap held).
void check_a_ring_of_vertices(std::size_t mapped_before) {
  const std::uint32_t n = 200000;
  graph::context ctx;
  graph::mesh M(ctx);
  std::vector<vertex> ring;
  ring.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    ring.push_back(ctx.new_vertex());
    ring.back()->tag = i;
    ring.back()->x = 0.5 * i;
    M.add(ring.back());
  }
  for (std::uint32_t i = 0; i < n; ++i) vv::make_nb(ring[i], {ring[(i + 1) % n], ring[(i + 2) % n]});
  vv::synchronise(M);
  for (std::uint32_t i = 0; i < n; ++i) vv::make_nb(ring[i], {ring[(i + n - 1) % n]});
  ASSERT_EQ(M.size(), n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const vertex& v = ring[i];
    ASSERT_EQ(v->tag, i);
    ASSERT_EQ(v->x, 0.5 * i);
    ASSERT_TRUE(M.contains(v));
    ASSERT_EQ(vv::valence(v), 1u);
    ASSERT_EQ(vv::any_in(v), ring[(i + n - 1) % n]);
    ASSERT_EQ(vv::valence(vv::old(v)), 2u) << "vertex " << i;
    ASSERT_EQ(vv::any_in(vv::old(v)), ring[(i + 1) % n]);
  }
  if (vv::detail::huge_pages_offered()) {
    // 48 bytes a vertex (a neighbourhood and the properties), current and
    // old, less the first MiB of blocks, which is on the heap.
    EXPECT_GE(huge_page_mappings() - mapped_before, std::size_t{2} * n * 48 - (std::size_t{1} << 20))
        << "the storage is in runs";
  }
}

TEST(StorageRuns, AContextInRunsKeepsEveryVertexAndGivesBackItsRuns) {
  const std::size_t mapped_before = huge_page_mappings();
  check_a_ring_of_vertices(mapped_before);
  EXPECT_EQ(huge_page_mappings(), mapped_before) << "every run is unmapped";
}

}  // namespace storage_runs
