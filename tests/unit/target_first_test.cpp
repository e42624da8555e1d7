// The vv 2.0 spellings of the C++ API (docs/library.md, "Operand order"):
// the target-first neighbourhood operations, vv::insert, face_vertices and
// context_of. Each is checked against hand-computed answers and against
// its old spelling: the same operation on a twin mesh (two contexts built
// alike, so labels match) must leave the same state and throw the same
// error text.
#include "test_meshes.hpp"

#include <algorithms/insert.hpp>

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

namespace {

using namespace vvtest;

// Two octahedra (labels 1..6 each), one edited with each spelling.
class TargetFirst : public ::testing::Test {
 protected:
  TargetFirst() : M_old(ctx_old), M_new(ctx_new) {
    o = build_double_pyramid(ctx_old, M_old);
    n = build_double_pyramid(ctx_new, M_new);
    for (std::size_t i = 0; i < 6; ++i) {
      vv::edge(o[i], vv::any_in(o[i])).mark = int(i) + 1;
      vv::edge(n[i], vv::any_in(n[i])).mark = int(i) + 1;
    }
    extra_old = ctx_old.new_vertex();
    extra_new = ctx_new.new_vertex();
  }
  // Every neighbourhood of the twins is the same: entries, flag, records.
  void expect_twins() {
    for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(state_of(o[i]), state_of(n[i])) << "vertex " << i + 1;
    EXPECT_EQ(state_of(extra_old), state_of(extra_new));
  }

  G::context ctx_old, ctx_new;
  G::mesh M_old, M_new;
  std::vector<V> o, n;
  V extra_old, extra_new;  // label 7 in both, no neighbours
};

// The what() of the vv::error f throws, or "" when it throws none.
std::string error_text(const std::function<void()>& f) {
  try {
    f();
  } catch (const vv::error& e) {
    return e.what();
  }
  return "";
}

const vv::where at{"model.vvp", 12};

TEST_F(TargetFirst, QueriesAgreeWithTheVvOrder) {
  vv::synchronise(M_old);
  for (std::size_t i = 0; i < 6; ++i)
    for (std::size_t j = 0; j < 6; ++j) {
      EXPECT_EQ(vv::has_nb(o[i], o[j]), vv::is_in(o[j], o[i]));
      EXPECT_EQ(vv::has_nb(vv::old(o[i]), o[j]), vv::is_in(o[j], vv::old(o[i])));
      EXPECT_EQ(vv::nb_after(o[i], o[j]), vv::next_to(o[j], o[i]));
      EXPECT_EQ(vv::nb_before(o[i], o[j]), vv::prev_to(o[j], o[i]));
      EXPECT_EQ(vv::nb_after(vv::old(o[i]), o[j]), vv::next_to(o[j], vv::old(o[i])));
      EXPECT_EQ(vv::nb_before(vv::old(o[i]), o[j]), vv::prev_to(o[j], vv::old(o[i])));
      for (long k = 1; k <= 9; ++k) {
        EXPECT_EQ(vv::nb_after(o[i], o[j], k), vv::next_to(o[j], o[i], k));
        EXPECT_EQ(vv::nb_before(o[i], o[j], k), vv::prev_to(o[j], o[i], k));
      }
    }
}

TEST_F(TargetFirst, QueriesGiveTheHandComputedNeighbours) {
  // The apex (label 5) has neighbourhood (4 3 2 1).
  EXPECT_EQ(vv::nb_after(o[4], o[3]).label(), 3u);
  EXPECT_EQ(vv::nb_before(o[4], o[3]).label(), 1u);  // cyclic: before the first is the last
  EXPECT_EQ(vv::nb_after(o[4], o[3], 2).label(), 2u);
  EXPECT_EQ(vv::nb_before(o[4], o[0], 5).label(), 2u);  // 5 places back = 1 place back, cyclic
  EXPECT_TRUE(vv::has_nb(o[4], o[0]));
  EXPECT_FALSE(vv::has_nb(o[4], o[5]));  // the other apex
  EXPECT_FALSE(vv::nb_after(o[4], o[5]));
}

TEST_F(TargetFirst, QueryErrorsAreTheSame) {
  EXPECT_EQ(error_text([&] { vv::nb_after(o[0], o[1], 0, at); }),
            error_text([&] { vv::next_to(o[1], o[0], 0, at); }));
  EXPECT_EQ(error_text([&] { vv::nb_before(o[0], o[1], -3, at); }),
            error_text([&] { vv::prev_to(o[1], o[0], -3, at); }));
  V null;
  std::string old_text = error_text([&] { vv::is_in(o[1], null, at); });
  EXPECT_NE(old_text, "");
  EXPECT_EQ(error_text([&] { vv::has_nb(null, o[1], at); }), old_text);
}

TEST_F(TargetFirst, EditsLeaveTheSameNeighbourhoods) {
  // Each step edits the old twin with the vv order, the new one target first.
  vv::replace_in(o[1], extra_old, o[4]);
  vv::replace_nb(n[4], n[1], extra_new);
  expect_twins();
  EXPECT_EQ(nb_labels(n[4]), (std::vector<unsigned>{4, 3, 7, 1}));  // by hand

  vv::erase_from(extra_old, o[4]);
  vv::erase_nb(n[4], extra_new);
  expect_twins();
  EXPECT_EQ(nb_labels(n[4]), (std::vector<unsigned>{4, 3, 1}));

  vv::splice_after(o[1], o[2], o[4]);
  vv::splice_nb_after(n[4], n[1], n[2]);
  expect_twins();
  EXPECT_EQ(nb_labels(n[4]), (std::vector<unsigned>{4, 3, 2, 1}));

  vv::splice_before(extra_old, o[3], o[4]);
  vv::splice_nb_before(n[4], extra_new, n[3]);
  expect_twins();
  EXPECT_EQ(nb_labels(n[4]), (std::vector<unsigned>{7, 4, 3, 2, 1}));

  vv::flag_in(o[2], o[4]);
  vv::flag_nb(n[4], n[2]);
  expect_twins();
  EXPECT_EQ(flag_label(n[4]), 3u);

  vv::replace_flag(o[5], o[4]);
  vv::replace_flagged_nb(n[4], n[5]);
  expect_twins();
  EXPECT_EQ(nb_labels(n[4]), (std::vector<unsigned>{7, 4, 6, 2, 1}));

  vv::erase_from(o[3], o[4]);
  vv::erase_nb(n[4], n[3]);
  vv::splice_after_flag(o[3], o[4]);
  vv::splice_nb_after_flag(n[4], n[3]);
  expect_twins();
  EXPECT_EQ(nb_labels(n[4]), (std::vector<unsigned>{7, 6, 4, 2, 1}));

  vv::erase_from(o[0], o[4]);
  vv::erase_nb(n[4], n[0]);
  vv::splice_before_flag(o[0], o[4]);
  vv::splice_nb_before_flag(n[4], n[0]);
  expect_twins();
  EXPECT_EQ(nb_labels(n[4]), (std::vector<unsigned>{7, 1, 6, 4, 2}));
  EXPECT_EQ(flag_label(n[4]), 6u);

  vv::flag_in(V(), o[4]);
  vv::flag_nb(n[4], V());
  expect_twins();
  EXPECT_EQ(flag_label(n[4]), 0u);
}

TEST_F(TargetFirst, EditErrorsAreTheSame) {
  // Inserting a vertex that is already a neighbour, and an unset flag.
  std::string old_text = error_text([&] { vv::splice_after(o[0], o[3], o[4], at); });
  EXPECT_NE(old_text, "");
  EXPECT_EQ(error_text([&] { vv::splice_nb_after(n[4], n[0], n[3], at); }), old_text);
  EXPECT_EQ(error_text([&] { vv::replace_nb(n[4], n[3], n[0], at); }),
            error_text([&] { vv::replace_in(o[3], o[0], o[4], at); }));
  EXPECT_EQ(error_text([&] { vv::splice_nb_before_flag(n[4], extra_new, at); }),
            error_text([&] { vv::splice_before_flag(extra_old, o[4], at); }));
  EXPECT_EQ(error_text([&] { vv::replace_flagged_nb(n[4], extra_new, at); }),
            error_text([&] { vv::replace_flag(extra_old, o[4], at); }));
  expect_twins();  // and nothing changed
}

TEST_F(TargetFirst, InsertIsTheFunctor) {
  algorithms::Insert<V> insert_functor;
  V x_old = insert_functor(o[0], o[1]);
  V x_new = vv::insert(n[0], n[1]);
  EXPECT_EQ(x_old.label(), 8u);
  EXPECT_EQ(x_new.label(), 8u);
  expect_twins();
  EXPECT_EQ(nb_labels(x_new), (std::vector<unsigned>{1, 2}));
  EXPECT_EQ(nb_labels(n[0]), (std::vector<unsigned>{8, 6, 4, 5}));  // 2 replaced by 8
  EXPECT_EQ(error_text([&] { vv::insert(n[4], n[5], at); }),
            error_text([&] { insert_functor(o[4], o[5], at); }));
  EXPECT_NE(error_text([&] { vv::insert(n[4], n[5], at); }), "");
}

TEST_F(TargetFirst, FaceVerticesAreTheFaceOrbits) {
  std::vector<std::vector<std::uint32_t>> by_position = vv::face_orbits(M_old);
  std::vector<std::vector<V>> by_vertex = vv::face_vertices(M_old);
  ASSERT_EQ(by_vertex.size(), 8u);  // the octahedron's triangles
  ASSERT_EQ(by_vertex.size(), by_position.size());
  for (std::size_t f = 0; f < by_vertex.size(); ++f) {
    ASSERT_EQ(by_vertex[f].size(), 3u);
    // Members were added in file order: position i is label i + 1.
    for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(by_vertex[f][k].label(), by_position[f][k] + 1);
  }
  // The first face starts at (1, 2) and goes on to (2, prevto 1 in 2) = (2, 6).
  EXPECT_EQ(labels({by_vertex[0][0], by_vertex[0][1], by_vertex[0][2]}),
            (std::vector<unsigned>{1, 2, 6}));
  EXPECT_TRUE(vv::face_vertices(M_old, 2).empty());  // every face is longer than 2
}

TEST_F(TargetFirst, ContextOfAMeshOrAVertex) {
  EXPECT_EQ(&vv::context_of(M_old), M_old.ctx());
  EXPECT_EQ(&vv::context_of(o[2]), &ctx_old);
  G::mesh N(vv::context_of(M_new));
  V made = vv::context_of(M_new).new_vertex();
  EXPECT_EQ(made.label(), 8u);
  N.add(made);
  EXPECT_EQ(N.ctx(), &ctx_new);
  G::mesh unset;
  EXPECT_TRUE(throws_vv_error([&] { vv::context_of(unset, at); }, {"model.vvp:12", "no context"}));
  EXPECT_TRUE(throws_vv_error([&] { vv::context_of(V(), at); }, {"model.vvp:12", "null vertex"}));
}

}  // namespace
