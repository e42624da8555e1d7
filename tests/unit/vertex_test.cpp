// Vertices (LANGUAGE.md sections 1, 3 and 3.1): creation, references,
// labels, comparisons, properties, the old (synchronised) state and lifetime.
#include "test_meshes.hpp"

#include <gtest/gtest.h>

#include <string>
#include <type_traits>
#include <unordered_set>
#include <utility>
#include <vector>

namespace {

using namespace vvtest;

// ---------------------------------------------------------------- creation

TEST(VertexCreate, DefaultPropertiesAreValueInitialised) {
  G::context ctx;
  V v = ctx.new_vertex();
  ASSERT_TRUE(v);
  EXPECT_EQ(v->x, 0.0);
  EXPECT_EQ(v->n, 0);
  EXPECT_EQ(v->pos.x(), 0.0);
  EXPECT_EQ(v->pos.y(), 0.0);
  EXPECT_EQ(v->pos.z(), 0.0);
  EXPECT_EQ(vv::valence(v), 0u);
  EXPECT_FALSE(vv::any_in(v));
  EXPECT_FALSE(vv::flagged_in(v));
  EXPECT_EQ(ctx.live_vertices(), 1u);
}

// Property types without default member initialisers are zeroed too.
struct RawProps {
  double d;
  int i;
  bool b;
};
using RawG = vv::graph<RawProps>;

TEST(VertexCreate, PropertiesWithoutInitialisersAreZeroed) {
  RawG::context ctx;
  std::vector<RawG::vertex> vs;
  for (int k = 0; k < 5; ++k) {
    vs.push_back(ctx.new_vertex());
    EXPECT_EQ(vs.back()->d, 0.0);
    EXPECT_EQ(vs.back()->i, 0);
    EXPECT_FALSE(vs.back()->b);
    vs.back()->d = 9.5;
    vs.back()->i = -3;
    vs.back()->b = true;
  }
  // A slot freed and reused starts value-initialised again.
  vs.clear();
  EXPECT_EQ(ctx.collect_garbage(), 5u);
  RawG::vertex w = ctx.new_vertex();
  EXPECT_EQ(w->d, 0.0);
  EXPECT_EQ(w->i, 0);
  EXPECT_FALSE(w->b);
}

TEST(VertexCreate, WithPropertiesInDeclarationOrder) {
  G::context ctx;
  V v = ctx.new_vertex(VP{1.5, 2, Pt(1, 2, 3)});
  EXPECT_EQ(v->x, 1.5);
  EXPECT_EQ(v->n, 2);
  EXPECT_EQ(v->pos.x(), 1.0);
  EXPECT_EQ(v->pos.y(), 2.0);
  EXPECT_EQ(v->pos.z(), 3.0);
  EXPECT_EQ(vv::valence(v), 0u);
  EXPECT_EQ(v.label(), 1u);
}

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
TEST(VertexCreate, WithPropertiesMissingTrailingOnesAreDefault) {
  G::context ctx;
  V v = ctx.new_vertex(VP{1.5, 2});
  EXPECT_EQ(v->x, 1.5);
  EXPECT_EQ(v->n, 2);
  EXPECT_EQ(v->pos.x(), 0.0);
  EXPECT_EQ(v->pos.y(), 0.0);
  EXPECT_EQ(v->pos.z(), 0.0);
  V w = ctx.new_vertex(VP{-4.25});
  EXPECT_EQ(w->x, -4.25);
  EXPECT_EQ(w->n, 0);
  EXPECT_EQ(w->pos.length(), 0.0);
}
#pragma GCC diagnostic pop

TEST(VertexCreate, EachCreationIsANewVertex) {
  G::context ctx;
  V a = ctx.new_vertex();
  V b = ctx.new_vertex();
  EXPECT_NE(a, b);
  a->x = 1;
  EXPECT_EQ(b->x, 0.0);
  EXPECT_EQ(ctx.live_vertices(), 2u);
}

// --------------------------------------------------------------- references

TEST(VertexReference, CopySharesTheVertex) {
  G::context ctx;
  V v = ctx.new_vertex();
  V r = v;  // vertex r = v;
  EXPECT_EQ(ctx.live_vertices(), 1u);  // no creation
  EXPECT_EQ(r, v);
  EXPECT_EQ(r.label(), v.label());
  r->x = 2.5;
  EXPECT_EQ(v->x, 2.5);
  v->n = 7;
  EXPECT_EQ(r->n, 7);
  V other = ctx.new_vertex();
  vv::make_nb(r, {other});
  EXPECT_EQ(nb_labels(v), labels({other}));
}

TEST(VertexReference, AssignmentRebindsNotCopies) {
  G::context ctx;
  V a = ctx.new_vertex(VP{1, 1, Pt()});
  V b = ctx.new_vertex(VP{2, 2, Pt()});
  V r = a;
  r = b;
  EXPECT_EQ(r, b);
  EXPECT_EQ(a->x, 1.0);  // a untouched
  r->x = 5;
  EXPECT_EQ(b->x, 5.0);
  EXPECT_EQ(a->x, 1.0);
  EXPECT_EQ(ctx.live_vertices(), 2u);
}

TEST(VertexReference, NullReference) {
  G::context ctx;
  V n = 0;  // vertex n = 0;
  EXPECT_FALSE(n);
  EXPECT_TRUE(!n);
  EXPECT_EQ(n.label(), 0u);
  EXPECT_EQ(vv::label_of(n), 0u);
  V d;  // default-constructed: also null
  EXPECT_FALSE(d);
  EXPECT_EQ(n, d);
  EXPECT_EQ(ctx.live_vertices(), 0u);
  V v = ctx.new_vertex();
  v = 0;  // assigning null drops the reference
  EXPECT_FALSE(v);
  EXPECT_EQ(v.label(), 0u);
}

TEST(VertexReference, PropertyAccessOnNullIsAnError) {
  V n = 0;
  EXPECT_TRUE(throws_vv_error([&] { (void)n.props(); }, {"null", "vertex_test.cpp"}));
}

struct Holder {
  V member;  // `vertex x;` inside a struct body: null until assigned
  std::vector<V> list;
};

V make_child(G::context& ctx, V parent) {  // vertex as parameter and return type
  V c = ctx.new_vertex(VP{parent->x + 1, parent->n, Pt()});
  vv::make_nb(c, {parent});
  return c;
}

TEST(VertexReference, MemberIsNullUntilAssigned) {
  G::context ctx;
  Holder h;
  EXPECT_FALSE(h.member);
  EXPECT_EQ(h.member.label(), 0u);
  EXPECT_EQ(ctx.live_vertices(), 0u);  // no allocation for a member
  V v = ctx.new_vertex();
  h.member = v;
  EXPECT_EQ(h.member, v);
  EXPECT_EQ(h.member.label(), 1u);
}

TEST(VertexReference, AsContainerElementParameterAndReturnType) {
  G::context ctx;
  V root = ctx.new_vertex(VP{10, 3, Pt()});
  std::vector<V> chain{root};
  for (int i = 0; i < 3; ++i) chain.push_back(make_child(ctx, chain.back()));
  ASSERT_EQ(chain.size(), 4u);
  std::vector<unsigned> labs;
  std::vector<double> xs;
  for (const V& v : chain) labs.push_back(v.label()), xs.push_back(v->x);
  EXPECT_EQ(labs, (std::vector<unsigned>{1, 2, 3, 4}));
  EXPECT_EQ(xs, (std::vector<double>{10, 11, 12, 13}));
  EXPECT_EQ(nb_labels(chain[3]), (std::vector<unsigned>{3}));
  EXPECT_EQ(nb_labels(chain[1]), (std::vector<unsigned>{1}));
  // Elements of a container are references: writing through them is shared.
  Holder h;
  h.list = chain;
  h.list[2]->n = 99;
  EXPECT_EQ(chain[2]->n, 99);
  // Vertices hash by label for unordered containers.
  std::unordered_set<V> set(chain.begin(), chain.end());
  EXPECT_EQ(set.size(), 4u);
  EXPECT_EQ(set.count(root), 1u);
}

// ------------------------------------------------------------------- labels

TEST(VertexLabel, PositiveAndInCreationOrder) {
  G::context ctx;
  std::vector<V> vs;
  for (int i = 0; i < 10; ++i) vs.push_back(ctx.new_vertex());
  for (int i = 0; i < 10; ++i) {
    EXPECT_EQ(vs[i].label(), static_cast<unsigned>(i + 1));
    EXPECT_EQ(vv::label_of(vs[i]), static_cast<unsigned>(i + 1));
  }
  static_assert(std::is_same_v<decltype(vv::label_of(vs[0])), unsigned>, "labelof is unsigned");
}

TEST(VertexLabel, StaysInCreationOrderAfterFreedSlotsAreReused) {
  G::context ctx;
  V keep = ctx.new_vertex();
  { V gone1 = ctx.new_vertex(); V gone2 = ctx.new_vertex(); }
  EXPECT_EQ(ctx.collect_garbage(), 2u);
  V later = ctx.new_vertex();
  V latest = ctx.new_vertex();
  EXPECT_EQ(keep.label(), 1u);
  EXPECT_EQ(later.label(), 4u);  // labels 2 and 3 are not handed out again
  EXPECT_EQ(latest.label(), 5u);
  EXPECT_LT(keep, later);
  EXPECT_LT(later, latest);
}

TEST(VertexLabel, DeterministicBetweenContexts) {
  G::context c1, c2;
  G::mesh M1(c1), M2(c2);
  auto p1 = build_double_pyramid(c1, M1);
  auto p2 = build_double_pyramid(c2, M2);
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(p1[i].label(), static_cast<unsigned>(i + 1));
    EXPECT_EQ(p1[i].label(), p2[i].label());
    EXPECT_EQ(nb_labels(p1[i]), nb_labels(p2[i]));
  }
}

TEST(VertexLabel, NullIsZero) {
  V n = 0;
  EXPECT_EQ(vv::label_of(n), 0u);
  EXPECT_EQ(V().label(), 0u);
}

// --------------------------------------------------------- bool conversion

TEST(VertexBool, NonNullIsTrue) {
  G::context ctx;
  V v = ctx.new_vertex();
  V n = 0;
  EXPECT_TRUE(static_cast<bool>(v));
  EXPECT_FALSE(!v);
  EXPECT_FALSE(static_cast<bool>(n));
  EXPECT_TRUE(!n);
  int taken = 0;
  if (v) taken += 1;
  if (n) taken += 10;
  if (!n) taken += 100;
  EXPECT_EQ(taken, 101);
  // A query that finds nothing gives a null vertex, false in a condition.
  EXPECT_TRUE(!vv::any_in(v));
}

// -------------------------------------------------------------- comparisons

TEST(VertexCompare, AllSixCompareLabels) {
  G::context ctx;
  V a = ctx.new_vertex();  // label 1
  V b = ctx.new_vertex();  // label 2
  V a2 = a;
  EXPECT_TRUE(a == a2);
  EXPECT_FALSE(a == b);
  EXPECT_TRUE(a != b);
  EXPECT_FALSE(a != a2);
  EXPECT_TRUE(a < b);
  EXPECT_FALSE(b < a);
  EXPECT_FALSE(a < a2);
  EXPECT_TRUE(b > a);
  EXPECT_FALSE(a > b);
  EXPECT_FALSE(a > a2);
  EXPECT_TRUE(a <= b);
  EXPECT_TRUE(a <= a2);
  EXPECT_FALSE(b <= a);
  EXPECT_TRUE(b >= a);
  EXPECT_TRUE(a >= a2);
  EXPECT_FALSE(a >= b);
}

TEST(VertexCompare, NullComparesAsLabelZero) {
  G::context ctx;
  V v = ctx.new_vertex();
  V n = 0;
  V m;
  EXPECT_TRUE(n == m);
  EXPECT_FALSE(n != m);
  EXPECT_FALSE(n == v);
  EXPECT_TRUE(n != v);
  EXPECT_TRUE(n < v);
  EXPECT_FALSE(v < n);
  EXPECT_TRUE(v > n);
  EXPECT_FALSE(n > v);
  EXPECT_TRUE(n <= v);
  EXPECT_TRUE(n <= m);
  EXPECT_FALSE(v <= n);
  EXPECT_TRUE(v >= n);
  EXPECT_TRUE(n >= m);
  EXPECT_FALSE(n >= v);
  EXPECT_FALSE(n < m);
  EXPECT_FALSE(n > m);
}

TEST(VertexCompare, SortingFollowsCreationOrder) {
  G::context ctx;
  std::vector<V> created;
  for (int i = 0; i < 6; ++i) created.push_back(ctx.new_vertex());
  std::vector<V> shuffled{created[4], created[1], V(), created[5], created[0], created[3],
                          created[2]};
  std::sort(shuffled.begin(), shuffled.end());
  std::vector<unsigned> labs;
  for (const V& v : shuffled) labs.push_back(v.label());
  EXPECT_EQ(labs, (std::vector<unsigned>{0, 1, 2, 3, 4, 5, 6}));
}

// --------------------------------------------------------------- properties

TEST(VertexProps, ReadWriteThroughBothForms) {
  G::context ctx;
  V v = ctx.new_vertex();
  v.props().x = 3.25;
  EXPECT_EQ(v->x, 3.25);
  v->n = 4;
  EXPECT_EQ(v.props().n, 4);
  v->pos = Pt(1, -2, 3);
  EXPECT_EQ(v.props().pos.y(), -2.0);
  v.props().pos.z(7);
  EXPECT_EQ(v->pos.z(), 7.0);
  v->x += 1;
  v.props().x *= 2;
  EXPECT_EQ(v->x, 8.5);
  // Properties belong to the vertex: another vertex is unaffected.
  V w = ctx.new_vertex();
  EXPECT_EQ(w->x, 0.0);
  EXPECT_EQ(w.props().n, 0);
}

TEST(VertexProps, ReferenceStaysValidWhileOtherVerticesAreCreated) {
  G::context ctx;
  V v = ctx.new_vertex();
  double& x = v->x;
  std::vector<V> many;
  for (int i = 0; i < 3000; ++i) many.push_back(ctx.new_vertex(VP{double(i), i, Pt()}));
  x = 42;
  EXPECT_EQ(v->x, 42.0);
  EXPECT_EQ(many[2999]->n, 2999);
  EXPECT_EQ(many[2999].label(), 3001u);
}

// ---------------------------------------------------------------- old state

TEST(VertexOld, ReadsSynchronisedPropertiesAfterCurrentChange) {
  G::context ctx;
  G::mesh M(ctx);
  V v = ctx.new_vertex(VP{1.5, 2, Pt(1, 1, 1)});
  M.add(v);
  vv::synchronise(M);
  v->x = 9;
  v->n = -1;
  v->pos = Pt(5, 6, 7);
  EXPECT_EQ(vv::old(v).props().x, 1.5);
  EXPECT_EQ(vv::old(v)->n, 2);
  EXPECT_EQ(vv::old(v)->pos.z(), 1.0);
  EXPECT_EQ(v->x, 9.0);
  EXPECT_EQ(v->n, -1);
  // Synchronising again takes the new values (the American spelling too).
  vv::synchronize(M);
  EXPECT_EQ(vv::old(v)->x, 9.0);
  EXPECT_EQ(vv::old(v)->n, -1);
  EXPECT_EQ(vv::old(v)->pos.x(), 5.0);
}

TEST(VertexOld, IsReadOnly) {
  G::context ctx;
  V v = ctx.new_vertex();
  V w = ctx.new_vertex();
  static_assert(std::is_const_v<std::remove_reference_t<decltype(vv::old(v).props())>>,
                "old properties are read-only");
  static_assert(std::is_const_v<std::remove_pointer_t<decltype(vv::old(v).operator->())>>,
                "old properties are read-only");
  static_assert(std::is_const_v<std::remove_reference_t<decltype(vv::edge(vv::old(v), w))>>,
                "old half-edge records are read-only");
  EXPECT_EQ(vv::old(v)->x, 0.0);
}

TEST(VertexOld, NeighbourhoodUnaffectedByLaterEdits) {
  G::context ctx;
  G::mesh M(ctx);
  auto p = build_double_pyramid(ctx, M);
  vv::flag_in(p[5], p[0]);
  vv::edge(p[0], p[3]).mark = 4;
  vv::synchronise(M);
  V extra = ctx.new_vertex();
  vv::make_nb(p[0], {p[1], extra});
  vv::splice_after(p[3], p[4], p[1]);
  vv::erase_from(p[0], p[4]);
  EXPECT_EQ(nb_labels(p[0]), (std::vector<unsigned>{2, 7}));
  EXPECT_EQ(nb_labels(vv::old(p[0])), (std::vector<unsigned>{2, 6, 4, 5}));
  EXPECT_EQ(flag_label(vv::old(p[0])), 6u);
  EXPECT_EQ(flag_label(p[0]), 0u);  // make unset the current flag
  EXPECT_EQ(vv::edge(vv::old(p[0]), p[3]).mark, 4);
  EXPECT_EQ(nb_labels(vv::old(p[1])), (std::vector<unsigned>{3, 6, 1, 5}));
  EXPECT_EQ(nb_labels(vv::old(p[4])), (std::vector<unsigned>{4, 3, 2, 1}));
  EXPECT_EQ(nb_labels(p[4]), (std::vector<unsigned>{4, 3, 2}));
}

TEST(VertexOld, NeverSynchronisedIsEmpty) {
  G::context ctx;
  V v = ctx.new_vertex(VP{5, 6, Pt(1, 2, 3)});
  V a = ctx.new_vertex();
  V b = ctx.new_vertex();
  vv::make_nb(v, {a, b});
  vv::flag_in(b, v);
  EXPECT_EQ(vv::old(v)->x, 0.0);
  EXPECT_EQ(vv::old(v)->n, 0);
  EXPECT_EQ(vv::old(v)->pos.length(), 0.0);
  EXPECT_EQ(vv::valence(vv::old(v)), 0u);
  EXPECT_TRUE(nb_labels(vv::old(v)).empty());
  EXPECT_FALSE(vv::any_in(vv::old(v)));
  EXPECT_FALSE(vv::flagged_in(vv::old(v)));
  EXPECT_FALSE(vv::is_in(a, vv::old(v)));
  // A mesh synchronised without v does not give v an old state either.
  G::mesh other(ctx);
  other.add(a);
  vv::synchronise(other);
  EXPECT_EQ(vv::valence(vv::old(v)), 0u);
  EXPECT_EQ(vv::old(v)->x, 0.0);
}

TEST(VertexOld, StrictModeMakesNeverSynchronisedAnError) {
  G::context ctx;
  ctx.strict_old_state = true;
  V v = ctx.new_vertex();
  V u = ctx.new_vertex();
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::old(v); }, {"vertex 1", "vertex_test.cpp"}));
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::valence(vv::old(u)); }, {"vertex 2"}));
  G::mesh M(ctx);
  M.add(v);
  vv::synchronise(M);
  v->x = 1;
  EXPECT_NO_THROW((void)vv::old(v));
  EXPECT_EQ(vv::old(v)->x, 0.0);
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::old(u); }, {"vertex 2"}));
}

TEST(VertexOld, NonStrictModeByDefault) {
  G::context ctx;
  EXPECT_FALSE(ctx.strict_old_state);
  V v = ctx.new_vertex();
  EXPECT_NO_THROW((void)vv::old(v));
}

TEST(VertexOld, OfNullIsAnError) {
  G::context ctx;
  V n = 0;
  EXPECT_TRUE(throws_vv_error([&] { (void)vv::old(n); }, {"`", "null", "vertex_test.cpp"}));
  // Naming the line of the use.
  int line = __LINE__ + 1;
  try { (void)vv::old(n); FAIL() << "no error"; } catch (const vv::error& e) {
    EXPECT_EQ(e.line(), line);
    EXPECT_NE(std::string(e.what()).find(":" + std::to_string(line) + ":"), std::string::npos)
        << e.what();
  }
}

TEST(VertexOld, EditWithOldTargetEditsCurrentState) {
  G::context ctx;
  G::mesh M(ctx);
  V v = ctx.new_vertex();
  V a = ctx.new_vertex();
  V b = ctx.new_vertex();
  V c = ctx.new_vertex();
  M.add(v);
  vv::make_nb(v, {a});
  vv::synchronise(M);
  vv::make_nb(vv::old(v), {a, b});
  EXPECT_EQ(nb_labels(v), labels({a, b}));
  vv::splice_after(c, b, vv::old(v));
  EXPECT_EQ(nb_labels(v), labels({a, b, c}));
  vv::erase_from(a, vv::old(v));
  EXPECT_EQ(nb_labels(v), labels({b, c}));
  vv::flag_in(c, vv::old(v));
  EXPECT_EQ(flag_label(v), c.label());
  vv::replace_in(b, a, vv::old(v));
  EXPECT_EQ(nb_labels(v), labels({a, c}));
  // The old state itself is untouched.
  EXPECT_EQ(nb_labels(vv::old(v)), labels({a}));
  EXPECT_FALSE(vv::flagged_in(vv::old(v)));
  EXPECT_TRUE(invariants_hold({v, a, b, c}));
}

TEST(VertexOld, OldOfOldIsOld) {
  G::context ctx;
  G::mesh M(ctx);
  V v = ctx.new_vertex(VP{2, 0, Pt()});
  M.add(v);
  vv::synchronise(M);
  v->x = 3;
  EXPECT_EQ(vv::old(vv::old(v))->x, 2.0);
}

// ----------------------------------------------------------------- lifetime

TEST(VertexLifetime, KeptAliveByANeighbourhoodEntry) {
  G::context ctx;
  V a = ctx.new_vertex();
  {
    V b = ctx.new_vertex(VP{7.5, 8, Pt(1, 2, 3)});
    vv::make_nb(a, {b});
  }  // the only handle to b is gone
  EXPECT_EQ(ctx.collect_garbage(), 0u);
  EXPECT_EQ(ctx.live_vertices(), 2u);
  V b = vv::any_in(a);
  ASSERT_TRUE(b);
  EXPECT_EQ(b.label(), 2u);
  EXPECT_EQ(b->x, 7.5);
  EXPECT_EQ(b->n, 8);
  EXPECT_EQ(b->pos.z(), 3.0);
}

TEST(VertexLifetime, KeptAliveTransitivelyThroughNeighbourhoods) {
  G::context ctx;
  V a = ctx.new_vertex();
  {
    V b = ctx.new_vertex();
    V c = ctx.new_vertex(VP{3, 3, Pt()});
    vv::make_nb(a, {b});
    vv::make_nb(b, {c});
  }
  EXPECT_EQ(ctx.collect_garbage(), 0u);
  EXPECT_EQ(ctx.live_vertices(), 3u);
  V c = vv::any_in(vv::any_in(a));
  EXPECT_EQ(c.label(), 3u);
  EXPECT_EQ(c->x, 3.0);
}

TEST(VertexLifetime, KeptAliveByAMesh) {
  G::context ctx;
  G::mesh M(ctx);
  { M.add(ctx.new_vertex(VP{4, 0, Pt()})); }
  EXPECT_EQ(ctx.collect_garbage(), 0u);
  EXPECT_EQ(ctx.live_vertices(), 1u);
  std::vector<double> xs;
  for (V v : vv::each(M)) xs.push_back(v->x);
  EXPECT_EQ(xs, (std::vector<double>{4}));
}

TEST(VertexLifetime, UnreferencedVertexIsFreed) {
  G::context ctx;
  V keep = ctx.new_vertex();
  { V v = ctx.new_vertex(); }
  EXPECT_EQ(ctx.live_vertices(), 2u);  // not yet collected
  EXPECT_EQ(ctx.collect_garbage(), 1u);
  EXPECT_EQ(ctx.live_vertices(), 1u);
  EXPECT_EQ(keep.label(), 1u);
  // Removing a vertex from its only mesh frees it too.
  G::mesh M(ctx);
  { M.add(ctx.new_vertex()); }
  EXPECT_EQ(ctx.live_vertices(), 2u);
  for (V v : vv::each(M)) M.remove(v);
  EXPECT_EQ(ctx.collect_garbage(), 1u);
  EXPECT_EQ(ctx.live_vertices(), 1u);
}

TEST(VertexLifetime, UnreferencedCycleIsFreed) {
  G::context ctx;
  V keep = ctx.new_vertex();
  {
    V a = ctx.new_vertex();
    V b = ctx.new_vertex();
    vv::make_nb(a, {b});
    vv::make_nb(b, {a});
  }
  EXPECT_EQ(ctx.live_vertices(), 3u);
  EXPECT_EQ(ctx.collect_garbage(), 2u);
  EXPECT_EQ(ctx.live_vertices(), 1u);
  EXPECT_EQ(keep.label(), 1u);
}

TEST(VertexLifetime, UnreferencedPyramidIsFreed) {
  G::context ctx;
  {
    G::mesh M(ctx);
    build_double_pyramid(ctx, M);
    EXPECT_EQ(ctx.live_vertices(), 6u);
  }
  EXPECT_EQ(ctx.collect_garbage(), 6u);
  EXPECT_EQ(ctx.live_vertices(), 0u);
}

TEST(VertexLifetime, KeptAliveByAnOldNeighbourhoodUntilNextSynchronise) {
  G::context ctx;
  G::mesh M(ctx);
  V a = ctx.new_vertex();
  M.add(a);
  {
    V b = ctx.new_vertex(VP{6.5, 1, Pt()});
    vv::make_nb(a, {b});
    vv::synchronise(M);
    vv::erase_from(b, a);  // b is now only in a's old neighbourhood
  }
  EXPECT_EQ(vv::valence(a), 0u);
  EXPECT_EQ(ctx.collect_garbage(), 0u);
  EXPECT_EQ(ctx.live_vertices(), 2u);
  {
    V b = vv::any_in(vv::old(a));
    ASSERT_TRUE(b);
    EXPECT_EQ(b.label(), 2u);
    EXPECT_EQ(b->x, 6.5);
  }
  vv::synchronise(M);  // replaces a's old neighbourhood by the empty one
  EXPECT_EQ(vv::valence(vv::old(a)), 0u);
  EXPECT_EQ(ctx.collect_garbage(), 1u);
  EXPECT_EQ(ctx.live_vertices(), 1u);
}

// ------------------------------------------- a neighbourhood loop's variable
// `for (auto&& x : vv::each(v))` (how vvc writes forall) binds x to the
// loop's own handle, which does not count its vertex: reading neighbours
// costs no count changes. Every copy, move or return of it is counted.

// a with neighbours b and c, whose only references are a's neighbourhood.
struct fan {
  G::context ctx;
  V a, other;
  std::uint32_t b_slot = 0, c_slot = 0;
  fan() {
    a = ctx.new_vertex();
    other = ctx.new_vertex();
    V b = ctx.new_vertex(VP{2, 0, Pt()}), c = ctx.new_vertex(VP{3, 0, Pt()});
    vv::make_nb(a, {b, c});
    b_slot = b.slot();
    c_slot = c.slot();
  }
  //! Leaves b and c referenced by nothing a neighbourhood or mesh holds.
  void unlink() { vv::make_nb(a, {}); }
};

TEST(VertexNeighbourLoop, ReadsNeighboursWithoutCountingThem) {
  fan f;
  const std::uint32_t b_refs = f.ctx.refs(f.b_slot), c_refs = f.ctx.refs(f.c_slot);
  std::vector<double> xs;
  for (auto&& x : vv::each(f.a)) {
    EXPECT_EQ(f.ctx.refs(f.b_slot), b_refs);
    EXPECT_EQ(f.ctx.refs(f.c_slot), c_refs);
    xs.push_back(x->x);
  }
  EXPECT_EQ(xs, (std::vector<double>{2, 3}));
  EXPECT_EQ(f.ctx.refs(f.b_slot), b_refs);
  EXPECT_EQ(f.ctx.refs(f.c_slot), c_refs);
}

TEST(VertexNeighbourLoop, CopiesOfTheVariableKeepTheirVerticesAlive) {
  fan f;
  std::vector<V> kept;
  for (auto&& x : vv::each(f.a)) {
    V copy = x;
    kept.push_back(copy);
    kept.push_back(x);
  }
  EXPECT_EQ(f.ctx.refs(f.b_slot), 2u);
  f.unlink();
  EXPECT_EQ(f.ctx.collect_garbage(), 0u);
  EXPECT_EQ(kept[0]->x, 2.0);
  EXPECT_EQ(kept[3]->x, 3.0);
  kept.clear();
  EXPECT_EQ(f.ctx.collect_garbage(), 2u);
}

TEST(VertexNeighbourLoop, AMovedVariableStaysValidAndItsTargetIsCounted) {
  fan f;
  std::vector<V> moved;
  for (auto&& x : vv::each(f.a)) {
    moved.push_back(std::move(x));
    EXPECT_TRUE(x);
    EXPECT_EQ(x, moved.back());
    V assigned;
    assigned = std::move(x);
    EXPECT_EQ(assigned, x);
  }
  EXPECT_EQ(f.ctx.refs(f.b_slot), 1u);
  EXPECT_EQ(f.ctx.refs(f.c_slot), 1u);
  f.unlink();
  EXPECT_EQ(f.ctx.collect_garbage(), 0u);
  moved.clear();
  EXPECT_EQ(f.ctx.collect_garbage(), 2u);
}

// Every return of the loop variable: a compiler may construct it in the
// caller's object (clang does), which is why the variable is a reference
// to the loop's handle rather than a handle of its own.
V first_neighbour(const V& v) {
  for (auto&& x : vv::each(v)) return x;
  return V();
}

TEST(VertexNeighbourLoop, ReturnedFromAFunctionItIsCounted) {
  fan f;
  V first = first_neighbour(f.a);
  EXPECT_EQ(first.slot(), f.b_slot);
  EXPECT_EQ(f.ctx.refs(f.b_slot), 1u);
  f.unlink();
  EXPECT_EQ(f.ctx.collect_garbage(), 1u);  // c only
  EXPECT_EQ(first->x, 2.0);
}

TEST(VertexNeighbourLoop, AssigningToTheVariableChangesThatIterationOnly) {
  fan f;
  const std::uint32_t other_refs = f.ctx.refs(f.other.slot());
  std::vector<std::uint32_t> visited;
  for (auto&& x : vv::each(f.a)) {
    visited.push_back(x.slot());
    x = f.other;
    EXPECT_EQ(f.ctx.refs(f.other.slot()), other_refs + 1);
  }
  EXPECT_EQ(visited, (std::vector<std::uint32_t>{f.b_slot, f.c_slot}));
  EXPECT_EQ(f.ctx.refs(f.other.slot()), other_refs);
  EXPECT_EQ(vv::valence(f.a), 2u);
}

// A mesh loop's variable is counted: the body may take its vertex out of
// the mesh and drop every other reference.
TEST(VertexNeighbourLoop, AMeshLoopsVariableIsCounted) {
  G::context ctx;
  G::mesh M(ctx);
  { M.add(ctx.new_vertex(VP{5, 0, Pt()})); }
  for (auto&& v : vv::each(M)) {
    EXPECT_EQ(ctx.refs(v.slot()), 2u);  // the mesh and the variable
    M.remove(v);
    EXPECT_EQ(ctx.collect_garbage(), 0u);
    EXPECT_EQ(v->x, 5.0);
  }
  EXPECT_EQ(ctx.collect_garbage(), 1u);
}

}  // namespace
