// Finding a neighbour and stepping around a neighbourhood, at every length
// and position: inline lists (searched four entries at a time), lists on
// the heap, lists that shrank back inline (whose unused entries still
// name their old neighbours), with and without half-edge records, in the
// current and the old state. Each answer is checked against the list the
// test built, by index arithmetic of its own.
#include <gtest/gtest.h>

#include <cstddef>
#include <string>
#include <vector>

#include <vv/vv.hpp>

// A namespace of its own: the algebra tests are built as one unity source.
namespace neighbourhood_search {

struct props {
  int index = -1;
};
struct edge_record {
  int mark = 0;
};
using plain = vv::traits<props>;
using with_records = vv::traits<props, edge_record>;
// An inline capacity that is no multiple of four, and one that is.
using capacity_five = vv::traits<props, vv::no_props, vv::no_props, 5>;
using capacity_eight = vv::traits<props, vv::no_props, vv::no_props, 8>;

template <class Tr>
struct ring {
  vv::context<Tr> ctx;
  vv::vertex<Tr> hub = ctx.new_vertex();
  vv::vertex<Tr> stranger = ctx.new_vertex();  // never a neighbour
  std::vector<vv::vertex<Tr>> spokes;

  explicit ring(std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
      spokes.push_back(ctx.new_vertex());
      spokes.back()->index = int(i);
    }
    if (n > 0) vv::make_nb_from(hub, spokes);
  }
};

// The expected neighbour `count` places after (or before) position i.
std::size_t around(std::size_t i, std::size_t n, long count, bool forward) {
  const std::size_t k = std::size_t(count) % n;
  return forward ? (i + k) % n : (i + n - k) % n;
}

// Every query on hub (as `view` reads it: current or old) against spokes.
template <class Tr, class View>
void check_every_query(const ring<Tr>& r, const View& view, const std::string& what) {
  const std::size_t n = r.spokes.size();
  ASSERT_EQ(vv::valence(view), n) << what;
  EXPECT_FALSE(vv::is_in(r.stranger, view)) << what;
  EXPECT_FALSE(vv::next_to(r.stranger, view)) << what;
  EXPECT_FALSE(vv::is_in(vv::vertex<Tr>(), view)) << what;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& x = r.spokes[i];
    EXPECT_TRUE(vv::is_in(x, view)) << what << ", spoke " << i;
    EXPECT_EQ(vv::next_to(x, view), r.spokes[around(i, n, 1, true)]) << what << ", nextto spoke " << i;
    EXPECT_EQ(vv::prev_to(x, view), r.spokes[around(i, n, 1, false)]) << what << ", prevto spoke " << i;
    for (long count : {2L, 3L, long(n), long(n) + 1, 2 * long(n) + 3}) {
      EXPECT_EQ(vv::next_to(x, view, count), r.spokes[around(i, n, count, true)])
          << what << ", next(" << count << ")to spoke " << i;
      EXPECT_EQ(vv::prev_to(x, view, count), r.spokes[around(i, n, count, false)])
          << what << ", prev(" << count << ")to spoke " << i;
    }
  }
  // forall visits the list in rotation order.
  std::vector<int> seen;
  for (auto&& x : vv::each(view)) seen.push_back(x->index);
  std::vector<int> expected;
  for (const auto& x : r.spokes) expected.push_back(x->index);
  EXPECT_EQ(seen, expected) << what << ", forall";
}

template <class Tr>
void check_lengths_up_to(std::size_t longest) {
  for (std::size_t n = 0; n <= longest; ++n) {
    ring<Tr> r(n);
    check_every_query(r, r.hub, "current, " + std::to_string(n) + " neighbours");
    vv::mesh<Tr> m(r.ctx);
    m.add(r.hub);
    vv::synchronise(m);
    check_every_query(r, vv::old(r.hub), "old, " + std::to_string(n) + " neighbours");
  }
}

template <class Tr>
void check_shrunk_lists(std::size_t longest) {
  // Erasing from the end leaves the erased neighbours' slots in the unused
  // entries of the list: none of them may be found.
  ring<Tr> r(longest);
  while (!r.spokes.empty()) {
    const auto gone = r.spokes.back();
    vv::erase_from(gone, r.hub);
    r.spokes.pop_back();
    const std::string what = "after shrinking to " + std::to_string(r.spokes.size());
    EXPECT_FALSE(vv::is_in(gone, r.hub)) << what;
    EXPECT_FALSE(vv::next_to(gone, r.hub)) << what;
    if (!r.spokes.empty()) check_every_query(r, r.hub, what);
  }
}

TEST(NeighbourhoodSearch, EveryPositionOfEveryLengthIsFound) {
  check_lengths_up_to<plain>(plain::inline_valence + 5);
}

TEST(NeighbourhoodSearch, ListsWithHalfEdgeRecordsAreSearchedAlike) {
  check_lengths_up_to<with_records>(with_records::inline_valence + 5);
}

TEST(NeighbourhoodSearch, InlineCapacitiesOfFiveAndEightAreSearchedWhole) {
  check_lengths_up_to<capacity_five>(9);
  check_lengths_up_to<capacity_eight>(12);
}

TEST(NeighbourhoodSearch, NeighboursErasedFromTheEndAreNotFound) {
  check_shrunk_lists<plain>(plain::inline_valence + 3);
  check_shrunk_lists<with_records>(with_records::inline_valence + 3);
  check_shrunk_lists<capacity_five>(7);
}

TEST(NeighbourhoodSearch, ANeighbourReplacedInPlaceIsFoundWhereItWas) {
  ring<plain> r(6);
  const auto fresh = r.ctx.new_vertex();
  fresh->index = 100;
  vv::replace_in(r.spokes[3], fresh, r.hub);
  const auto old_spoke = r.spokes[3];
  r.spokes[3] = fresh;
  EXPECT_FALSE(vv::is_in(old_spoke, r.hub));
  check_every_query(r, r.hub, "after replace");
}

TEST(NeighbourhoodSearch, SplicedNeighboursTakeTheirPlaceAtEveryPosition) {
  // Splicing before each position of every length, up to the heap.
  for (std::size_t n = 1; n <= plain::inline_valence + 2; ++n) {
    for (std::size_t position = 0; position < n; ++position) {
      ring<plain> r(n);
      const auto x = r.ctx.new_vertex();
      x->index = 100;
      vv::splice_before(x, r.spokes[position], r.hub);
      r.spokes.insert(r.spokes.begin() + long(position), x);
      check_every_query(r, r.hub, "splice before position " + std::to_string(position) + " of " + std::to_string(n));
    }
  }
}

TEST(PathWalks, StoreWritesThePairAndGivesTheSecondVariable) {
  ring<plain> r(4);
  vv::vertex<plain> a = r.hub, b = r.spokes[1];
  const vv::vertex<plain>& value = vv::path_into(a, b).next().store();
  EXPECT_EQ(&value, &b);
  EXPECT_EQ(a, r.hub);
  EXPECT_EQ(b, r.spokes[2]);
  // A swap walk moves both ends; the handles stay counted right.
  vv::path_into(a, b).swap().next().store();
  EXPECT_EQ(a, r.spokes[2]);
  EXPECT_EQ(b, vv::vertex<plain>());  // the spoke has no neighbours
  const unsigned held = r.ctx.refs(r.spokes[2].slot());
  a = vv::vertex<plain>();
  EXPECT_EQ(r.ctx.refs(r.spokes[2].slot()), held - 1);
}

}  // namespace neighbourhood_search
