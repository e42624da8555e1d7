// Half-edge records (LANGUAGE.md section 4.2) and path expressions
// (section 4.1), on the double pyramid.
//
// Pyramid labels (file index + 1) and neighbourhoods:
//   1: 2 6 4 5   2: 3 6 1 5   3: 4 6 2 5
//   4: 1 6 3 5   5: 4 3 2 1   6: 1 2 3 4
#include "test_meshes.hpp"

#include <gtest/gtest.h>

#include <type_traits>
#include <vector>

namespace {

using namespace vvtest;

class Pyramid : public ::testing::Test {
 protected:
  Pyramid() : M(ctx), p(build_double_pyramid(ctx, M)) {}
  ::testing::AssertionResult ok() {
    try {
      vv::check_invariants(M);
    } catch (const vv::error& e) {
      return ::testing::AssertionFailure() << e.what();
    }
    return ::testing::AssertionSuccess();
  }
  G::context ctx;
  G::mesh M;
  std::vector<V> p;  // p[i] has label i + 1
};

// =========================================================== (a^b) records

using Edges = Pyramid;

TEST_F(Edges, RecordsStartDefault) {
  for (const V& v : p)
    for (V x : vv::each(v)) {
      EXPECT_EQ(vv::edge(v, x).mark, 0);
      EXPECT_FALSE(vv::edge(v, x).b);
      EXPECT_EQ(vv::edge(v, x), EP{});
    }
}

TEST_F(Edges, ReadWriteIsPerHalfEdge) {
  vv::edge(p[0], p[1]).mark = 3;
  vv::edge(p[0], p[1]).b = true;
  EXPECT_EQ(vv::edge(p[0], p[1]).mark, 3);
  EXPECT_TRUE(vv::edge(p[0], p[1]).b);
  // The opposite half-edge and the other entries are separate records.
  EXPECT_EQ(vv::edge(p[1], p[0]).mark, 0);
  EXPECT_FALSE(vv::edge(p[1], p[0]).b);
  EXPECT_EQ(vv::edge(p[0], p[5]).mark, 0);
  EXPECT_EQ(vv::edge(p[0], p[4]).mark, 0);
  vv::edge(p[1], p[0]).mark = -8;
  EXPECT_EQ(vv::edge(p[0], p[1]).mark, 3);
  EXPECT_EQ(vv::edge(p[1], p[0]).mark, -8);
  EXPECT_TRUE(ok());
}

TEST_F(Edges, ReferenceIsTheStoredRecord) {
  EP& r = vv::edge(p[2], p[5]);
  r.mark = 12;
  ++vv::edge(p[2], p[5]).mark;
  EXPECT_EQ(r.mark, 13);
  EXPECT_EQ(vv::edge(p[2], p[5]).mark, 13);
  static_assert(std::is_same_v<decltype(vv::edge(p[0], p[1])), EP&>, "(a^b) is writable");
}

TEST_F(Edges, CopyAssignBetweenRecords) {
  vv::edge(p[2], p[3]) = EP{5, true};
  vv::edge(p[0], p[1]) = vv::edge(p[2], p[3]);  // (a^b) = (c^d)
  EXPECT_EQ(vv::edge(p[0], p[1]).mark, 5);
  EXPECT_TRUE(vv::edge(p[0], p[1]).b);
  EXPECT_EQ(vv::edge(p[0], p[1]), vv::edge(p[2], p[3]));
  // A copy, not an alias.
  vv::edge(p[2], p[3]).mark = 6;
  EXPECT_EQ(vv::edge(p[0], p[1]).mark, 5);
  EXPECT_NE(vv::edge(p[0], p[1]), vv::edge(p[2], p[3]));
  EXPECT_TRUE(ok());
}

TEST_F(Edges, LocalEdgeValue) {
  G::edge e;  // `edge e;`
  EXPECT_EQ(e.mark, 0);
  EXPECT_FALSE(e.b);
  e.mark = 4;
  vv::edge(p[4], p[0]) = e;
  e.mark = 9;
  EXPECT_EQ(vv::edge(p[4], p[0]).mark, 4);
  G::edge f = vv::edge(p[4], p[0]);
  f.b = true;
  EXPECT_TRUE(f.b);
  EXPECT_EQ(f.mark, 4);
  EXPECT_FALSE(vv::edge(p[4], p[0]).b);
}

TEST_F(Edges, ErrorWhenBNotInA) {
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::edge(p[0], p[2]); },
                              {"^", "vertex 1", "vertex 3", "edges_paths_test.cpp"}));
  EXPECT_TRUE(throws_vv_error([&] { vv::edge(p[4], p[5]).mark = 1; }, {"vertex 5", "vertex 6"}));
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::edge(p[0], p[0]); }, {"vertex 1"}));
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::edge(p[0], V()); }, {"null"}));
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::edge(V(), p[0]); }, {"null"}));
  // Asymmetric: b in a* but a not in b* -> only a->b exists.
  vv::erase_from(p[0], p[1]);
  EXPECT_NO_THROW((void)vv::edge(p[0], p[1]));
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::edge(p[1], p[0]); }, {"vertex 2", "vertex 1"}));
}

TEST_F(Edges, RecordGoesAwayWithTheEntry) {
  vv::edge(p[0], p[1]).mark = 7;
  vv::erase_from(p[1], p[0]);
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::edge(p[0], p[1]); }, {"^"}));
  vv::splice_before(p[1], p[5], p[0]);  // a new entry: a new default record
  EXPECT_EQ(vv::edge(p[0], p[1]).mark, 0);
  EXPECT_TRUE(ok());
}

// =========================================================== (a|b) records

// Issue 9, item 15: a record reference is valid until the next edit of
// the neighbourhood it lives in; records keep their values through edits
// (read them again through (a^b)).
TEST_F(Edges, RecordsKeepTheirValuesThroughEditsOfTheNeighbourhood) {
  const std::vector<V> around = {p[1], p[5], p[3], p[4]};  // 1: 2 6 4 5
  for (std::size_t i = 0; i < around.size(); ++i) vv::edge(p[0], around[i]).mark = 10 + static_cast<int>(i);
  std::vector<V> added;
  for (int i = 0; i < 12; ++i) {  // past the inline capacity and back
    added.push_back(ctx.new_vertex());
    vv::splice_after(added.back(), p[1], p[0]);
  }
  for (const V& x : added) vv::erase_from(x, p[0]);
  for (std::size_t i = 0; i < around.size(); ++i)
    EXPECT_EQ(vv::edge(p[0], around[i]).mark, 10 + static_cast<int>(i));
  EXPECT_TRUE(ok());
}

#if VV_MOVE_RECORDS_ON_EDIT
// The sanitizer build moves a neighbourhood's records on every edit, so a
// reference kept past an edit is reported by AddressSanitizer where it is
// used, instead of silently writing into another entry.
TEST_F(Edges, AReferenceKeptPastAnEditIsReportedInTheSanitizerBuild) {
  EXPECT_DEATH(
      {
        EP& kept = vv::edge(p[0], p[1]);
        V x = ctx.new_vertex();
        vv::splice_after(x, p[1], p[0]);
        kept.mark = 7;
      },
      "heap-use-after-free");
}
#endif

TEST_F(Edges, SymmetricWritesBothDirections) {
  vv::edge(p[1], p[0]).b = true;
  vv::sym_edge(p[0], p[1]).mark = 9;
  EXPECT_EQ(vv::edge(p[0], p[1]).mark, 9);
  EXPECT_EQ(vv::edge(p[1], p[0]).mark, 9);
  // The whole record a->b is copied onto b->a.
  EXPECT_FALSE(vv::edge(p[1], p[0]).b);
  EXPECT_EQ(vv::edge(p[0], p[1]), vv::edge(p[1], p[0]));
  // Other records are untouched.
  EXPECT_EQ(vv::edge(p[1], p[2]).mark, 0);
  EXPECT_EQ(vv::edge(p[0], p[5]).mark, 0);
  EXPECT_TRUE(ok());
}

TEST_F(Edges, SymmetricCopyHappensAfterTheFullExpression) {
  int during = (vv::sym_edge(p[0], p[1]).mark = 9, vv::edge(p[1], p[0]).mark);
  EXPECT_EQ(during, 0);  // not yet copied inside the expression
  EXPECT_EQ(vv::edge(p[1], p[0]).mark, 9);  // copied at its end
  // Several updates in one expression: the final a->b value is copied.
  EP& r = vv::sym_edge(p[2], p[3]);
  r.mark = 1;  // r outlives its full expression: that copy already happened
  EXPECT_EQ(vv::edge(p[3], p[2]).mark, 0);
  (void)(vv::sym_edge(p[2], p[3]).mark += 10, vv::sym_edge(p[2], p[3]).mark += 100);
  EXPECT_EQ(vv::edge(p[2], p[3]).mark, 111);
  EXPECT_EQ(vv::edge(p[3], p[2]).mark, 111);
}

TEST_F(Edges, SymmetricAccessThatOnlyReadsAlsoEqualises) {
  vv::edge(p[0], p[4]).mark = 4;
  vv::edge(p[4], p[0]).mark = 40;
  int m = vv::sym_edge(p[0], p[4]).mark;
  EXPECT_EQ(m, 4);
  EXPECT_EQ(vv::edge(p[4], p[0]).mark, 4);
  EXPECT_EQ(vv::edge(p[0], p[4]).mark, 4);
}

TEST_F(Edges, SymmetricWritesOnlyAToBWhenANotInB) {
  vv::erase_from(p[0], p[1]);  // p[1] is in p[0]*, p[0] is not in p[1]*
  vv::edge(p[1], p[2]).mark = 2;
  nb_state before = state_of(p[1]);
  vv::sym_edge(p[0], p[1]).mark = 9;
  EXPECT_EQ(vv::edge(p[0], p[1]).mark, 9);
  EXPECT_EQ(state_of(p[1]), before);  // b's neighbourhood and records untouched
  EXPECT_FALSE(vv::is_in(p[0], p[1]));
  EXPECT_TRUE(ok());
}

TEST_F(Edges, SymmetricErrorWhenBNotInA) {
  EXPECT_TRUE(throws_vv_error([&] { vv::sym_edge(p[0], p[2]).mark = 1; },
                              {"vertex 1", "vertex 3", "edges_paths_test.cpp"}));
  EXPECT_EQ(vv::edge(p[2], p[1]).mark, 0);
  vv::erase_from(p[1], p[0]);
  // a in b* but b not in a*: there is no record a->b.
  EXPECT_TRUE(throws_vv_error([&] { vv::sym_edge(p[0], p[1]).mark = 1; }, {"vertex 2"}));
  EXPECT_EQ(vv::edge(p[1], p[0]).mark, 0);
}

// ====================================================== old records ((`a)^b)

TEST_F(Edges, OldRecordReadsTheSynchronisedValue) {
  vv::edge(p[0], p[1]) = EP{2, true};
  vv::synchronise(M);
  vv::edge(p[0], p[1]) = EP{5, false};
  EXPECT_EQ(vv::edge(vv::old(p[0]), p[1]).mark, 2);
  EXPECT_TRUE(vv::edge(vv::old(p[0]), p[1]).b);
  EXPECT_EQ(vv::edge(p[0], p[1]).mark, 5);
  vv::sym_edge(p[0], p[1]).mark = 7;
  EXPECT_EQ(vv::edge(vv::old(p[0]), p[1]).mark, 2);
  EXPECT_EQ(vv::edge(vv::old(p[1]), p[0]).mark, 0);
  vv::synchronise(M);
  EXPECT_EQ(vv::edge(vv::old(p[0]), p[1]).mark, 7);
  EXPECT_EQ(vv::edge(vv::old(p[1]), p[0]).mark, 7);
}

TEST_F(Edges, OldSymmetricAccessReadsTheSynchronisedRecord) {
  vv::edge(p[3], p[4]).mark = 11;
  vv::synchronise(M);
  vv::edge(p[3], p[4]).mark = 12;
  const EP& r = vv::sym_edge(vv::old(p[3]), p[4]);  // ((`a)|b)
  EXPECT_EQ(r.mark, 11);
  EXPECT_EQ(vv::edge(p[4], p[3]).mark, 0);  // reading the old state copies nothing
  static_assert(
      std::is_const_v<std::remove_reference_t<decltype(vv::sym_edge(vv::old(p[3]), p[4]))>>,
      "((`a)|b) is read-only");
}

TEST_F(Edges, OldRecordSurvivesEditsOfTheCurrentNeighbourhood) {
  vv::edge(p[0], p[1]).mark = 3;
  vv::synchronise(M);
  vv::erase_from(p[1], p[0]);
  vv::splice_after(p[2], p[5], p[0]);
  EXPECT_EQ(vv::edge(vv::old(p[0]), p[1]).mark, 3);
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::edge(p[0], p[1]); }, {"^"}));
  // p[2] is in the current p[0]* only.
  EXPECT_EQ(vv::edge(p[0], p[2]).mark, 0);
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::edge(vv::old(p[0]), p[2]); },
                              {"vertex 1", "vertex 3"}));
  EXPECT_TRUE(ok());
}

TEST_F(Edges, OldRecordErrorWhenBNotInOldA) {
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::edge(vv::old(p[0]), p[1]); },
                              {"vertex 1", "vertex 2"}));  // never synchronised: empty
  vv::synchronise(M);
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::edge(vv::old(p[0]), p[2]); },
                              {"^", "vertex 1", "vertex 3", "edges_paths_test.cpp"}));
  EXPECT_NO_THROW((void)vv::edge(vv::old(p[0]), p[1]));
}

// ================================================================== paths

using Paths = Pyramid;

TEST_F(Paths, NoOpsGivesTheSecondVertex) {
  EXPECT_EQ(vv::path(p[0], p[1]).second(), p[1]);
  EXPECT_EQ(vv::path(p[0], p[1]).first(), p[0]);
}

TEST_F(Paths, Next) {
  EXPECT_EQ(vv::path(p[0], p[1]).next().second().label(), 6u);
  EXPECT_EQ(vv::path(p[0], p[4]).next().second().label(), 2u);
  EXPECT_EQ(vv::path(p[0], p[1]).next().next().second().label(), 4u);
  EXPECT_EQ(vv::path(p[0], p[1]).next().first(), p[0]);
  for (const V& a : p)
    for (V b : vv::each(a)) EXPECT_EQ(vv::path(a, b).next().second(), vv::next_to(b, a));
}

TEST_F(Paths, Prev) {
  EXPECT_EQ(vv::path(p[0], p[1]).prev().second().label(), 5u);
  EXPECT_EQ(vv::path(p[5], p[2]).prev().second().label(), 2u);
  EXPECT_EQ(vv::path(p[0], p[1]).next().prev().second(), p[1]);
  for (const V& a : p)
    for (V b : vv::each(a)) EXPECT_EQ(vv::path(a, b).prev().second(), vv::prev_to(b, a));
}

TEST_F(Paths, Swap) {
  auto w = vv::path(p[0], p[1]);
  w.swap();
  EXPECT_EQ(w.first(), p[1]);
  EXPECT_EQ(w.second(), p[0]);
  EXPECT_EQ(vv::path(p[0], p[1]).swap().swap().second(), p[1]);
}

TEST_F(Paths, NextOnANonNeighbourIsNull) {
  EXPECT_FALSE(vv::path(p[0], p[2]).next().second());
  EXPECT_FALSE(vv::path(p[4], p[5]).prev().second());
}

TEST_F(Paths, SwapNextSwapNext) {
  // @(a, b) swap next swap next @ = nextto b in (nextto a in b)
  V r = vv::path(p[0], p[1]).swap().next().swap().next().second();
  EXPECT_EQ(r.label(), 1u);
  EXPECT_EQ(vv::path(p[0], p[1]).swap().next().swap().next().first().label(), 5u);
  for (const V& b : p)
    for (V a : vv::each(b))
      EXPECT_EQ(vv::path(a, b).swap().next().swap().next().second(),
                vv::next_to(b, vv::next_to(a, b)));
}

TEST_F(Paths, LanguageExampleEquality) {
  // LANGUAGE.md 4.1: @(a, b) swap next next swap next @ ==
  //                  nextto b in (nextto (nextto a in b) in b)
  V a = p[0], b = p[1];
  V lhs = vv::path(a, b).swap().next().next().swap().next().second();
  V rhs = vv::next_to(b, vv::next_to(vv::next_to(a, b), b));
  EXPECT_EQ(lhs, rhs);
  EXPECT_EQ(lhs.label(), 5u);
  // ... and for every oriented edge of the pyramid.
  std::vector<unsigned> got, expected;
  for (const V& bb : p)
    for (V aa : vv::each(bb)) {
      got.push_back(vv::path(aa, bb).swap().next().next().swap().next().second().label());
      expected.push_back(vv::next_to(bb, vv::next_to(vv::next_to(aa, bb), bb)).label());
    }
  EXPECT_EQ(got, expected);
  EXPECT_EQ(got.size(), 24u);
  // First pair: b = 1, a = 2: nextto 2 in 1* is 6, nextto 6 in 1* is 4,
  // nextto 1 in 4* (1 6 3 5) is 6.
  EXPECT_EQ(got[0], 6u);
}

TEST_F(Paths, OldPathWalksOldNeighbourhoods) {
  vv::synchronise(M);
  // Turn every current neighbourhood around: current walks now differ.
  for (const V& v : p) {
    std::vector<V> rev;
    for (V x : vv::each(v)) rev.insert(rev.begin(), x);
    vv::make_nb_from(v, rev);
  }
  EXPECT_EQ(vv::path(p[0], p[1]).next().second().label(), 5u);
  EXPECT_EQ(vv::old_path(p[0], p[1]).next().second().label(), 6u);
  EXPECT_EQ(vv::old_path(p[0], p[1]).prev().second().label(), 5u);
  EXPECT_EQ(vv::old_path(p[0], p[1]).swap().next().next().swap().next().second().label(), 5u);
  // Against an untouched pyramid in another context, every walk agrees.
  G::context ctx2;
  G::mesh M2(ctx2);
  auto q = build_double_pyramid(ctx2, M2);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      if (!vv::is_in(q[j], q[i])) continue;
      EXPECT_EQ(vv::old_path(p[i], p[j]).swap().next().next().swap().next().second().label(),
                vv::path(q[i], q[j]).swap().next().next().swap().next().second().label());
      EXPECT_EQ(vv::old_path(p[i], p[j]).prev().swap().prev().second().label(),
                vv::path(q[i], q[j]).prev().swap().prev().second().label());
    }
}

TEST_F(Paths, OldPathAfterEraseStillFindsOldNeighbours) {
  vv::synchronise(M);
  vv::make_nb(p[0], {});
  EXPECT_FALSE(vv::path(p[0], p[1]).next().second());
  EXPECT_EQ(vv::old_path(p[0], p[1]).next().second().label(), 6u);
}

TEST_F(Paths, AWalkCountsNoReferences) {
  // A step is a neighbour search over slots; only the vertices handed out
  // are counted.
  const std::uint32_t a_refs = ctx.refs(p[0].slot()), b_refs = ctx.refs(p[1].slot());
  auto w = vv::path(p[0], p[1]);
  w.next().prev();
  EXPECT_EQ(ctx.refs(p[0].slot()), a_refs);
  EXPECT_EQ(ctx.refs(p[1].slot()), b_refs);
  V b = w.second();
  EXPECT_EQ(b, p[1]);
  EXPECT_EQ(ctx.refs(p[1].slot()), b_refs + 1);
}

TEST_F(Paths, StepsFromTheNullVertexAreErrors) {
  V a, b = p[1];
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::path(a, b).next().second(); },
                              {"nextto", "the target is the null vertex", "edges_paths_test.cpp"}));
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::path(a, b).prev().second(); }, {"prevto", "null vertex"}));
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::old_path(a, b).next().second(); },
                              {"`", "old state of the null vertex"}));
  // A walk that reached null by a step stops there with the same error.
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::path(p[0], p[2]).next().swap().next().second(); },
                              {"the target is the null vertex"}));
}

TEST_F(Paths, StrictOldPathRefusesANeverSynchronisedVertex) {
  ctx.strict_old_state = true;
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::old_path(p[0], p[1]).next().second(); },
                              {"vertex 1 has never been synchronised (strict mode)"}));
  vv::synchronise(M);
  EXPECT_EQ(vv::old_path(p[0], p[1]).next().second().label(), 6u);
}

TEST_F(Paths, AVertexOfAnotherContextIsNoNeighbour) {
  G::context other;
  V stranger = other.new_vertex();
  EXPECT_FALSE(vv::path(p[0], stranger).next().second());
  EXPECT_FALSE(vv::old_path(p[0], stranger).prev().second());
}

TEST_F(Paths, PathIntoAssignsBothVariables) {
  V a = p[0], b = p[1];
  V r = vv::path_into(a, b).swap().next().store();
  EXPECT_EQ(a, p[1]);
  EXPECT_EQ(b.label(), 5u);  // nextto 1 in 2
  EXPECT_EQ(r, b);
  // The vertices themselves are untouched, only the variables change.
  EXPECT_EQ(p[0].label(), 1u);
  EXPECT_EQ(p[1].label(), 2u);
  vv::path_into(a, b).prev().store();
  EXPECT_EQ(a, p[1]);
  EXPECT_EQ(b.label(), 1u);  // prevto 5 in 2
  vv::path_into(a, b).swap().store();
  EXPECT_EQ(a.label(), 1u);
  EXPECT_EQ(b.label(), 2u);
}

TEST_F(Paths, OldPathIntoAssignsFromOldNeighbourhoods) {
  vv::synchronise(M);
  vv::make_nb(p[1], {p[2], p[0]});
  V a = p[0], b = p[1];
  vv::old_path_into(a, b).swap().next().store();
  EXPECT_EQ(a.label(), 2u);
  EXPECT_EQ(b.label(), 5u);  // old 2*: 3 6 1 5
  V c = p[0], d = p[1];
  vv::path_into(c, d).swap().next().store();
  EXPECT_EQ(c.label(), 2u);
  EXPECT_EQ(d.label(), 3u);  // current 2*: 3 1
}

TEST_F(Paths, FaceOrbitWalkReturnsAfterThreeSteps) {
  vv::synchronise(M);
  // Scramble the current state so that only old neighbourhoods give faces.
  for (const V& v : p) vv::make_nb(v, {});
  V v = p[0], q = p[1];
  V a = v, b = q;
  std::vector<unsigned> visited;
  int steps = 0;
  do {
    vv::old_path_into(a, b).swap().next().store();
    visited.push_back(a.label());
    ++steps;
  } while (a != v && steps < 10);
  EXPECT_EQ(steps, 3);
  EXPECT_EQ(visited, (std::vector<unsigned>{2, 5, 1}));
  EXPECT_EQ(a, v);
  EXPECT_EQ(b, q);  // the walk closes on the starting oriented edge
}

TEST_F(Paths, EveryOrientedEdgeLiesOnATriangle) {
  vv::synchronise(M);
  int edges = 0;
  for (const V& v : p)
    for (V q : vv::each(vv::old(v))) {
      V a = v, b = q;
      int steps = 0;
      do {
        vv::old_path_into(a, b).swap().next().store();
        ++steps;
      } while (a != v && steps < 10);
      EXPECT_EQ(steps, 3) << "from " << v << " to " << q;
      EXPECT_EQ(b, q);
      ++edges;
    }
  EXPECT_EQ(edges, 24);  // 8 triangles x 3
}

}  // namespace
