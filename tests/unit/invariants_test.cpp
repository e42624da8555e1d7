// check_invariants finds each kind of broken structure. The algebra itself
// never builds these, so some are made by writing to the storage directly.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include <vv/io/from_faces.hpp>
#include <vv/vv.hpp>

namespace {

struct props {
  std::array<double, 3> pos{};
};
using graph = vv::graph<props>;
using vertex = graph::vertex;
using entry_traits = graph::context::entry_traits;

struct Invariants : ::testing::Test {
  graph::context ctx;
  graph::mesh S{ctx};
  std::vector<vertex> v;

  void SetUp() override {
    // The double pyramid, by file index.
    std::vector<std::vector<int>> nb = {{1, 5, 3, 4}, {2, 5, 0, 4}, {3, 5, 1, 4},
                                        {0, 5, 2, 4}, {3, 2, 1, 0}, {0, 1, 2, 3}};
    for (int i = 0; i < 6; ++i) v.push_back(ctx.new_vertex());
    for (int i = 0; i < 6; ++i) {
      std::vector<vertex> list;
      for (int j : nb[std::size_t(i)]) list.push_back(v[std::size_t(j)]);
      vv::make_nb_from(v[std::size_t(i)], list);
      S.add(v[std::size_t(i)]);
    }
  }
  std::string violations(vv::invariant_options opt = {}) {
    std::string all;
    for (const auto& p : vv::invariant_violations(S, opt)) all += p + "\n";
    return all;
  }
};

}  // namespace

TEST_F(Invariants, TheDoublePyramidHasNone) {
  EXPECT_EQ(violations({true, true}), "");
  EXPECT_NO_THROW(vv::check_invariants(S, {true, true}));
}

TEST_F(Invariants, AsymmetryIsReportedOnlyWhenAsked) {
  vv::erase_from(v[0], v[1]);
  EXPECT_EQ(violations(), "");
  EXPECT_NE(violations({true, false}).find("vertex 2 is a neighbour of vertex 1 but not the other way round"),
            std::string::npos)
      << violations({true, false});
}

TEST_F(Invariants, SelfNeighbourIsReported) {
  ctx.nb(v[2].slot()).insert(0, entry_traits::make(v[2].slot()));
  EXPECT_NE(violations().find("vertex 3 (current): is its own neighbour"), std::string::npos)
      << violations();
}

TEST_F(Invariants, DuplicateNeighbourIsReported) {
  ctx.nb(v[2].slot()).insert(0, entry_traits::make(v[3].slot()));
  EXPECT_NE(violations().find("vertex 3 (current): vertex 4 appears twice"), std::string::npos)
      << violations();
}

TEST_F(Invariants, FlagOutsideTheNeighbourhoodIsReported) {
  ctx.nb(v[0].slot()).set_flag(7);
  EXPECT_NE(violations().find("vertex 1 (current): flag 7 is outside the neighbourhood of 4"),
            std::string::npos)
      << violations();
}

TEST_F(Invariants, DeadNeighbourIsReported) {
  const std::uint32_t never_allocated = ctx.slot_count() + 5;
  ctx.nb(v[0].slot()).insert(0, entry_traits::make(never_allocated));
  EXPECT_NE(violations().find("vertex 1 (current): entry 0 is not a live vertex"), std::string::npos)
      << violations();
}

TEST_F(Invariants, OldStateIsCheckedToo) {
  vv::synchronise(S);
  ctx.writable_old_nb(v[1].slot()).insert(1, entry_traits::make(v[1].slot()));
  EXPECT_NE(violations().find("vertex 2 (old): is its own neighbour"), std::string::npos)
      << violations();
}

TEST_F(Invariants, NonManifoldOrbitIsReported) {
  // Two tetrahedra sharing one vertex: its rotation holds two fans, and the
  // orbits through it pass it twice.
  graph::mesh T(ctx);
  std::vector<std::array<double, 3>> p(7);
  vv::build_from_faces(T, p,
                       {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2},
                        {0, 5, 4}, {0, 4, 6}, {4, 5, 6}, {0, 6, 5}},
                       "two tetrahedra");
  auto problems = vv::invariant_violations(T, {true, true});
  ASSERT_FALSE(problems.empty());
  EXPECT_NE(problems[0].find("face orbit visits a vertex twice"), std::string::npos) << problems[0];
  EXPECT_TRUE(vv::invariant_violations(T, {true, false}).empty());
}

TEST_F(Invariants, CheckThrowsNamingTheCallerAndEveryProblem) {
  ctx.nb(v[0].slot()).set_flag(9);
  ctx.nb(v[1].slot()).set_flag(9);
  try {
    vv::check_invariants(S);
    FAIL() << "no error";
  } catch (const vv::error& e) {
    std::string what = e.what();
    EXPECT_NE(what.find("invariants_test.cpp:"), std::string::npos) << what;
    EXPECT_NE(what.find("vertex 1 (current): flag 9"), std::string::npos) << what;
    EXPECT_NE(what.find("vertex 2 (current): flag 9"), std::string::npos) << what;
  }
}
