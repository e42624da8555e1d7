// Neighbourhood edits (LANGUAGE.md section 4, second table and the notes
// after it). Every successful edit is followed by check_invariants on the
// vertices involved; every failing edit must leave the neighbourhood, its
// flag and its records exactly as they were.
#include "test_meshes.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace {

using namespace vvtest;

// v with neighbourhood (a, b, c, d) and labels v=1, a=2, b=3, c=4, d=5;
// x=6 and y=7 are not neighbours of anyone.
class Edits : public ::testing::Test {
 protected:
  Edits()
      : v(ctx.new_vertex()), a(ctx.new_vertex()), b(ctx.new_vertex()), c(ctx.new_vertex()),
        d(ctx.new_vertex()), x(ctx.new_vertex()), y(ctx.new_vertex()) {
    vv::make_nb(v, {a, b, c, d});
    vv::edge(v, a).mark = 10;
    vv::edge(v, b).mark = 20;
    vv::edge(v, c).mark = 30;
    vv::edge(v, d).mark = 40;
    vv::edge(v, c).b = true;
  }
  ::testing::AssertionResult ok() { return invariants_hold({v, a, b, c, d, x, y}); }

  G::context ctx;
  V v, a, b, c, d, x, y;
};

// ===================================================================== make

TEST_F(Edits, MakeSetsTheCyclicList) {
  V w = ctx.new_vertex();
  vv::make_nb(w, {c, a, d});
  EXPECT_EQ(nb_labels(w), labels({c, a, d}));
  EXPECT_EQ(vv::any_in(w), c);
  EXPECT_EQ(vv::next_to(d, w), c);
  EXPECT_TRUE(ok());
  EXPECT_TRUE(invariants_hold({w}));
}

TEST_F(Edits, MakeReplacesTheWholeNeighbourhood) {
  vv::make_nb(v, {x, b, y});
  EXPECT_EQ(nb_labels(v), labels({x, b, y}));
  EXPECT_FALSE(vv::is_in(a, v));
  EXPECT_TRUE(ok());
  vv::make_nb(v, {});
  EXPECT_EQ(vv::valence(v), 0u);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, MakeFromAnyRange) {
  std::vector<V> list{d, c, b, a, x};
  vv::make_nb_from(v, list);
  EXPECT_EQ(nb_labels(v), (std::vector<unsigned>{5, 4, 3, 2, 6}));
  EXPECT_TRUE(ok());
}

TEST_F(Edits, MakeRecordsAreDefault) {
  vv::make_nb(v, {a, b, c, d, x});  // entries existed before with records
  for (V n : vv::each(v)) {
    EXPECT_EQ(vv::edge(v, n).mark, 0) << n;
    EXPECT_FALSE(vv::edge(v, n).b) << n;
  }
  EXPECT_TRUE(ok());
}

TEST_F(Edits, MakeUnsetsTheFlag) {
  vv::flag_in(b, v);
  ASSERT_EQ(vv::flagged_in(v), b);
  vv::make_nb(v, {a, b, c});
  EXPECT_FALSE(vv::flagged_in(v));
  EXPECT_TRUE(ok());
}

TEST_F(Edits, MakeWithTargetListedIsAnError) {
  vv::flag_in(c, v);
  nb_state before = state_of(v);
  EXPECT_TRUE(throws_vv_error([&] { vv::make_nb(v, {a, v, x}); },
                              {"make", "vertex 1 cannot be its own neighbour", "edits_test.cpp"}));
  EXPECT_EQ(state_of(v), before);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, MakeWithAVertexOfAnotherContextIsAnError) {
  vv::flag_in(c, v);
  nb_state before = state_of(v);
  G::context other;
  V stranger = other.new_vertex();
  EXPECT_TRUE(throws_vv_error([&] { vv::make_nb(v, {a, stranger, x}); },
                              {"make", "vertex 1 belongs to another context than vertex 1", "edits_test.cpp"}));
  // Of the three faults, the first in the list's order is named.
  EXPECT_TRUE(throws_vv_error([&] { vv::make_nb(v, {stranger, nullptr, v}); }, {"another context"}));
  EXPECT_TRUE(throws_vv_error([&] { vv::make_nb(v, {a, nullptr, stranger}); }, {"contains the null vertex"}));
  EXPECT_EQ(state_of(v), before);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, MakeWithANullEntryIsAnError) {
  vv::flag_in(c, v);
  nb_state before = state_of(v);
  EXPECT_TRUE(throws_vv_error([&] { vv::make_nb(v, {a, nullptr, x}); },
                              {"make", "the list for vertex 1 contains the null vertex", "edits_test.cpp"}));
  EXPECT_TRUE(throws_vv_error([&] { vv::make_nb(v, {a, V(), x}); }, {"contains the null vertex"}));
  EXPECT_EQ(state_of(v), before);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, MakeFromQueryResultsKeepsTheirVertices) {
  // Entries that are temporaries (query results) are read before the
  // statement ends: the new neighbourhood names them.
  V w = ctx.new_vertex();
  vv::make_nb(w, {vv::any_in(v), vv::next_to(vv::any_in(v), v)});
  ASSERT_EQ(vv::valence(w), 2u);
  EXPECT_EQ(vv::any_in(w), vv::any_in(v));
  EXPECT_EQ(vv::next_to(vv::any_in(w), w), vv::next_to(vv::any_in(v), v));
}

TEST_F(Edits, MakeWithDuplicateIsAnError) {
  vv::flag_in(c, v);
  nb_state before = state_of(v);
  EXPECT_TRUE(throws_vv_error([&] { vv::make_nb(v, {x, a, y, a}); },
                              {"make", "vertex 2", "edits_test.cpp"}));
  EXPECT_EQ(state_of(v), before);
  V w = ctx.new_vertex();
  EXPECT_TRUE(throws_vv_error([&] { vv::make_nb(w, {x, x}); }, {"make", "vertex 6"}));
  EXPECT_EQ(vv::valence(w), 0u);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, MakeWithDuplicateInALongListIsAnError) {
  std::vector<V> list;
  for (int i = 0; i < 40; ++i) list.push_back(ctx.new_vertex());
  list.push_back(list[17]);
  nb_state before = state_of(v);
  EXPECT_TRUE(throws_vv_error([&] { vv::make_nb_from(v, list); },
                              {"make", "vertex " + std::to_string(list[17].label())}));
  EXPECT_EQ(state_of(v), before);
  list.pop_back();
  vv::make_nb_from(v, list);
  EXPECT_EQ(vv::valence(v), 40u);
  EXPECT_EQ(vv::next_to(list[39], v), list[0]);
  EXPECT_TRUE(ok());
}

// Distinct vertices whose slots are equal modulo 64 (the quick duplicate
// filter cannot tell them apart) are no duplicates; a real duplicate among
// them still is one.
TEST_F(Edits, MakeTellsSlotsEqualModulo64FromDuplicates) {
  std::vector<V> made;
  for (int i = 0; i < 200; ++i) made.push_back(ctx.new_vertex());
  std::vector<V> list;  // the first three share a slot modulo 64, so do the last three
  for (const V& u : made)
    if (u.slot() % 64 == made[0].slot() % 64 && list.size() < 3) list.push_back(u);
  for (const V& u : made)
    if (u.slot() % 64 == made[1].slot() % 64 && list.size() < 6) list.push_back(u);
  ASSERT_EQ(list.size(), 6u);
  vv::make_nb_from(v, list);
  EXPECT_EQ(vv::valence(v), 6u);
  EXPECT_EQ(vv::next_to(list[2], v), list[3]);

  V w = ctx.new_vertex();
  std::vector<V> twice = {list[0], list[3], list[1], list[4], list[3]};
  EXPECT_TRUE(throws_vv_error([&] { vv::make_nb_from(w, twice); },
                              {"make", "vertex " + std::to_string(list[3].label()) + " is listed twice"}));
  EXPECT_EQ(vv::valence(w), 0u);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, MakeWithNullTargetIsAnError) {
  EXPECT_TRUE(throws_vv_error([&] { vv::make_nb(V(), {a, b}); },
                              {"make", "null", "edits_test.cpp"}));
  EXPECT_EQ(state_of(a).nb, std::vector<unsigned>{});
}

// ==================================================================== erase

TEST_F(Edits, EraseRemovesTheEntry) {
  vv::erase_from(b, v);
  EXPECT_EQ(nb_labels(v), labels({a, c, d}));
  EXPECT_FALSE(vv::is_in(b, v));
  EXPECT_EQ(vv::next_to(a, v), c);
  EXPECT_TRUE(ok());
  vv::erase_from(d, v);
  vv::erase_from(a, v);
  vv::erase_from(c, v);
  EXPECT_EQ(vv::valence(v), 0u);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, EraseKeepsOtherRecords) {
  vv::erase_from(b, v);
  EXPECT_EQ(vv::edge(v, a).mark, 10);
  EXPECT_EQ(vv::edge(v, c).mark, 30);
  EXPECT_TRUE(vv::edge(v, c).b);
  EXPECT_EQ(vv::edge(v, d).mark, 40);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, EraseAbsentHasNoEffect) {
  vv::flag_in(c, v);
  nb_state before = state_of(v);
  vv::erase_from(x, v);
  EXPECT_EQ(state_of(v), before);
  vv::erase_from(v, v);
  EXPECT_EQ(state_of(v), before);
  vv::erase_from(V(), v);
  EXPECT_EQ(state_of(v), before);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, EraseWithNullTargetIsAnError) {
  EXPECT_TRUE(throws_vv_error([&] { vv::erase_from(a, V()); },
                              {"erase", "null", "edits_test.cpp"}));
}

// ================================================================== replace

TEST_F(Edits, ReplacePutsXInAsPlace) {
  vv::replace_in(b, x, v);
  EXPECT_EQ(nb_labels(v), labels({a, x, c, d}));
  EXPECT_FALSE(vv::is_in(b, v));
  EXPECT_TRUE(ok());
}

TEST_F(Edits, ReplaceKeepsTheRecordOfTheSlot) {
  vv::replace_in(c, x, v);
  EXPECT_EQ(vv::edge(v, x).mark, 30);
  EXPECT_TRUE(vv::edge(v, x).b);
  EXPECT_EQ(vv::edge(v, a).mark, 10);
  EXPECT_EQ(vv::edge(v, d).mark, 40);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, ReplaceAbsentHasNoEffect) {
  vv::flag_in(b, v);
  nb_state before = state_of(v);
  vv::replace_in(x, y, v);
  EXPECT_EQ(state_of(v), before);
  vv::replace_in(V(), y, v);
  EXPECT_EQ(state_of(v), before);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, ReplaceWithTargetIsAnError) {
  vv::flag_in(b, v);
  nb_state before = state_of(v);
  EXPECT_TRUE(throws_vv_error([&] { vv::replace_in(b, v, v); },
                              {"replace", "vertex 1", "edits_test.cpp"}));
  EXPECT_EQ(state_of(v), before);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, ReplaceWithExistingNeighbourIsAnError) {
  vv::flag_in(b, v);
  nb_state before = state_of(v);
  EXPECT_TRUE(throws_vv_error([&] { vv::replace_in(b, d, v); },
                              {"replace", "vertex 5", "edits_test.cpp"}));
  EXPECT_EQ(state_of(v), before);
  // Replacing an entry with itself: x is in v*.
  EXPECT_TRUE(throws_vv_error([&] { vv::replace_in(b, b, v); }, {"replace", "vertex 3"}));
  EXPECT_EQ(state_of(v), before);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, ReplaceWithNullTargetIsAnError) {
  EXPECT_TRUE(throws_vv_error([&] { vv::replace_in(a, x, V()); },
                              {"replace", "null", "edits_test.cpp"}));
}

// =================================================================== splice

TEST_F(Edits, SpliceAfterInsertsAfterA) {
  vv::splice_after(x, b, v);
  EXPECT_EQ(cycle(v), canon(labels({a, b, x, c, d})));
  EXPECT_EQ(vv::next_to(b, v), x);
  EXPECT_EQ(vv::next_to(x, v), c);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, SpliceAfterLastEntry) {
  vv::splice_after(x, d, v);
  EXPECT_EQ(cycle(v), canon(labels({a, b, c, d, x})));
  EXPECT_EQ(vv::next_to(d, v), x);
  EXPECT_EQ(vv::next_to(x, v), a);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, SpliceBeforeInsertsBeforeA) {
  vv::splice_before(x, c, v);
  EXPECT_EQ(cycle(v), canon(labels({a, b, x, c, d})));
  EXPECT_EQ(vv::prev_to(c, v), x);
  EXPECT_EQ(vv::prev_to(x, v), b);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, SpliceBeforeFirstEntry) {
  vv::splice_before(x, a, v);
  EXPECT_EQ(cycle(v), canon(labels({x, a, b, c, d})));
  EXPECT_EQ(vv::prev_to(a, v), x);
  EXPECT_EQ(vv::prev_to(x, v), d);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, SpliceIntoSingleton) {
  V w = ctx.new_vertex();
  vv::make_nb(w, {a});
  vv::splice_after(b, a, w);
  vv::splice_before(c, a, w);
  EXPECT_EQ(cycle(w), canon(labels({a, b, c})));
  EXPECT_TRUE(invariants_hold({w, a, b, c}));
}

TEST_F(Edits, SpliceGrowsPastInlineCapacity) {
  V prev = d;
  std::vector<unsigned> expect = labels({a, b, c, d});
  for (int i = 0; i < 20; ++i) {
    V n = ctx.new_vertex();
    vv::splice_after(n, prev, v);
    expect.push_back(n.label());
    prev = n;
  }
  EXPECT_EQ(cycle(v), canon(expect));
  EXPECT_EQ(vv::edge(v, c).mark, 30);
  for (int i = 0; i < 20; ++i) vv::erase_from(vv::prev_to(a, v), v);
  EXPECT_EQ(cycle(v), canon(labels({a, b, c, d})));
  EXPECT_EQ(vv::edge(v, b).mark, 20);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, SpliceAfterNewRecordIsDefault) {
  vv::splice_after(x, c, v);  // c's record has mark 30, b true
  EXPECT_EQ(vv::edge(v, x).mark, 0);
  EXPECT_FALSE(vv::edge(v, x).b);
  EXPECT_EQ(vv::edge(v, c).mark, 30);
  EXPECT_TRUE(vv::edge(v, c).b);
  EXPECT_EQ(vv::edge(v, d).mark, 40);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, SpliceBeforeNewRecordIsDefault) {
  vv::splice_before(x, c, v);
  EXPECT_EQ(vv::edge(v, x).mark, 0);
  EXPECT_FALSE(vv::edge(v, x).b);
  EXPECT_EQ(vv::edge(v, b).mark, 20);
  EXPECT_EQ(vv::edge(v, c).mark, 30);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, SpliceAfterAbsentHasNoEffect) {
  vv::flag_in(c, v);
  nb_state before = state_of(v);
  vv::splice_after(x, y, v);
  EXPECT_EQ(state_of(v), before);
  vv::splice_after(x, V(), v);
  EXPECT_EQ(state_of(v), before);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, SpliceBeforeAbsentHasNoEffect) {
  vv::flag_in(c, v);
  nb_state before = state_of(v);
  vv::splice_before(x, y, v);
  EXPECT_EQ(state_of(v), before);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, SpliceAfterTargetIsAnError) {
  vv::flag_in(c, v);
  nb_state before = state_of(v);
  EXPECT_TRUE(throws_vv_error([&] { vv::splice_after(v, b, v); },
                              {"splice", "vertex 1", "edits_test.cpp"}));
  EXPECT_EQ(state_of(v), before);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, SpliceBeforeTargetIsAnError) {
  vv::flag_in(c, v);
  nb_state before = state_of(v);
  EXPECT_TRUE(throws_vv_error([&] { vv::splice_before(v, b, v); },
                              {"splice", "vertex 1", "edits_test.cpp"}));
  EXPECT_EQ(state_of(v), before);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, SpliceAfterExistingNeighbourIsAnError) {
  vv::flag_in(c, v);
  nb_state before = state_of(v);
  EXPECT_TRUE(throws_vv_error([&] { vv::splice_after(d, b, v); },
                              {"splice", "vertex 5", "edits_test.cpp"}));
  EXPECT_EQ(state_of(v), before);
  EXPECT_TRUE(throws_vv_error([&] { vv::splice_after(b, b, v); }, {"splice", "vertex 3"}));
  EXPECT_EQ(state_of(v), before);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, SpliceBeforeExistingNeighbourIsAnError) {
  vv::flag_in(c, v);
  nb_state before = state_of(v);
  EXPECT_TRUE(throws_vv_error([&] { vv::splice_before(a, c, v); },
                              {"splice", "vertex 2", "edits_test.cpp"}));
  EXPECT_EQ(state_of(v), before);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, SpliceAfterWithNullTargetIsAnError) {
  EXPECT_TRUE(throws_vv_error([&] { vv::splice_after(x, a, V()); },
                              {"splice", "null", "edits_test.cpp"}));
}

TEST_F(Edits, SpliceBeforeWithNullTargetIsAnError) {
  EXPECT_TRUE(throws_vv_error([&] { vv::splice_before(x, a, V()); },
                              {"splice", "null", "edits_test.cpp"}));
}

// ===================================================================== flag

TEST_F(Edits, FlagMarksThePosition) {
  vv::flag_in(c, v);
  EXPECT_EQ(vv::flagged_in(v), c);
  EXPECT_EQ(nb_labels(v), labels({a, b, c, d}));  // the list is unchanged
  EXPECT_TRUE(ok());
  vv::flag_in(a, v);
  EXPECT_EQ(vv::flagged_in(v), a);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, FlagAbsentHasNoEffect) {
  vv::flag_in(c, v);
  nb_state before = state_of(v);
  vv::flag_in(x, v);
  EXPECT_EQ(state_of(v), before);
  EXPECT_EQ(vv::flagged_in(v), c);
  vv::flag_in(v, v);
  EXPECT_EQ(state_of(v), before);
  // No effect also means an unset flag stays unset.
  vv::flag_in(V(), v);
  vv::flag_in(x, v);
  EXPECT_FALSE(vv::flagged_in(v));
  EXPECT_TRUE(ok());
}

TEST_F(Edits, FlagNullUnsets) {
  vv::flag_in(c, v);
  vv::flag_in(V(), v);
  EXPECT_FALSE(vv::flagged_in(v));
  EXPECT_EQ(nb_labels(v), labels({a, b, c, d}));
  EXPECT_TRUE(ok());
  vv::flag_in(V(), v);  // unsetting an unset flag is fine
  EXPECT_FALSE(vv::flagged_in(v));
}

TEST_F(Edits, FlagWithNullTargetIsAnError) {
  EXPECT_TRUE(throws_vv_error([&] { vv::flag_in(a, V()); },
                              {"flag", "null", "edits_test.cpp"}));
}

// ------------------------------------------------------ edits at the flag

TEST_F(Edits, SpliceAfterFlag) {
  vv::flag_in(b, v);
  vv::splice_after_flag(x, v);
  EXPECT_EQ(cycle(v), canon(labels({a, b, x, c, d})));
  EXPECT_EQ(vv::flagged_in(v), b);
  EXPECT_EQ(vv::edge(v, x).mark, 0);
  EXPECT_FALSE(vv::edge(v, x).b);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, SpliceBeforeFlag) {
  vv::flag_in(b, v);
  vv::splice_before_flag(x, v);
  EXPECT_EQ(cycle(v), canon(labels({a, x, b, c, d})));
  EXPECT_EQ(vv::flagged_in(v), b);
  EXPECT_EQ(vv::edge(v, x).mark, 0);
  EXPECT_EQ(vv::edge(v, b).mark, 20);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, SpliceBeforeFlagAtFirstEntry) {
  vv::flag_in(a, v);
  vv::splice_before_flag(x, v);
  EXPECT_EQ(cycle(v), canon(labels({x, a, b, c, d})));
  EXPECT_EQ(vv::flagged_in(v), a);
  EXPECT_EQ(vv::prev_to_flag(v), x);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, ReplaceFlag) {
  vv::flag_in(c, v);
  vv::replace_flag(x, v);
  EXPECT_EQ(nb_labels(v), labels({a, b, x, d}));
  EXPECT_EQ(vv::edge(v, x).mark, 30);  // the slot's record is kept
  EXPECT_TRUE(vv::edge(v, x).b);
  EXPECT_EQ(vv::flagged_in(v), x);  // the flag is the position
  EXPECT_TRUE(ok());
}

TEST_F(Edits, EraseFlag) {
  vv::flag_in(c, v);
  vv::erase_flag(v);
  EXPECT_EQ(nb_labels(v), labels({a, b, d}));
  EXPECT_TRUE(ok());
}

TEST_F(Edits, EraseFlagUnsetsTheFlag) {
  vv::flag_in(c, v);
  vv::erase_flag(v);
  EXPECT_FALSE(vv::flagged_in(v));
  EXPECT_TRUE(throws_vv_error([&] { vv::erase_flag(v); }, {"erase flag"}));
  EXPECT_EQ(nb_labels(v), labels({a, b, d}));
  EXPECT_TRUE(ok());
}

TEST_F(Edits, SpliceAfterFlagErrorWhenUnset) {
  nb_state before = state_of(v);
  EXPECT_TRUE(throws_vv_error([&] { vv::splice_after_flag(x, v); },
                              {"splice after flag", "flag", "edits_test.cpp"}));
  EXPECT_EQ(state_of(v), before);
}

TEST_F(Edits, SpliceBeforeFlagErrorWhenUnset) {
  nb_state before = state_of(v);
  EXPECT_TRUE(throws_vv_error([&] { vv::splice_before_flag(x, v); },
                              {"splice before flag", "edits_test.cpp"}));
  EXPECT_EQ(state_of(v), before);
}

TEST_F(Edits, ReplaceFlagErrorWhenUnset) {
  nb_state before = state_of(v);
  EXPECT_TRUE(throws_vv_error([&] { vv::replace_flag(x, v); },
                              {"replace flag", "edits_test.cpp"}));
  EXPECT_EQ(state_of(v), before);
}

TEST_F(Edits, EraseFlagErrorWhenUnset) {
  nb_state before = state_of(v);
  EXPECT_TRUE(throws_vv_error([&] { vv::erase_flag(v); }, {"erase flag", "edits_test.cpp"}));
  EXPECT_EQ(state_of(v), before);
}

TEST_F(Edits, FlagEditsErrorWhenUnsetOnEmptyNeighbourhood) {
  V w = ctx.new_vertex();
  EXPECT_TRUE(throws_vv_error([&] { vv::splice_after_flag(x, w); }, {"splice after flag"}));
  EXPECT_TRUE(throws_vv_error([&] { vv::splice_before_flag(x, w); }, {"splice before flag"}));
  EXPECT_TRUE(throws_vv_error([&] { vv::replace_flag(x, w); }, {"replace flag"}));
  EXPECT_TRUE(throws_vv_error([&] { vv::erase_flag(w); }, {"erase flag"}));
  EXPECT_EQ(vv::valence(w), 0u);
}

TEST_F(Edits, SpliceAtFlagOfTargetOrNeighbourIsAnError) {
  vv::flag_in(b, v);
  nb_state before = state_of(v);
  EXPECT_TRUE(throws_vv_error([&] { vv::splice_after_flag(v, v); }, {"splice after flag", "vertex 1"}));
  EXPECT_TRUE(throws_vv_error([&] { vv::splice_before_flag(d, v); }, {"splice before flag", "vertex 5"}));
  EXPECT_TRUE(throws_vv_error([&] { vv::replace_flag(a, v); }, {"replace flag", "vertex 2"}));
  EXPECT_TRUE(throws_vv_error([&] { vv::replace_flag(v, v); }, {"replace flag", "vertex 1"}));
  EXPECT_EQ(state_of(v), before);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, FlagEditsWithNullTargetAreErrors) {
  EXPECT_TRUE(throws_vv_error([&] { vv::splice_after_flag(x, V()); },
                              {"splice after flag", "null", "edits_test.cpp"}));
  EXPECT_TRUE(throws_vv_error([&] { vv::splice_before_flag(x, V()); },
                              {"splice before flag", "null", "edits_test.cpp"}));
  EXPECT_TRUE(throws_vv_error([&] { vv::replace_flag(x, V()); },
                              {"replace flag", "null", "edits_test.cpp"}));
  EXPECT_TRUE(throws_vv_error([&] { vv::erase_flag(V()); },
                              {"erase flag", "null", "edits_test.cpp"}));
}

// ---------------------------------------------- the flag is a position

TEST_F(Edits, FlagStableUnderSpliceOfOtherEntries) {
  vv::flag_in(c, v);
  vv::splice_before(x, a, v);  // before the flagged position
  EXPECT_EQ(vv::flagged_in(v), c);
  vv::splice_after(y, c, v);  // right after it
  EXPECT_EQ(vv::flagged_in(v), c);
  V z = ctx.new_vertex();
  vv::splice_before(z, c, v);  // right before it
  EXPECT_EQ(vv::flagged_in(v), c);
  EXPECT_EQ(vv::next_to_flag(v), y);
  EXPECT_EQ(vv::prev_to_flag(v), z);
  EXPECT_EQ(cycle(v), canon(labels({x, a, b, z, c, y, d})));
  EXPECT_TRUE(invariants_hold({v, a, b, c, d, x, y, z}));
}

TEST_F(Edits, FlagStableUnderReplaceOfOtherEntries) {
  vv::flag_in(c, v);
  vv::replace_in(a, x, v);
  EXPECT_EQ(vv::flagged_in(v), c);
  vv::replace_in(d, y, v);
  EXPECT_EQ(vv::flagged_in(v), c);
  EXPECT_EQ(vv::next_to_flag(v), y);
  EXPECT_EQ(nb_labels(v), labels({x, b, c, y}));
  EXPECT_TRUE(ok());
}

TEST_F(Edits, FlagStableUnderEraseOfOtherEntries) {
  vv::flag_in(c, v);
  vv::erase_from(a, v);  // before the flagged entry
  EXPECT_EQ(vv::flagged_in(v), c);
  vv::erase_from(d, v);  // after it
  EXPECT_EQ(vv::flagged_in(v), c);
  vv::erase_from(b, v);
  EXPECT_EQ(vv::flagged_in(v), c);
  EXPECT_EQ(nb_labels(v), labels({c}));
  EXPECT_EQ(vv::next_to_flag(v), c);
  EXPECT_TRUE(ok());
}

TEST_F(Edits, FlagStableUnderFlagEditsAroundIt) {
  vv::flag_in(b, v);
  vv::splice_after_flag(x, v);
  vv::splice_before_flag(y, v);
  EXPECT_EQ(vv::flagged_in(v), b);
  EXPECT_EQ(vv::next_to_flag(v), x);
  EXPECT_EQ(vv::prev_to_flag(v), y);
  EXPECT_EQ(cycle(v), canon(labels({a, y, b, x, c, d})));
  EXPECT_TRUE(ok());
}

TEST_F(Edits, ErasingTheFlaggedEntryUnsetsTheFlag) {
  vv::flag_in(b, v);
  vv::erase_from(b, v);
  EXPECT_FALSE(vv::flagged_in(v));
  // and the flag does not come back when b returns
  vv::splice_after(b, a, v);
  EXPECT_FALSE(vv::flagged_in(v));
  EXPECT_TRUE(ok());
}

TEST_F(Edits, MakeUnsetsTheFlagEvenWithSameList) {
  vv::flag_in(d, v);
  vv::make_nb(v, {a, b, c, d});
  EXPECT_FALSE(vv::flagged_in(v));
  EXPECT_TRUE(ok());
}

TEST_F(Edits, ReplacingTheFlaggedEntryKeepsThePosition) {
  vv::flag_in(b, v);
  vv::replace_in(b, x, v);
  EXPECT_EQ(vv::flagged_in(v), x);
  EXPECT_TRUE(ok());
}

// ------------------------------------------------------------ one at a time

TEST_F(Edits, EditsTouchOneNeighbourhoodOnly) {
  vv::make_nb(a, {v, b});
  vv::make_nb(b, {v, a});
  vv::erase_from(a, v);
  EXPECT_EQ(nb_labels(a), labels({v, b}));  // a still lists v
  vv::replace_in(b, x, v);
  EXPECT_EQ(nb_labels(b), labels({v, a}));
  EXPECT_TRUE(nb_labels(x).empty());
  vv::splice_after(y, x, v);
  EXPECT_TRUE(nb_labels(y).empty());
  EXPECT_EQ(cycle(v), canon(labels({x, y, c, d})));
  EXPECT_TRUE(ok());
}

TEST_F(Edits, EditsDoNotTouchTheOldState) {
  G::mesh M(ctx);
  M.add(v);
  vv::flag_in(b, v);
  vv::synchronise(M);
  vv::erase_from(a, v);
  vv::replace_in(b, x, v);
  vv::splice_after(y, c, v);
  vv::erase_flag(v);
  EXPECT_EQ(cycle(v), canon(labels({c, y, d})));
  EXPECT_EQ(nb_labels(vv::old(v)), labels({a, b, c, d}));
  EXPECT_EQ(vv::flagged_in(vv::old(v)), b);
  EXPECT_EQ(vv::edge(vv::old(v), b).mark, 20);
  EXPECT_TRUE(ok());
}

}  // namespace
