// Neighbourhood queries and selections (LANGUAGE.md section 4, first table),
// on current and old states, checked on the double pyramid.
//
// Pyramid labels (file index + 1) and neighbourhoods:
//   1: 2 6 4 5   2: 3 6 1 5   3: 4 6 2 5
//   4: 1 6 3 5   5: 4 3 2 1   6: 1 2 3 4
#include "test_meshes.hpp"

#include <gtest/gtest.h>

#include <limits>

#include <vector>

namespace {

using namespace vvtest;

class Queries : public ::testing::Test {
 protected:
  Queries() : M(ctx), p(build_double_pyramid(ctx, M)) {}
  G::context ctx;
  G::mesh M;
  std::vector<V> p;  // p[i] has label i + 1
};

// ------------------------------------------------------------------ valence

TEST_F(Queries, ValenceCountsNeighbours) {
  for (const V& v : p) EXPECT_EQ(vv::valence(v), 4u) << v;
  V lone = ctx.new_vertex();
  EXPECT_EQ(vv::valence(lone), 0u);
  vv::make_nb(lone, {p[0], p[2]});
  EXPECT_EQ(vv::valence(lone), 2u);
  vv::erase_from(p[1], p[0]);
  EXPECT_EQ(vv::valence(p[0]), 3u);
}

// -------------------------------------------------------------------- is in

TEST_F(Queries, IsInTrueForNeighbours) {
  EXPECT_TRUE(vv::is_in(p[1], p[0]));
  EXPECT_TRUE(vv::is_in(p[5], p[0]));
  EXPECT_TRUE(vv::is_in(p[3], p[0]));
  EXPECT_TRUE(vv::is_in(p[4], p[0]));
}

TEST_F(Queries, IsInFalseForNonNeighbours) {
  EXPECT_FALSE(vv::is_in(p[2], p[0]));  // opposite corner
  EXPECT_FALSE(vv::is_in(p[0], p[0]));  // never its own neighbour
  EXPECT_FALSE(vv::is_in(p[5], p[4]));  // opposite apex
  V other = ctx.new_vertex();
  EXPECT_FALSE(vv::is_in(other, p[0]));
  EXPECT_FALSE(vv::is_in(V(), p[0]));  // the null vertex is nobody's neighbour
}

TEST_F(Queries, IsInIsNotSymmetricByItself) {
  vv::erase_from(p[1], p[0]);
  EXPECT_FALSE(vv::is_in(p[1], p[0]));
  EXPECT_TRUE(vv::is_in(p[0], p[1]));
}

// ------------------------------------------------------------------- any in

TEST_F(Queries, AnyInIsTheFirstEntry) {
  EXPECT_EQ(vv::any_in(p[0]).label(), 2u);
  EXPECT_EQ(vv::any_in(p[4]).label(), 4u);
  EXPECT_EQ(vv::any_in(p[5]).label(), 1u);
  V v = ctx.new_vertex();
  vv::make_nb(v, {p[3], p[1], p[2]});
  EXPECT_EQ(vv::any_in(v), p[3]);
}

TEST_F(Queries, AnyInNullWhenEmpty) {
  V v = ctx.new_vertex();
  EXPECT_FALSE(vv::any_in(v));
  EXPECT_EQ(vv::any_in(v).label(), 0u);
  vv::make_nb(v, {p[0]});
  vv::erase_from(p[0], v);
  EXPECT_FALSE(vv::any_in(v));
}

// ------------------------------------------------------------------- nextto

TEST_F(Queries, NextToGivesTheFollowingNeighbour) {
  EXPECT_EQ(vv::next_to(p[1], p[0]).label(), 6u);
  EXPECT_EQ(vv::next_to(p[5], p[0]).label(), 4u);
  EXPECT_EQ(vv::next_to(p[3], p[0]).label(), 5u);
  EXPECT_EQ(vv::next_to(p[3], p[4]).label(), 3u);
}

TEST_F(Queries, NextToWrapsAroundTheCycle) {
  EXPECT_EQ(vv::next_to(p[4], p[0]).label(), 2u);  // last -> first
  EXPECT_EQ(vv::next_to(p[0], p[4]).label(), 4u);
  V v = ctx.new_vertex();
  vv::make_nb(v, {p[2]});
  EXPECT_EQ(vv::next_to(p[2], v), p[2]);  // a single neighbour follows itself
}

TEST_F(Queries, NextToNullWhenNotANeighbour) {
  EXPECT_FALSE(vv::next_to(p[2], p[0]));
  EXPECT_FALSE(vv::next_to(p[0], p[0]));
  EXPECT_FALSE(vv::next_to(V(), p[0]));
  V empty = ctx.new_vertex();
  EXPECT_FALSE(vv::next_to(p[0], empty));
}

// ------------------------------------------------------------------- prevto

TEST_F(Queries, PrevToGivesThePrecedingNeighbour) {
  EXPECT_EQ(vv::prev_to(p[5], p[0]).label(), 2u);
  EXPECT_EQ(vv::prev_to(p[3], p[0]).label(), 6u);
  EXPECT_EQ(vv::prev_to(p[4], p[0]).label(), 4u);
  EXPECT_EQ(vv::prev_to(p[2], p[5]).label(), 2u);
}

TEST_F(Queries, PrevToWrapsAroundTheCycle) {
  EXPECT_EQ(vv::prev_to(p[1], p[0]).label(), 5u);  // first -> last
  EXPECT_EQ(vv::prev_to(p[0], p[5]).label(), 4u);
}

TEST_F(Queries, PrevToNullWhenNotANeighbour) {
  EXPECT_FALSE(vv::prev_to(p[2], p[0]));
  EXPECT_FALSE(vv::prev_to(p[4], p[4]));
  EXPECT_FALSE(vv::prev_to(V(), p[0]));
}

TEST_F(Queries, NextToAndPrevToAreInverse) {
  for (const V& v : p)
    for (V x : vv::each(v)) {
      EXPECT_EQ(vv::prev_to(vv::next_to(x, v), v), x);
      EXPECT_EQ(vv::next_to(vv::prev_to(x, v), v), x);
    }
}

// ----------------------------------------------------------- next(i)to etc.

TEST_F(Queries, NextIToWithOneIsNextTo) {
  for (V x : vv::each(p[0])) EXPECT_EQ(vv::next_to(x, p[0], 1), vv::next_to(x, p[0]));
  EXPECT_EQ(vv::next_to(p[1], p[0], 1).label(), 6u);
}

TEST_F(Queries, NextIToWithTwo) {
  EXPECT_EQ(vv::next_to(p[1], p[0], 2).label(), 4u);
  EXPECT_EQ(vv::next_to(p[3], p[0], 2).label(), 2u);  // wraps
  EXPECT_EQ(vv::next_to(p[4], p[0], 2).label(), 6u);
  EXPECT_EQ(vv::next_to(p[1], p[0], 2), vv::next_to(vv::next_to(p[1], p[0]), p[0]));
}

TEST_F(Queries, NextIToWithValenceIsXItself) {
  for (V x : vv::each(p[4])) EXPECT_EQ(vv::next_to(x, p[4], 4), x);
  V v = ctx.new_vertex();
  vv::make_nb(v, {p[0], p[1], p[2], p[3], p[4], p[5]});
  EXPECT_EQ(vv::next_to(p[2], v, 6), p[2]);
}

TEST_F(Queries, NextIToWithValencePlusOneIsNextTo) {
  for (V x : vv::each(p[4])) EXPECT_EQ(vv::next_to(x, p[4], 5), vv::next_to(x, p[4]));
  EXPECT_EQ(vv::next_to(p[3], p[4], 5).label(), 3u);
  EXPECT_EQ(vv::next_to(p[3], p[4], 9).label(), 3u);  // 2 * valence + 1
}

TEST_F(Queries, NextIToNullWhenNotANeighbour) {
  EXPECT_FALSE(vv::next_to(p[2], p[0], 2));
  EXPECT_FALSE(vv::next_to(V(), p[0], 3));
}

// Issue 9, item 13: a count below 1 was taken silently (next(0)to gave x
// itself, next(-1)to acted as prevto), and LONG_MAX / LONG_MIN overflowed.
TEST_F(Queries, NextIToAndPrevIToRefuseACountBelowOne) {
  for (long bad : {0L, -1L, -7L, std::numeric_limits<long>::min()}) {
    try {
      vv::next_to(p[1], p[0], bad, vv::where{"model.vvp", 12});
      ADD_FAILURE() << "next(" << bad << ")to was accepted";
    } catch (const vv::error& e) {
      EXPECT_EQ(std::string(e.what()),
                "model.vvp:12: next(i)to: the count must be 1 or more, not " + std::to_string(bad));
    }
    EXPECT_THROW(vv::prev_to(p[1], p[0], bad), vv::error);
  }
}

TEST_F(Queries, AHugeCountIsTakenModuloTheValence) {
  long big = std::numeric_limits<long>::max();
  long rest = big % static_cast<long>(vv::valence(p[0]));
  V forward = rest ? vv::next_to(p[1], p[0], rest) : p[1];
  V backward = rest ? vv::prev_to(p[1], p[0], rest) : p[1];
  EXPECT_EQ(vv::next_to(p[1], p[0], big), forward);
  EXPECT_EQ(vv::prev_to(p[1], p[0], big), backward);
}

// Every position, count and direction of a fan of each valence 1..9,
// against index arithmetic: the cyclic step avoids division for counts
// below the valence and must agree with the modulo everywhere.
TEST(CyclicSteps, NextIToAndPrevIToAgreeWithModuloArithmeticOnEveryValence) {
  for (unsigned n = 1; n <= 9; ++n) {
    G::context ctx;
    V centre = ctx.new_vertex();
    std::vector<V> ring;
    for (unsigned i = 0; i < n; ++i) ring.push_back(ctx.new_vertex());
    vv::make_nb_from(centre, ring);
    for (unsigned pos = 0; pos < n; ++pos)
      for (long count = 1; count <= 3 * long(n) + 1; ++count) {
        unsigned k = static_cast<unsigned>(count % long(n));
        EXPECT_EQ(vv::next_to(ring[pos], centre, count), ring[(pos + k) % n])
            << "valence " << n << ", position " << pos << ", count " << count;
        EXPECT_EQ(vv::prev_to(ring[pos], centre, count), ring[(pos + n - k) % n])
            << "valence " << n << ", position " << pos << ", count " << count;
      }
    for (unsigned pos = 0; pos < n; ++pos) {
      vv::flag_in(ring[pos], centre);
      EXPECT_EQ(vv::next_to_flag(centre), ring[(pos + 1) % n]) << "valence " << n << ", flag at " << pos;
      EXPECT_EQ(vv::prev_to_flag(centre), ring[(pos + n - 1) % n]) << "valence " << n << ", flag at " << pos;
    }
  }
}

TEST_F(Queries, PrevIToWithOneIsPrevTo) {
  for (V x : vv::each(p[0])) EXPECT_EQ(vv::prev_to(x, p[0], 1), vv::prev_to(x, p[0]));
  EXPECT_EQ(vv::prev_to(p[5], p[0], 1).label(), 2u);
}

TEST_F(Queries, PrevIToWithTwo) {
  EXPECT_EQ(vv::prev_to(p[3], p[0], 2).label(), 2u);
  EXPECT_EQ(vv::prev_to(p[1], p[0], 2).label(), 4u);  // wraps
  EXPECT_EQ(vv::prev_to(p[5], p[0], 2).label(), 5u);
  EXPECT_EQ(vv::prev_to(p[0], p[5], 2), vv::prev_to(vv::prev_to(p[0], p[5]), p[5]));
}

TEST_F(Queries, PrevIToWithValenceIsXItself) {
  for (V x : vv::each(p[5])) EXPECT_EQ(vv::prev_to(x, p[5], 4), x);
}

TEST_F(Queries, PrevIToWithValencePlusOneIsPrevTo) {
  for (V x : vv::each(p[5])) EXPECT_EQ(vv::prev_to(x, p[5], 5), vv::prev_to(x, p[5]));
  EXPECT_EQ(vv::prev_to(p[0], p[5], 5).label(), 4u);
}

TEST_F(Queries, PrevIToNullWhenNotANeighbour) {
  EXPECT_FALSE(vv::prev_to(p[2], p[0], 2));
  EXPECT_FALSE(vv::prev_to(V(), p[0], 2));
}

// --------------------------------------------------------------- flagged in

TEST_F(Queries, FlaggedInNullWhenUnset) {
  for (const V& v : p) EXPECT_FALSE(vv::flagged_in(v)) << v;
  V empty = ctx.new_vertex();
  EXPECT_FALSE(vv::flagged_in(empty));
}

TEST_F(Queries, FlaggedInGivesTheFlaggedNeighbour) {
  vv::flag_in(p[3], p[0]);
  EXPECT_EQ(vv::flagged_in(p[0]), p[3]);
  EXPECT_EQ(vv::flagged_in(p[0]).label(), 4u);
  vv::flag_in(p[1], p[0]);  // flag moves
  EXPECT_EQ(vv::flagged_in(p[0]).label(), 2u);
  EXPECT_FALSE(vv::flagged_in(p[1]));  // flags are per neighbourhood
}

TEST_F(Queries, NextToFlag) {
  vv::flag_in(p[5], p[0]);
  EXPECT_EQ(vv::next_to_flag(p[0]).label(), 4u);
  vv::flag_in(p[4], p[0]);  // last entry: wraps
  EXPECT_EQ(vv::next_to_flag(p[0]).label(), 2u);
  EXPECT_EQ(vv::next_to_flag(p[0]), vv::next_to(vv::flagged_in(p[0]), p[0]));
}

TEST_F(Queries, PrevToFlag) {
  vv::flag_in(p[5], p[0]);
  EXPECT_EQ(vv::prev_to_flag(p[0]).label(), 2u);
  vv::flag_in(p[1], p[0]);  // first entry: wraps
  EXPECT_EQ(vv::prev_to_flag(p[0]).label(), 5u);
  EXPECT_EQ(vv::prev_to_flag(p[0]), vv::prev_to(vv::flagged_in(p[0]), p[0]));
}

TEST_F(Queries, NextToFlagErrorWhenUnset) {
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::next_to_flag(p[0]); },
                              {"nextto flag", "flag", "queries_test.cpp"}));
  V empty = ctx.new_vertex();
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::next_to_flag(empty); }, {"nextto flag"}));
}

TEST_F(Queries, PrevToFlagErrorWhenUnset) {
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::prev_to_flag(p[0]); },
                              {"prevto flag", "queries_test.cpp"}));
  vv::flag_in(p[1], p[0]);
  vv::flag_in(V(), p[0]);  // unset again
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::prev_to_flag(p[0]); }, {"prevto flag"}));
}

// -------------------------------------------------------------- old states

class OldQueries : public Queries {
 protected:
  // Synchronise the pyramid, then change the current state everywhere the
  // tests look, so a query that read the current state would be caught.
  OldQueries() {
    vv::flag_in(p[3], p[0]);
    vv::synchronise(M);
    extra = ctx.new_vertex();
    vv::make_nb(p[0], {p[2], extra});          // current 1: 3 7
    vv::erase_from(p[0], p[5]);                // current 6: 2 3 4
    vv::splice_before(extra, p[3], p[4]);      // current 5: 7 4 3 2 1
    vv::flag_in(p[1], p[4]);
  }
  V extra;
};

TEST_F(OldQueries, CurrentStateReallyChanged) {
  EXPECT_EQ(nb_labels(p[0]), (std::vector<unsigned>{3, 7}));
  EXPECT_EQ(cycle(p[5]), (std::vector<unsigned>{2, 3, 4}));
  EXPECT_EQ(cycle(p[4]), canon({7, 4, 3, 2, 1}));
}

TEST_F(OldQueries, Valence) {
  EXPECT_EQ(vv::valence(vv::old(p[0])), 4u);
  EXPECT_EQ(vv::valence(vv::old(p[5])), 4u);
  EXPECT_EQ(vv::valence(vv::old(p[4])), 4u);
  EXPECT_EQ(vv::valence(vv::old(extra)), 0u);  // never synchronised
}

TEST_F(OldQueries, IsIn) {
  EXPECT_TRUE(vv::is_in(p[1], vv::old(p[0])));
  EXPECT_FALSE(vv::is_in(p[2], vv::old(p[0])));
  EXPECT_FALSE(vv::is_in(extra, vv::old(p[0])));
  EXPECT_TRUE(vv::is_in(p[0], vv::old(p[5])));
  EXPECT_FALSE(vv::is_in(extra, vv::old(p[4])));
}

TEST_F(OldQueries, AnyIn) {
  EXPECT_EQ(vv::any_in(vv::old(p[0])).label(), 2u);
  EXPECT_EQ(vv::any_in(vv::old(p[5])).label(), 1u);
  EXPECT_FALSE(vv::any_in(vv::old(extra)));
}

TEST_F(OldQueries, NextToAndPrevTo) {
  EXPECT_EQ(vv::next_to(p[1], vv::old(p[0])).label(), 6u);
  EXPECT_EQ(vv::prev_to(p[1], vv::old(p[0])).label(), 5u);
  EXPECT_EQ(vv::next_to(p[3], vv::old(p[4])).label(), 3u);
  EXPECT_EQ(vv::prev_to(p[2], vv::old(p[4])).label(), 4u);
  EXPECT_FALSE(vv::next_to(p[2], vv::old(p[0])));
  EXPECT_FALSE(vv::prev_to(extra, vv::old(p[4])));
  EXPECT_EQ(vv::next_to(p[2], vv::old(p[5])).label(), 4u);
}

TEST_F(OldQueries, NextIToAndPrevITo) {
  EXPECT_EQ(vv::next_to(p[1], vv::old(p[0]), 2).label(), 4u);
  EXPECT_EQ(vv::prev_to(p[1], vv::old(p[0]), 2).label(), 4u);
  EXPECT_EQ(vv::next_to(p[1], vv::old(p[0]), 4), p[1]);
  EXPECT_EQ(vv::next_to(p[1], vv::old(p[0]), 5).label(), 6u);
  EXPECT_EQ(vv::prev_to(p[1], vv::old(p[0]), 5).label(), 5u);
  EXPECT_FALSE(vv::next_to(extra, vv::old(p[4]), 2));
}

TEST_F(OldQueries, FlaggedIn) {
  EXPECT_EQ(vv::flagged_in(vv::old(p[0])).label(), 4u);
  EXPECT_FALSE(vv::flagged_in(p[0]));         // make unset the current flag
  EXPECT_FALSE(vv::flagged_in(vv::old(p[4])));  // flagged only after synchronise
  EXPECT_EQ(vv::flagged_in(p[4]).label(), 2u);
}

TEST_F(OldQueries, NextToFlagAndPrevToFlag) {
  EXPECT_EQ(vv::next_to_flag(vv::old(p[0])).label(), 5u);
  EXPECT_EQ(vv::prev_to_flag(vv::old(p[0])).label(), 6u);
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::next_to_flag(vv::old(p[4])); }, {"nextto flag"}));
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::prev_to_flag(vv::old(p[4])); }, {"prevto flag"}));
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::next_to_flag(p[0]); }, {"nextto flag"}));
}

TEST_F(OldQueries, ForallOnOldState) {
  EXPECT_EQ(nb_labels(vv::old(p[0])), (std::vector<unsigned>{2, 6, 4, 5}));
  EXPECT_EQ(nb_labels(vv::old(p[4])), (std::vector<unsigned>{4, 3, 2, 1}));
  EXPECT_EQ(nb_labels(vv::old(p[5])), (std::vector<unsigned>{1, 2, 3, 4}));
}

// --------------------------------------------------------- null target: error

TEST_F(Queries, ValenceOfNullIsAnError) {
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::valence(V()); },
                              {"valence", "null", "queries_test.cpp"}));
}

TEST_F(Queries, IsInNullIsAnError) {
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::is_in(p[0], V()); },
                              {"is", "null", "queries_test.cpp"}));
}

TEST_F(Queries, AnyInNullIsAnError) {
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::any_in(V()); },
                              {"any in", "null", "queries_test.cpp"}));
}

TEST_F(Queries, NextToInNullIsAnError) {
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::next_to(p[0], V()); },
                              {"nextto", "null", "queries_test.cpp"}));
}

TEST_F(Queries, PrevToInNullIsAnError) {
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::prev_to(p[0], V()); },
                              {"prevto", "null", "queries_test.cpp"}));
}

TEST_F(Queries, NextIToInNullIsAnError) {
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::next_to(p[0], V(), 2); },
                              {"next", "null", "queries_test.cpp"}));
}

TEST_F(Queries, PrevIToInNullIsAnError) {
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::prev_to(p[0], V(), 2); },
                              {"prev", "null", "queries_test.cpp"}));
}

TEST_F(Queries, FlaggedInNullIsAnError) {
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::flagged_in(V()); },
                              {"flagged in", "null", "queries_test.cpp"}));
}

TEST_F(Queries, NextToFlagInNullIsAnError) {
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::next_to_flag(V()); },
                              {"nextto flag", "null", "queries_test.cpp"}));
}

TEST_F(Queries, PrevToFlagInNullIsAnError) {
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::prev_to_flag(V()); },
                              {"prevto flag", "null", "queries_test.cpp"}));
}

TEST_F(Queries, ForallInNullIsAnError) {
  EXPECT_TRUE(throws_vv_error([&] { (void)nb_labels(V()); }, {"forall", "null"}));
}

TEST_F(Queries, OldStateOfNullTargetIsAnError) {
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::valence(vv::old(V())); }, {"`", "null"}));
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::next_to(p[0], vv::old(V())); }, {"`", "null"}));
}

TEST_F(Queries, ErrorNamesTheLineOfTheQuery) {
  int line = __LINE__ + 2;
  try {
    (void)vv::valence(V());
    FAIL() << "no error";
  } catch (const vv::error& e) {
    EXPECT_EQ(e.line(), line);
    EXPECT_NE(e.file().find("queries_test.cpp"), std::string::npos) << e.file();
  }
}

}  // namespace
