// Meshes (LANGUAGE.md section 5) and iteration (section 6): every row of the
// mesh table, lifetime and order of members, a large randomised mesh checked
// against a model, and `forall` over meshes and neighbourhoods whose bodies
// edit what is being iterated.
#include <vv/vv.hpp>

#include <util/point.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <list>
#include <random>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace {

using Pt = util::Point<double>;

struct VP {
  Pt pos;
  double c = 0;
  int tag = 0;
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos);
    f("c", c);
    f("tag", tag);
  }
};

struct EP {
  int mark = 0;
  template <class F>
  void vv_fields(F&& f) {
    f("mark", mark);
  }
  friend bool operator==(const EP& a, const EP& b) { return a.mark == b.mark; }
  friend bool operator!=(const EP& a, const EP& b) { return !(a == b); }
};

struct MP {
  int generation = 0;
  std::string name;
  template <class F>
  void vv_fields(F&& f) {
    f("generation", generation);
    f("name", name);
  }
};

using G = vv::graph<VP, EP, MP>;
using V = G::vertex;
using Mesh = G::mesh;
using Labels = std::vector<unsigned>;

// ---- helpers ----

V tagged(G::context& ctx, int tag) {
  V v = ctx.new_vertex();
  v->tag = tag;
  return v;
}

std::vector<V> make_vertices(G::context& ctx, int n, int first_tag = 1) {
  std::vector<V> out;
  for (int i = 0; i < n; ++i) out.push_back(tagged(ctx, first_tag + i));
  return out;
}

Labels labels_of(const Mesh& m) {
  Labels out;
  for (V v : vv::each(m)) out.push_back(v.label());
  return out;
}

Labels labels_of(const std::vector<V>& vs) {
  Labels out;
  for (const V& v : vs) out.push_back(v.label());
  return out;
}

std::vector<int> tags_of(const Mesh& m) {
  std::vector<int> out;
  for (V v : m) out.push_back(v->tag);
  return out;
}

Labels nb_labels(const V& v) {
  Labels out;
  for (V x : vv::each(v)) out.push_back(x.label());
  return out;
}

Labels old_nb_labels(const V& v) {
  Labels out;
  for (V x : vv::each(vv::old(v))) out.push_back(x.label());
  return out;
}

// ---- global mesh (section 5: a mesh may be a global object) ----

G::context global_ctx;
Mesh global_mesh(global_ctx);

// ---- a mesh as a member, a parameter and a return value ----

struct Tissue {
  Mesh cells;
  int divisions = 0;
  explicit Tissue(G::context& ctx) : cells(ctx) {}
};

void add_all(Mesh& target, const std::vector<V>& vs) {
  for (const V& v : vs) target.add(v);
  target.generation += 1;
}

Mesh make_mesh_of(G::context& ctx, const std::vector<V>& vs, int generation) {
  Mesh m(ctx);
  for (const V& v : vs) m.add(v);
  m.generation = generation;
  m.name = "made";
  return m;
}

// =====================================================================
// Section 5: declaring meshes
// =====================================================================

TEST(MeshDeclare, LocalMeshStartsEmptyWithDefaultProperties) {
  G::context ctx;
  Mesh M(ctx);
  V v = ctx.new_vertex();
  EXPECT_EQ(M.size(), 0u);
  EXPECT_EQ(M.vertexCount(), 0u);
  EXPECT_TRUE(M.empty());
  EXPECT_FALSE(M.contains(v));
  EXPECT_EQ(labels_of(M), Labels{});
  EXPECT_EQ(M.generation, 0);
  EXPECT_EQ(M.name, "");
}

TEST(MeshDeclare, MeshWithoutContextTakesItFromFirstVertex) {
  G::context ctx;
  Mesh M;
  EXPECT_EQ(M.ctx(), nullptr);
  V v = ctx.new_vertex();
  M.add(v);
  EXPECT_EQ(M.ctx(), &ctx);
  EXPECT_TRUE(M.contains(v));
  EXPECT_EQ(labels_of(M), Labels{v.label()});
}

TEST(MeshDeclare, GlobalMesh) {
  std::vector<V> vs = make_vertices(global_ctx, 3);
  global_mesh.add(vs[0]);
  global_mesh.add(vs[2]);
  global_mesh.generation = 11;
  EXPECT_EQ(global_mesh.size(), 2u);
  EXPECT_EQ(labels_of(global_mesh), (Labels{vs[0].label(), vs[2].label()}));
  EXPECT_FALSE(vv::is_in(vs[1], global_mesh));
  EXPECT_EQ(global_mesh.generation, 11);
  global_mesh.clear();
  global_mesh.generation = 0;
  EXPECT_EQ(global_mesh.size(), 0u);
}

TEST(MeshDeclare, MemberOfAStruct) {
  G::context ctx;
  Tissue t(ctx);
  std::vector<V> vs = make_vertices(ctx, 4);
  for (const V& v : vs) t.cells.add(v);
  t.cells.name = "cells";
  EXPECT_EQ(t.cells.vertexCount(), 4u);
  EXPECT_EQ(labels_of(t.cells), labels_of(vs));
  // Copying the struct copies the set (vertices shared).
  Tissue u = t;
  EXPECT_EQ(labels_of(u.cells), labels_of(vs));
  EXPECT_EQ(u.cells.name, "cells");
  u.cells.remove(vs[0]);
  EXPECT_EQ(t.cells.size(), 4u);
  EXPECT_EQ(u.cells.size(), 3u);
}

TEST(MeshDeclare, ParameterByReferenceChangesTheCallersMesh) {
  G::context ctx;
  Mesh M(ctx);
  std::vector<V> vs = make_vertices(ctx, 3);
  add_all(M, vs);
  EXPECT_EQ(M.size(), 3u);
  EXPECT_EQ(labels_of(M), labels_of(vs));
  EXPECT_EQ(M.generation, 1);
  add_all(M, vs);  // all already in: only the property changes
  EXPECT_EQ(M.size(), 3u);
  EXPECT_EQ(M.generation, 2);
}

TEST(MeshDeclare, ReturnValueCarriesMembersAndProperties) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 5);
  Mesh M = make_mesh_of(ctx, {vs[4], vs[1], vs[3]}, 7);
  EXPECT_EQ(labels_of(M), (Labels{vs[4].label(), vs[1].label(), vs[3].label()}));
  EXPECT_EQ(M.generation, 7);
  EXPECT_EQ(M.name, "made");
  // A returned mesh can be iterated directly (forall v in f(...)).
  Labels seen;
  for (V v : vv::each(make_mesh_of(ctx, {vs[2], vs[0]}, 1))) seen.push_back(v.label());
  EXPECT_EQ(seen, (Labels{vs[2].label(), vs[0].label()}));
  // Assigning a returned mesh to an existing one.
  M = make_mesh_of(ctx, {vs[0]}, 9);
  EXPECT_EQ(labels_of(M), Labels{vs[0].label()});
  EXPECT_EQ(M.generation, 9);
}

// =====================================================================
// Section 5: add / remove
// =====================================================================

TEST(MeshAdd, AddInsertsOnceAndAgainIsANoOp) {
  G::context ctx;
  Mesh M(ctx);
  std::vector<V> vs = make_vertices(ctx, 3);
  M.add(vs[1]);
  M.add(vs[0]);
  EXPECT_EQ(M.size(), 2u);
  M.add(vs[1]);  // already in
  M.add(vs[0]);
  EXPECT_EQ(M.size(), 2u);
  EXPECT_EQ(labels_of(M), (Labels{vs[1].label(), vs[0].label()}));
  EXPECT_TRUE(M.contains(vs[0]));
  EXPECT_TRUE(M.contains(vs[1]));
  EXPECT_FALSE(M.contains(vs[2]));
}

TEST(MeshRemove, RemoveDeletesAndAbsentIsANoOp) {
  G::context ctx;
  Mesh M(ctx);
  std::vector<V> vs = make_vertices(ctx, 4);
  for (int i = 0; i < 3; ++i) M.add(vs[i]);
  M.remove(vs[1]);
  EXPECT_EQ(M.size(), 2u);
  EXPECT_FALSE(M.contains(vs[1]));
  EXPECT_EQ(labels_of(M), (Labels{vs[0].label(), vs[2].label()}));
  M.remove(vs[1]);  // already removed
  M.remove(vs[3]);  // never a member
  M.remove(V());    // the null vertex is never a member
  EXPECT_EQ(M.size(), 2u);
  EXPECT_EQ(labels_of(M), (Labels{vs[0].label(), vs[2].label()}));
  // Removing from a mesh does not touch the vertex.
  EXPECT_TRUE(static_cast<bool>(vs[1]));
  EXPECT_EQ(vs[1]->tag, 2);
}

TEST(MeshRemove, RemoveFromOneMeshLeavesOthers) {
  G::context ctx;
  Mesh A(ctx), B(ctx);
  V v = tagged(ctx, 5);
  A.add(v);
  B.add(v);
  A.remove(v);
  EXPECT_FALSE(A.contains(v));
  EXPECT_TRUE(B.contains(v));
  EXPECT_EQ(B.size(), 1u);
}

// =====================================================================
// Section 5: merge and +=
// =====================================================================

TEST(MeshMerge, MergeIsUnionKeepingOrder) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 5);
  Mesh M(ctx), N(ctx);
  M.add(vs[0]);
  M.add(vs[2]);
  N.add(vs[3]);
  N.add(vs[2]);
  N.add(vs[1]);
  M.generation = 4;
  N.generation = 8;
  M.merge(N);
  EXPECT_EQ(labels_of(M), (Labels{vs[0].label(), vs[2].label(), vs[3].label(), vs[1].label()}));
  EXPECT_EQ(M.size(), 4u);
  EXPECT_EQ(M.generation, 4);  // merge changes the set only
  // N is unchanged.
  EXPECT_EQ(labels_of(N), (Labels{vs[3].label(), vs[2].label(), vs[1].label()}));
  // Merging again changes nothing; merging with itself changes nothing.
  M.merge(N);
  M.merge(M);
  EXPECT_EQ(M.size(), 4u);
  EXPECT_FALSE(M.contains(vs[4]));
}

TEST(MeshMerge, CountsEachNewMemberOnce) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 3);
  Mesh M(ctx), N(ctx);
  M.add(vs[0]);
  N.add(vs[0]);
  N.add(vs[1]);
  const std::uint32_t before0 = ctx.refs(vs[0].slot()), before1 = ctx.refs(vs[1].slot());
  M.merge(N);
  EXPECT_EQ(ctx.refs(vs[0].slot()), before0);  // already a member
  EXPECT_EQ(ctx.refs(vs[1].slot()), before1 + 1);
  EXPECT_EQ(ctx.refs(vs[2].slot()), 1u);  // the handle alone
}

TEST(MeshMerge, IntoAMeshWithoutContextTakesTheOthers) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 2);
  Mesh N(ctx);
  N.add(vs[1]);
  N.add(vs[0]);
  Mesh M;
  M.merge(N);
  EXPECT_EQ(M.ctx(), &ctx);
  EXPECT_EQ(labels_of(M), (Labels{vs[1].label(), vs[0].label()}));
}

TEST(MeshMerge, AMeshOfAnotherContextIsAnErrorAndChangesNothing) {
  G::context ctx, other;
  std::vector<V> vs = make_vertices(ctx, 1), strangers = make_vertices(other, 2);
  Mesh M(ctx), N(other);
  M.add(vs[0]);
  N.add(strangers[0]);
  N.add(strangers[1]);
  std::string message;
  try {
    M.merge(N);
  } catch (const vv::error& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("add: vertex 1 belongs to another context than the mesh"), std::string::npos) << message;
  EXPECT_EQ(labels_of(M), (Labels{vs[0].label()}));
}

TEST(MeshMerge, PlusEqualsIsUnionAndReturnsTheMesh) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 4);
  Mesh M(ctx), N(ctx), E(ctx);
  M.add(vs[1]);
  N.add(vs[0]);
  N.add(vs[1]);
  N.add(vs[3]);
  Mesh& r = (M += N);
  EXPECT_EQ(&r, &M);
  EXPECT_EQ(labels_of(M), (Labels{vs[1].label(), vs[0].label(), vs[3].label()}));
  M += E;  // union with the empty set
  EXPECT_EQ(M.size(), 3u);
  E += M;  // into an empty mesh
  EXPECT_EQ(labels_of(E), labels_of(M));
}

// =====================================================================
// Section 5: M = N
// =====================================================================

TEST(MeshAssign, CopiesTheSetSharesVerticesAndCopiesProperties) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 5);
  Mesh M(ctx), N(ctx);
  M.add(vs[4]);  // replaced by the assignment
  M.generation = 1;
  M.name = "old";
  N.add(vs[2]);
  N.add(vs[0]);
  N.add(vs[1]);
  N.generation = 6;
  N.name = "N";
  M = N;
  EXPECT_EQ(labels_of(M), (Labels{vs[2].label(), vs[0].label(), vs[1].label()}));
  EXPECT_FALSE(M.contains(vs[4]));
  EXPECT_EQ(M.generation, 6);
  EXPECT_EQ(M.name, "N");

  // Vertices are shared: an edit through N's members is seen through M's.
  for (V v : vv::each(N)) v->c = v->tag * 10.0;
  std::vector<double> cs;
  for (V v : vv::each(M)) cs.push_back(v->c);
  EXPECT_EQ(cs, (std::vector<double>{30.0, 10.0, 20.0}));
  V x = ctx.new_vertex();
  for (V v : vv::each(N)) vv::make_nb(v, {x});
  for (V v : vv::each(M)) EXPECT_EQ(nb_labels(v), Labels{x.label()});

  // The set is a copy: later changes to one do not reach the other.
  N.add(vs[3]);
  N.remove(vs[2]);
  N.generation = 99;
  EXPECT_EQ(labels_of(M), (Labels{vs[2].label(), vs[0].label(), vs[1].label()}));
  EXPECT_EQ(M.generation, 6);
  M.remove(vs[0]);
  EXPECT_TRUE(N.contains(vs[0]));
}

TEST(MeshAssign, SelfAssignmentKeepsEverything) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 3);
  Mesh M(ctx);
  for (const V& v : vs) M.add(v);
  M.generation = 3;
  Mesh& alias = M;
  M = alias;
  EXPECT_EQ(labels_of(M), labels_of(vs));
  EXPECT_EQ(M.generation, 3);
}

TEST(MeshAssign, AssigningAnEmptyMeshEmptiesTheSet) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 3);
  Mesh M(ctx), E(ctx);
  for (const V& v : vs) M.add(v);
  E.name = "empty";
  M = E;
  EXPECT_EQ(M.size(), 0u);
  EXPECT_EQ(labels_of(M), Labels{});
  EXPECT_EQ(M.name, "empty");
  for (const V& v : vs) EXPECT_FALSE(M.contains(v));
}

// =====================================================================
// Section 5: clear, membership, vertexCount, properties
// =====================================================================

TEST(MeshClear, EmptiesTheSetAndLeavesVerticesAndProperties) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 4);
  Mesh M(ctx);
  for (const V& v : vs) M.add(v);
  M.generation = 2;
  M.clear();
  EXPECT_EQ(M.size(), 0u);
  EXPECT_EQ(M.vertexCount(), 0u);
  EXPECT_EQ(labels_of(M), Labels{});
  for (const V& v : vs) EXPECT_FALSE(vv::is_in(v, M));
  EXPECT_EQ(M.generation, 2);
  EXPECT_EQ(vs[3]->tag, 4);
  // The mesh is usable after clearing; order starts afresh.
  M.add(vs[2]);
  M.add(vs[0]);
  EXPECT_EQ(labels_of(M), (Labels{vs[2].label(), vs[0].label()}));
  M.clear();
  M.clear();  // clearing an empty mesh
  EXPECT_EQ(M.size(), 0u);
}

TEST(MeshMembership, IsInIsTrueExactlyForMembers) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 3);
  Mesh M(ctx), N(ctx);
  M.add(vs[0]);
  N.add(vs[1]);
  EXPECT_TRUE(vv::is_in(vs[0], M));
  EXPECT_FALSE(vv::is_in(vs[1], M));
  EXPECT_FALSE(vv::is_in(vs[2], M));
  EXPECT_FALSE(vv::is_in(V(), M));
  EXPECT_TRUE(vv::is_in(vs[1], N));
  // Another handle to the same vertex is the same member.
  V again = vs[0];
  EXPECT_TRUE(vv::is_in(again, M));
  // A vertex of another context is not a member.
  G::context other;
  V foreign = other.new_vertex();
  EXPECT_FALSE(vv::is_in(foreign, M));
  M.remove(vs[0]);
  EXPECT_FALSE(vv::is_in(again, M));
}

TEST(MeshVertexCount, CountsDistinctMembers) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 10);
  Mesh M(ctx);
  EXPECT_EQ(M.vertexCount(), 0u);
  for (const V& v : vs) M.add(v);
  EXPECT_EQ(M.vertexCount(), 10u);
  for (const V& v : vs) M.add(v);
  EXPECT_EQ(M.vertexCount(), 10u);
  M.remove(vs[3]);
  M.remove(vs[7]);
  M.remove(vs[7]);
  EXPECT_EQ(M.vertexCount(), 8u);
  EXPECT_EQ(M.vertexCount(), M.size());
  M.clear();
  EXPECT_EQ(M.vertexCount(), 0u);
}

TEST(MeshProperties, ReadWriteAndPerMesh) {
  G::context ctx;
  Mesh M(ctx), N(ctx);
  M.generation = 3;
  M.name = "leaf";
  N.generation = -1;
  EXPECT_EQ(M.generation, 3);
  EXPECT_EQ(M.name, "leaf");
  EXPECT_EQ(N.generation, -1);
  EXPECT_EQ(N.name, "");
  M.generation += 2;
  EXPECT_EQ(M.generation, 5);
  // Properties do not depend on membership.
  V v = ctx.new_vertex();
  M.add(v);
  M.remove(v);
  EXPECT_EQ(M.generation, 5);
  EXPECT_EQ(M.name, "leaf");
}

// =====================================================================
// Section 5: synchronise
// =====================================================================

TEST(MeshSynchronise, SavesPropertiesNeighbourhoodRecordsAndFlagOfMembers) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 5);
  V a = vs[0], b = vs[1], c = vs[2], d = vs[3];
  Mesh M(ctx);
  for (int i = 0; i < 4; ++i) M.add(vs[i]);
  a->c = 1.5;
  a->pos = Pt(1, 2, 3);
  vv::make_nb(a, {b, c, d});
  vv::edge(a, b).mark = 4;
  vv::edge(a, d).mark = 6;
  vv::flag_in(c, a);
  vv::make_nb(b, {a});
  b->c = -2;

  vv::synchronise(M);

  // Change the current state in every respect.
  a->c = 2.5;
  a->pos = Pt(0, 0, 0);
  vv::make_nb(a, {d, b});
  vv::edge(a, b).mark = 40;
  vv::flag_in(d, a);
  b->c = 7;
  vv::erase_from(a, b);

  // The old state is the one saved.
  EXPECT_TRUE(vv::old(a).synchronised());
  EXPECT_EQ(vv::old(a)->c, 1.5);
  EXPECT_EQ(vv::old(a)->pos, Pt(1, 2, 3));
  EXPECT_EQ(old_nb_labels(a), (Labels{b.label(), c.label(), d.label()}));
  EXPECT_EQ(vv::valence(vv::old(a)), 3u);
  EXPECT_EQ(vv::edge(vv::old(a), b).mark, 4);
  EXPECT_EQ(vv::edge(vv::old(a), c).mark, 0);
  EXPECT_EQ(vv::edge(vv::old(a), d).mark, 6);
  EXPECT_EQ(vv::flagged_in(vv::old(a)), c);
  EXPECT_EQ(vv::next_to(b, vv::old(a)), c);
  EXPECT_EQ(vv::old(b)->c, -2);
  EXPECT_EQ(old_nb_labels(b), Labels{a.label()});
  // A member without neighbours has an empty, synchronised old state.
  EXPECT_TRUE(vv::old(d).synchronised());
  EXPECT_EQ(vv::valence(vv::old(d)), 0u);

  // The current state is untouched by the old one.
  EXPECT_EQ(a->c, 2.5);
  EXPECT_EQ(nb_labels(a), (Labels{d.label(), b.label()}));
  EXPECT_EQ(vv::edge(a, b).mark, 40);
  EXPECT_TRUE(vv::edge(vv::old(a), b) != vv::edge(a, b));
  EXPECT_EQ(vv::flagged_in(a), d);
  EXPECT_EQ(nb_labels(b), Labels{});

  // A second synchronise replaces the saved state.
  vv::synchronise(M);
  EXPECT_EQ(vv::old(a)->c, 2.5);
  EXPECT_EQ(old_nb_labels(a), (Labels{d.label(), b.label()}));
  EXPECT_EQ(vv::edge(vv::old(a), b).mark, 40);
  EXPECT_EQ(vv::flagged_in(vv::old(a)), d);
  EXPECT_EQ(old_nb_labels(b), Labels{});
}

TEST(MeshSynchronise, UnsetFlagIsSavedUnset) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 3);
  Mesh M(ctx);
  M.add(vs[0]);
  vv::make_nb(vs[0], {vs[1], vs[2]});
  vv::synchronise(M);
  vv::flag_in(vs[2], vs[0]);
  EXPECT_EQ(vv::flagged_in(vv::old(vs[0])), V());
  EXPECT_EQ(vv::flagged_in(vs[0]), vs[2]);
}

TEST(MeshSynchronise, DoesNotTouchNonMembers) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 4);
  V m = vs[0], outside = vs[1], other = vs[2], was_member = vs[3];
  Mesh M(ctx);
  M.add(m);
  M.add(was_member);
  M.remove(was_member);
  for (const V& v : {m, outside, was_member}) {
    v->c = 3;
    vv::make_nb(v, {other});
    vv::edge(v, other).mark = 1;
  }
  vv::flag_in(other, outside);
  vv::synchronise(M);

  EXPECT_TRUE(vv::old(m).synchronised());
  EXPECT_EQ(vv::old(m)->c, 3);
  for (const V& v : {outside, was_member}) {
    EXPECT_FALSE(vv::old(v).synchronised());
    EXPECT_EQ(vv::old(v)->c, 0);
    EXPECT_EQ(vv::old(v)->tag, 0);
    EXPECT_EQ(vv::valence(vv::old(v)), 0u);
    EXPECT_EQ(old_nb_labels(v), Labels{});
    EXPECT_EQ(vv::flagged_in(vv::old(v)), V());
  }
  // A neighbour of a member is not synchronised either.
  EXPECT_FALSE(vv::old(other).synchronised());
}

TEST(MeshSynchronise, AmericanSpellingDoesTheSame) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 3);
  Mesh M(ctx);
  M.add(vs[0]);
  M.add(vs[1]);
  vs[0]->c = 8;
  vv::make_nb(vs[0], {vs[1], vs[2]});
  vv::edge(vs[0], vs[2]).mark = 12;
  vv::flag_in(vs[2], vs[0]);
  vv::synchronize(M);
  vs[0]->c = 9;
  vv::make_nb(vs[0], {});
  EXPECT_EQ(vv::old(vs[0])->c, 8);
  EXPECT_EQ(old_nb_labels(vs[0]), (Labels{vs[1].label(), vs[2].label()}));
  EXPECT_EQ(vv::edge(vv::old(vs[0]), vs[2]).mark, 12);
  EXPECT_EQ(vv::flagged_in(vv::old(vs[0])), vs[2]);
  EXPECT_TRUE(vv::old(vs[1]).synchronised());
  EXPECT_FALSE(vv::old(vs[2]).synchronised());
}

// =====================================================================
// Lifetime: a mesh keeps its members alive
// =====================================================================

TEST(MeshLifetime, MembersStayAliveWithoutHandles) {
  G::context ctx;
  Mesh M(ctx);
  unsigned first_label = 0;
  {
    std::vector<V> vs = make_vertices(ctx, 3, 21);
    for (const V& v : vs) M.add(v);
    first_label = vs[0].label();
  }
  EXPECT_EQ(ctx.live_vertices(), 3u);
  EXPECT_EQ(ctx.collect_garbage(), 0u);
  EXPECT_EQ(ctx.live_vertices(), 3u);
  // Creating vertices reuses no member's storage.
  for (int i = 0; i < 50; ++i) tagged(ctx, -1);
  EXPECT_EQ(ctx.collect_garbage(), 50u);
  EXPECT_EQ(tags_of(M), (std::vector<int>{21, 22, 23}));
  EXPECT_EQ(labels_of(M), (Labels{first_label, first_label + 1, first_label + 2}));
}

TEST(MeshLifetime, RemovedMemberWithoutHandlesIsFreed) {
  G::context ctx;
  Mesh M(ctx);
  {
    std::vector<V> vs = make_vertices(ctx, 3);
    for (const V& v : vs) M.add(v);
  }
  ASSERT_EQ(ctx.live_vertices(), 3u);
  {
    V second;
    for (V v : M)
      if (v->tag == 2) second = v;
    ASSERT_TRUE(static_cast<bool>(second));
    M.remove(second);
    // Still held by `second`.
    EXPECT_EQ(ctx.collect_garbage(), 0u);
    EXPECT_EQ(ctx.live_vertices(), 3u);
  }
  EXPECT_EQ(ctx.collect_garbage(), 1u);
  EXPECT_EQ(ctx.live_vertices(), 2u);
  EXPECT_EQ(tags_of(M), (std::vector<int>{1, 3}));
}

TEST(MeshLifetime, VertexInSeveralMeshesLivesUntilTheLastLetsGo) {
  G::context ctx;
  Mesh A(ctx), B(ctx);
  {
    V v = tagged(ctx, 5);
    A.add(v);
    B.add(v);
  }
  V probe;
  for (V v : A) probe = v;
  A.remove(probe);
  probe = V();
  EXPECT_EQ(ctx.collect_garbage(), 0u);
  EXPECT_EQ(tags_of(B), std::vector<int>{5});
  B.clear();
  EXPECT_EQ(ctx.collect_garbage(), 1u);
  EXPECT_EQ(ctx.live_vertices(), 0u);
}

TEST(MeshLifetime, DestroyedMeshReleasesItsMembers) {
  G::context ctx;
  {
    Mesh M(ctx);
    for (int i = 0; i < 4; ++i) M.add(ctx.new_vertex());
    EXPECT_EQ(ctx.collect_garbage(), 0u);
  }
  EXPECT_EQ(ctx.collect_garbage(), 4u);
  EXPECT_EQ(ctx.live_vertices(), 0u);
}

// =====================================================================
// Iteration order is insertion order
// =====================================================================

TEST(MeshOrder, IterationFollowsInsertionNotLabels) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 6);
  Mesh M(ctx);
  for (int i : {4, 1, 5, 0, 3, 2}) M.add(vs[static_cast<std::size_t>(i)]);
  EXPECT_EQ(tags_of(M), (std::vector<int>{5, 2, 6, 1, 4, 3}));
  // Iterating twice gives the same order.
  EXPECT_EQ(tags_of(M), (std::vector<int>{5, 2, 6, 1, 4, 3}));
}

TEST(MeshOrder, RemovalKeepsOrderAndReAddGoesToTheEnd) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 5);
  Mesh M(ctx);
  for (const V& v : vs) M.add(v);
  M.remove(vs[1]);
  M.remove(vs[3]);
  EXPECT_EQ(tags_of(M), (std::vector<int>{1, 3, 5}));
  M.add(vs[3]);
  M.add(vs[1]);
  EXPECT_EQ(tags_of(M), (std::vector<int>{1, 3, 5, 4, 2}));
  M.add(vs[0]);  // already in: stays first
  EXPECT_EQ(tags_of(M), (std::vector<int>{1, 3, 5, 4, 2}));
  M.remove(vs[0]);
  M.add(vs[0]);
  EXPECT_EQ(tags_of(M), (std::vector<int>{3, 5, 4, 2, 1}));
}

TEST(MeshOrder, OrderSurvivesManyRemovals) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 1000);
  Mesh M(ctx);
  for (const V& v : vs) M.add(v);
  std::vector<int> expected;
  for (int i = 0; i < 1000; ++i)
    if (i % 10 == 3) expected.push_back(i + 1);
    else M.remove(vs[static_cast<std::size_t>(i)]);
  EXPECT_EQ(M.size(), 100u);
  EXPECT_EQ(tags_of(M), expected);
  for (int i = 999; i >= 0; i -= 100) {
    M.add(vs[static_cast<std::size_t>(i)]);
    expected.push_back(i + 1);
  }
  EXPECT_EQ(tags_of(M), expected);
  for (int i = 0; i < 1000; ++i)
    EXPECT_EQ(M.contains(vs[static_cast<std::size_t>(i)]), i % 10 == 3 || i % 100 == 99) << i;
  EXPECT_NO_THROW(vv::check_invariants(M));
}

// =====================================================================
// A large mesh against a model
// =====================================================================

TEST(MeshLarge, RandomAddRemoveContainsMatchesAModel) {
  constexpr std::size_t n = 100000;
  constexpr int operations = 300000;
  G::context ctx;
  Mesh M(ctx);
  std::vector<V> pool;
  pool.reserve(n);
  for (std::size_t i = 0; i < n; ++i) pool.push_back(ctx.new_vertex());

  std::unordered_set<unsigned> model;
  std::list<unsigned> order;
  std::unordered_map<unsigned, std::list<unsigned>::iterator> place;
  auto model_add = [&](const V& v) {
    if (model.insert(v.label()).second) place[v.label()] = order.insert(order.end(), v.label());
  };
  auto model_remove = [&](const V& v) {
    if (model.erase(v.label())) {
      order.erase(place[v.label()]);
      place.erase(v.label());
    }
  };
  auto check_order = [&](int at) {
    Labels got = labels_of(M);
    Labels want(order.begin(), order.end());
    EXPECT_EQ(got.size(), want.size()) << "after operation " << at;
    EXPECT_TRUE(got == want) << "iteration order differs from the model after operation " << at;
  };

  // Start with every vertex in, in a shuffled order.
  std::mt19937 rng(20240607u);
  std::vector<std::size_t> perm(n);
  for (std::size_t i = 0; i < n; ++i) perm[i] = i;
  for (std::size_t i = n - 1; i > 0; --i) std::swap(perm[i], perm[rng() % (i + 1)]);
  for (std::size_t i : perm) {
    M.add(pool[i]);
    model_add(pool[i]);
  }
  ASSERT_EQ(M.size(), n);
  check_order(0);

  int wrong_membership = 0, wrong_size = 0, first_wrong = -1;
  for (int op = 1; op <= operations; ++op) {
    const V& v = pool[rng() % n];
    unsigned kind = rng() % 10;
    if (kind < 4) {
      M.add(v);
      model_add(v);
    } else if (kind < 9) {
      M.remove(v);
      model_remove(v);
    }
    bool in = M.contains(v);
    if (in != (model.count(v.label()) != 0) || vv::is_in(v, M) != in) {
      ++wrong_membership;
      if (first_wrong < 0) first_wrong = op;
    }
    if (M.size() != model.size()) ++wrong_size;
    if (op % 30000 == 0) check_order(op);
  }
  EXPECT_EQ(wrong_membership, 0) << "first at operation " << first_wrong;
  EXPECT_EQ(wrong_size, 0);
  EXPECT_EQ(M.vertexCount(), model.size());
  // Every vertex, member or not, answers membership like the model.
  std::size_t mismatches = 0;
  for (const V& v : pool)
    if (M.contains(v) != (model.count(v.label()) != 0)) ++mismatches;
  EXPECT_EQ(mismatches, 0u);
  check_order(operations);
  EXPECT_NO_THROW(vv::check_invariants(M));
}

// A subdivision step's meshes hold new vertices, in the slots after all
// the others; a long model's hold reused slots, below them. The index
// (dense over a window of slots, or hashed when the members are spread
// thin) must answer like a set whichever way its window has to move.
TEST(MeshLarge, MembershipStaysRightAsTheSlotsMoveAboveAndBelow) {
  G::context ctx;
  std::mt19937 rng(20261129u);
  std::vector<V> older;  // kept alive: their slots stay taken
  for (int i = 0; i < 20000; ++i) older.push_back(ctx.new_vertex());

  Mesh M(ctx);
  std::vector<V> candidates;
  std::unordered_set<unsigned> model;
  std::list<unsigned> order;
  std::unordered_map<unsigned, std::list<unsigned>::iterator> place;
  auto add = [&](const V& v) {
    M.add(v);
    if (model.insert(v.label()).second) place[v.label()] = order.insert(order.end(), v.label());
  };
  auto remove = [&](const V& v) {
    M.remove(v);
    if (model.erase(v.label())) {
      order.erase(place[v.label()]);
      place.erase(v.label());
    }
  };
  int wrong = 0;
  auto check = [&](const char* phase) {
    for (const V& v : candidates)
      if (M.contains(v) != (model.count(v.label()) != 0)) ++wrong;
    for (const V& v : older)
      if (M.contains(v) != (model.count(v.label()) != 0)) ++wrong;
    EXPECT_EQ(wrong, 0) << phase;
    EXPECT_EQ(M.size(), model.size()) << phase;
    EXPECT_TRUE(labels_of(M) == Labels(order.begin(), order.end())) << phase;
  };

  // 1. New vertices, one after another above everything (dense at once).
  for (int i = 0; i < 5000; ++i) {
    candidates.push_back(ctx.new_vertex());
    add(candidates.back());
  }
  check("new vertices");
  // 2. Older vertices below the window, a few, then many (it moves down).
  for (int i = 0; i < 50; ++i) add(older[19999 - 7 * i]);
  check("a few below");
  for (int i = 0; i < 20000; i += 3) add(older[i]);
  check("many below");
  // 3. Removals, and vertices far above (the context grew meanwhile).
  for (int i = 0; i < 20000; ++i) ctx.new_vertex();
  for (int i = 0; i < 3000; ++i) remove(candidates[rng() % candidates.size()]);
  for (int i = 0; i < 300; ++i) {
    candidates.push_back(ctx.new_vertex());
    add(candidates.back());
  }
  check("removals and far above");
  // 4. Spread thin: every 50th slot of a much larger range (hashed).
  Mesh thin(ctx);
  std::vector<V> spread;
  for (int i = 0; i < 200000; ++i) {
    V v = ctx.new_vertex();
    if (i % 50 == 0) spread.push_back(v), thin.add(v);
  }
  for (std::size_t i = 0; i < 300; ++i) thin.add(older[i * 61]);
  std::size_t thin_wrong = 0;
  for (std::size_t i = 0; i < spread.size(); ++i)
    if (!thin.contains(spread[i])) ++thin_wrong;
  for (std::size_t i = 0; i < older.size(); ++i)
    if (thin.contains(older[i]) != (i % 61 == 0 && i / 61 < 300)) ++thin_wrong;
  EXPECT_EQ(thin_wrong, 0u);
  EXPECT_EQ(thin.size(), spread.size() + 300);
  // ... and its storage stays within a few dozen bytes a member, not 4 a
  // slot of the context (880 kB).
  EXPECT_LT(thin.storage_bytes(), 40 * thin.size());
  // 5. Slots freed and reused: new vertices now take scattered low slots.
  M.clear();
  model.clear(), order.clear(), place.clear();
  older.resize(1000);
  candidates.clear();
  ctx.collect_garbage();
  for (int i = 0; i < 8000; ++i) {
    candidates.push_back(ctx.new_vertex());
    add(candidates.back());
    if (i % 5 == 0) remove(candidates[rng() % candidates.size()]);
  }
  check("reused slots");
  EXPECT_NO_THROW(vv::check_invariants(M));
}

// =====================================================================
// Section 6: forall over a mesh
// =====================================================================

TEST(ForallMesh, VisitsMembersAtEntryInInsertionOrder) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 5);
  Mesh M(ctx);
  for (int i : {2, 0, 4, 1}) M.add(vs[static_cast<std::size_t>(i)]);
  std::vector<int> seen;
  for (V v : vv::each(M)) seen.push_back(v->tag);
  EXPECT_EQ(seen, (std::vector<int>{3, 1, 5, 2}));
  // Range-for directly on the mesh is the same loop.
  seen.clear();
  for (auto v : M) seen.push_back(v->tag);
  EXPECT_EQ(seen, (std::vector<int>{3, 1, 5, 2}));
  // An empty mesh: no visits.
  Mesh E(ctx);
  int visits = 0;
  for (V v : vv::each(E)) visits += v->tag;
  EXPECT_EQ(visits, 0);
}

TEST(ForallMesh, RemovingTheCurrentVertexIsSafe) {
  G::context ctx;
  Mesh M(ctx);
  for (int i = 1; i <= 200; ++i) M.add(tagged(ctx, i));  // held by the mesh only
  std::vector<int> seen;
  for (V v : vv::each(M)) {
    seen.push_back(v->tag);
    M.remove(v);
  }
  std::vector<int> expected;
  for (int i = 1; i <= 200; ++i) expected.push_back(i);
  EXPECT_EQ(seen, expected);
  EXPECT_EQ(M.size(), 0u);
  EXPECT_EQ(labels_of(M), Labels{});
  EXPECT_EQ(ctx.collect_garbage(), 200u);
}

TEST(ForallMesh, RemovingEveryOtherCurrentVertexKeepsTheRest) {
  G::context ctx;
  Mesh M(ctx);
  for (int i = 1; i <= 10; ++i) M.add(tagged(ctx, i));
  std::vector<int> seen;
  for (V v : vv::each(M)) {
    seen.push_back(v->tag);
    if (v->tag % 2 == 0) M.remove(v);
  }
  EXPECT_EQ(seen, (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10}));
  EXPECT_EQ(tags_of(M), (std::vector<int>{1, 3, 5, 7, 9}));
}

TEST(ForallMesh, MembersRemovedBeforeTheirTurnAreSkipped) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 6);
  Mesh M(ctx);
  for (const V& v : vs) M.add(v);
  std::vector<int> seen;
  for (V v : vv::each(M)) {
    seen.push_back(v->tag);
    if (v->tag == 1) {
      M.remove(vs[2]);
      M.remove(vs[4]);
    }
    if (v->tag == 4) M.remove(vs[0]);  // already visited: no effect on the loop
  }
  EXPECT_EQ(seen, (std::vector<int>{1, 2, 4, 6}));
  EXPECT_EQ(tags_of(M), (std::vector<int>{2, 4, 6}));
}

TEST(ForallMesh, MembersAddedDuringTheLoopAreNotVisited) {
  G::context ctx;
  Mesh M(ctx);
  for (int i = 1; i <= 3; ++i) M.add(tagged(ctx, i));
  std::vector<int> seen;
  int next_tag = 100;
  for (V v : vv::each(M)) {
    seen.push_back(v->tag);
    for (int k = 0; k < 30; ++k) M.add(tagged(ctx, next_tag++));  // grows the storage
  }
  EXPECT_EQ(seen, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(M.size(), 93u);
  std::vector<int> tags = tags_of(M);
  EXPECT_EQ(tags.front(), 1);
  EXPECT_EQ(tags[3], 100);
  EXPECT_EQ(tags.back(), 189);
}

TEST(ForallMesh, RemovedAndReAddedBeforeItsTurnIsNotVisited) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 4);
  Mesh M(ctx);
  for (const V& v : vs) M.add(v);
  std::vector<int> seen;
  for (V v : vv::each(M)) {
    seen.push_back(v->tag);
    if (v->tag == 1) {
      M.remove(vs[2]);
      M.add(vs[2]);  // now added during the loop
    }
  }
  EXPECT_EQ(seen, (std::vector<int>{1, 2, 4}));
  EXPECT_EQ(tags_of(M), (std::vector<int>{1, 2, 4, 3}));
}

TEST(ForallMesh, ClearingTheMeshEndsTheVisits) {
  G::context ctx;
  Mesh M(ctx);
  for (int i = 1; i <= 100; ++i) M.add(tagged(ctx, i));
  std::vector<int> seen;
  for (V v : vv::each(M)) {
    seen.push_back(v->tag);
    if (v->tag == 2) M.clear();
  }
  EXPECT_EQ(seen, (std::vector<int>{1, 2}));
  EXPECT_EQ(M.size(), 0u);
  // The mesh works normally afterwards.
  M.add(tagged(ctx, 9));
  EXPECT_EQ(tags_of(M), std::vector<int>{9});
}

TEST(ForallMesh, ClearAndRefillInsideTheLoopVisitsNothingNew) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 4);
  Mesh M(ctx);
  for (const V& v : vs) M.add(v);
  std::vector<int> seen;
  for (V v : vv::each(M)) {
    seen.push_back(v->tag);
    if (v->tag == 1) {
      M.clear();
      for (const V& w : vs) M.add(w);  // all re-added during the loop
    }
  }
  EXPECT_EQ(seen, std::vector<int>{1});
  EXPECT_EQ(tags_of(M), (std::vector<int>{1, 2, 3, 4}));
  EXPECT_NO_THROW(vv::check_invariants(M));
}

TEST(ForallMesh, AssigningTheMeshInsideItsLoop) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 6);
  Mesh M(ctx), N(ctx);
  for (int i = 0; i < 5; ++i) M.add(vs[static_cast<std::size_t>(i)]);
  N.add(vs[1]);
  N.add(vs[3]);
  N.add(vs[5]);
  std::vector<int> seen;
  for (V v : vv::each(M)) {
    seen.push_back(v->tag);
    if (v->tag == 1) M = N;  // 1, 3, 5 removed; 6 added
  }
  EXPECT_EQ(seen, (std::vector<int>{1, 2, 4}));
  EXPECT_EQ(M.size(), 3u);
  EXPECT_TRUE(M.contains(vs[1]));
  EXPECT_TRUE(M.contains(vs[3]));
  EXPECT_TRUE(M.contains(vs[5]));
  // Assigning a returned mesh (a move) inside the loop behaves the same.
  seen.clear();
  for (V v : vv::each(M)) {
    seen.push_back(v->tag);
    if (v->tag == 2) M = make_mesh_of(ctx, {vs[0], vs[1]}, 4);  // 4, 6 removed; 1 added
  }
  EXPECT_EQ(seen, std::vector<int>{2});
  EXPECT_EQ(M.size(), 2u);
  EXPECT_TRUE(M.contains(vs[0]));
  EXPECT_TRUE(M.contains(vs[1]));
  EXPECT_FALSE(M.contains(vs[3]));
  EXPECT_FALSE(M.contains(vs[5]));
  EXPECT_EQ(M.generation, 4);
}

// Moving the mesh out of its own loop, or swapping it, copies instead of
// stealing the storage the loop reads; the loop then sees the new members.
TEST(ForallMesh, MovingOrSwappingTheMeshInsideItsLoop) {
  G::context ctx;
  std::vector<V> vs = make_vertices(ctx, 6);
  Mesh S(ctx), N(ctx);
  for (int i = 0; i < 4; ++i) S.add(vs[static_cast<std::size_t>(i)]);
  std::vector<int> seen;
  for (V v : vv::each(S)) {
    seen.push_back(v->tag);
    if (v->tag == 2) N = std::move(S);  // S empties: the loop ends
  }
  EXPECT_EQ(seen, (std::vector<int>{1, 2}));
  EXPECT_TRUE(S.empty());
  EXPECT_EQ(N.size(), 4u);

  seen.clear();
  for (V v : vv::each(N)) {
    seen.push_back(v->tag);
    if (v->tag == 1) {
      Mesh taken(std::move(N));  // move construction from the iterated mesh
      EXPECT_EQ(taken.size(), 4u);
    }
  }
  EXPECT_EQ(seen, std::vector<int>{1});
  EXPECT_TRUE(N.empty());

  Mesh A(ctx), B(ctx);
  for (int i = 0; i < 4; ++i) A.add(vs[static_cast<std::size_t>(i)]);
  B.add(vs[4]);
  B.add(vs[5]);
  seen.clear();
  for (V v : vv::each(A)) {
    seen.push_back(v->tag);
    if (v->tag == 2) std::swap(A, B);  // 3, 4 left A; 5, 6 came in after the loop's start
  }
  EXPECT_EQ(seen, (std::vector<int>{1, 2}));
  EXPECT_EQ(tags_of(A), (std::vector<int>{5, 6}));
  EXPECT_EQ(tags_of(B), (std::vector<int>{1, 2, 3, 4}));
  EXPECT_NO_THROW(vv::check_invariants(A));
  EXPECT_NO_THROW(vv::check_invariants(B));
}

TEST(ForallMesh, NestedLoopsOverTheSameMesh) {
  G::context ctx;
  Mesh M(ctx);
  for (int i = 1; i <= 4; ++i) M.add(tagged(ctx, i));
  std::vector<std::pair<int, int>> pairs;
  for (V a : vv::each(M))
    for (V b : vv::each(M)) pairs.emplace_back(a->tag, b->tag);
  ASSERT_EQ(pairs.size(), 16u);
  for (int i = 0; i < 16; ++i) {
    EXPECT_EQ(pairs[static_cast<std::size_t>(i)].first, i / 4 + 1);
    EXPECT_EQ(pairs[static_cast<std::size_t>(i)].second, i % 4 + 1);
  }
}

TEST(ForallMesh, NestedLoopRemovalIsSeenByTheOuterLoop) {
  G::context ctx;
  Mesh M(ctx);
  for (int i = 1; i <= 6; ++i) M.add(tagged(ctx, i));
  std::vector<int> outer;
  int inner_visits = 0;
  for (V a : vv::each(M)) {
    outer.push_back(a->tag);
    for (V b : vv::each(M)) {
      ++inner_visits;
      if (b->tag == a->tag + 1) M.remove(b);  // the outer loop's next member
    }
  }
  // 1 removes 2, 3 removes 4, 5 removes 6.
  EXPECT_EQ(outer, (std::vector<int>{1, 3, 5}));
  EXPECT_EQ(inner_visits, 6 + 5 + 4);
  EXPECT_EQ(tags_of(M), (std::vector<int>{1, 3, 5}));
  EXPECT_NO_THROW(vv::check_invariants(M));
}

TEST(ForallMesh, MassRemovalInAnInnerLoopKeepsTheOuterLoopsPlace) {
  // Enough removals that the set would squeeze out its holes if it could:
  // it must not while the outer loop still runs.
  G::context ctx;
  Mesh M(ctx);
  for (int i = 1; i <= 300; ++i) M.add(tagged(ctx, i));
  std::vector<int> outer;
  for (V a : vv::each(M)) {
    outer.push_back(a->tag);
    if (a->tag == 1) {
      for (V b : vv::each(M))
        if (b->tag > 1 && b->tag % 3 != 0) M.remove(b);
      EXPECT_EQ(M.size(), 101u);
    }
  }
  std::vector<int> expected{1};
  for (int i = 3; i <= 300; i += 3) expected.push_back(i);
  EXPECT_EQ(outer, expected);
  EXPECT_EQ(tags_of(M), expected);
  EXPECT_NO_THROW(vv::check_invariants(M));
}

TEST(ForallMesh, BreakAndContinue) {
  G::context ctx;
  Mesh M(ctx);
  for (int i = 1; i <= 8; ++i) M.add(tagged(ctx, i));
  std::vector<int> seen;
  for (V v : vv::each(M)) {
    if (v->tag % 3 == 0) continue;
    if (v->tag == 7) break;
    seen.push_back(v->tag);
  }
  EXPECT_EQ(seen, (std::vector<int>{1, 2, 4, 5}));
  // After a break the mesh can be edited and iterated normally.
  M.remove(*M.begin());
  EXPECT_EQ(tags_of(M), (std::vector<int>{2, 3, 4, 5, 6, 7, 8}));
}

TEST(ForallMesh, RemovalsAndGarbageCollectionDuringTheLoop) {
  G::context ctx;
  Mesh M(ctx);
  for (int i = 1; i <= 2000; ++i) M.add(tagged(ctx, i));  // held by the mesh only
  std::vector<int> seen;
  int created = 0;
  for (V v : vv::each(M)) {
    seen.push_back(v->tag);
    // Remove the current vertex and the next one (no handle keeps them).
    int t = v->tag;
    M.remove(v);
    for (V w : vv::each(M))
      if (w->tag == t + 1) {
        M.remove(w);
        break;
      }
    // Enough dropped vertices to let the collector run and reuse slots; a
    // few of them join the mesh (never visited by this loop).
    for (int k = 0; k < 40; ++k) {
      V tmp = tagged(ctx, -1);
      ++created;
      if (k == 0) M.add(tmp);
    }
  }
  std::vector<int> expected;
  for (int i = 1; i <= 2000; i += 2) expected.push_back(i);
  EXPECT_EQ(seen, expected);
  EXPECT_EQ(created, 40000);
  // The collector ran during the loop: freed slots were reused.
  EXPECT_LT(ctx.slot_count(), 2000u + 40000u + 1u);
  EXPECT_EQ(M.size(), 1000u);
  for (int t : tags_of(M)) EXPECT_EQ(t, -1);
  EXPECT_NO_THROW(vv::check_invariants(M));
}

// =====================================================================
// Section 6: forall over a neighbourhood
// =====================================================================

struct Star {
  V centre;
  std::vector<V> ring;
};

Star make_star(G::context& ctx, int n) {
  Star s{tagged(ctx, 0), make_vertices(ctx, n)};
  vv::make_nb_from(s.centre, s.ring);
  return s;
}

TEST(ForallNeighbourhood, VisitsNeighboursInRotationOrder) {
  G::context ctx;
  Star s = make_star(ctx, 5);
  std::vector<int> seen;
  for (V x : vv::each(s.centre)) seen.push_back(x->tag);
  EXPECT_EQ(seen, (std::vector<int>{1, 2, 3, 4, 5}));
  // The rotation starts where the list starts.
  vv::make_nb(s.centre, {s.ring[3], s.ring[0], s.ring[4]});
  seen.clear();
  for (V x : vv::each(s.centre)) seen.push_back(x->tag);
  EXPECT_EQ(seen, (std::vector<int>{4, 1, 5}));
  // No neighbours: no visits.
  V lone = ctx.new_vertex();
  int visits = 0;
  for (V x : vv::each(lone)) visits += x->tag + 1;
  EXPECT_EQ(visits, 0);
}

TEST(ForallNeighbourhood, BodyErasingNeighboursStillVisitsAll) {
  G::context ctx;
  Star s = make_star(ctx, 6);
  std::vector<int> seen;
  for (V x : vv::each(s.centre)) {
    seen.push_back(x->tag);
    vv::erase_from(x, s.centre);
    if (x->tag == 2) vv::erase_from(s.ring[4], s.centre);  // one not yet visited
  }
  EXPECT_EQ(seen, (std::vector<int>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(vv::valence(s.centre), 0u);
}

TEST(ForallNeighbourhood, BodySplicingDoesNotAddVisits) {
  G::context ctx;
  Star s = make_star(ctx, 3);
  std::vector<int> seen;
  int next_tag = 10;
  for (V x : vv::each(s.centre)) {
    seen.push_back(x->tag);
    vv::splice_after(tagged(ctx, next_tag++), x, s.centre);
    vv::splice_before(tagged(ctx, next_tag++), x, s.centre);
  }
  EXPECT_EQ(seen, (std::vector<int>{1, 2, 3}));
  std::vector<int> now;
  for (V x : vv::each(s.centre)) now.push_back(x->tag);
  EXPECT_EQ(now, (std::vector<int>{11, 1, 10, 13, 2, 12, 15, 3, 14}));
}

TEST(ForallNeighbourhood, BodyMakingTheNeighbourhoodVisitsTheEntryList) {
  G::context ctx;
  Star s = make_star(ctx, 4);
  std::vector<V> others = make_vertices(ctx, 3, 50);
  std::vector<int> seen;
  for (V x : vv::each(s.centre)) {
    seen.push_back(x->tag);
    vv::make_nb_from(s.centre, others);
  }
  EXPECT_EQ(seen, (std::vector<int>{1, 2, 3, 4}));
  std::vector<int> now;
  for (V x : vv::each(s.centre)) now.push_back(x->tag);
  EXPECT_EQ(now, (std::vector<int>{50, 51, 52}));
}

TEST(ForallNeighbourhood, BodyReplacingNeighboursVisitsTheEntryList) {
  G::context ctx;
  Star s = make_star(ctx, 4);
  std::vector<int> seen;
  int next_tag = 20;
  for (V x : vv::each(s.centre)) {
    seen.push_back(x->tag);
    V y = tagged(ctx, next_tag++);
    vv::replace_in(x, y, s.centre);
  }
  EXPECT_EQ(seen, (std::vector<int>{1, 2, 3, 4}));
  std::vector<int> now;
  for (V x : vv::each(s.centre)) now.push_back(x->tag);
  EXPECT_EQ(now, (std::vector<int>{20, 21, 22, 23}));
}

TEST(ForallNeighbourhood, LongNeighbourhoodEmptiedByTheBody) {
  G::context ctx;
  Star s = make_star(ctx, 40);
  std::vector<int> seen;
  for (V x : vv::each(s.centre)) {
    seen.push_back(x->tag);
    vv::make_nb(s.centre, {});
  }
  std::vector<int> expected;
  for (int i = 1; i <= 40; ++i) expected.push_back(i);
  EXPECT_EQ(seen, expected);
}

TEST(ForallNeighbourhood, OldNeighbourhood) {
  G::context ctx;
  Star s = make_star(ctx, 4);
  Mesh M(ctx);
  M.add(s.centre);
  vv::synchronise(M);
  vv::make_nb(s.centre, {s.ring[2], s.ring[1]});
  std::vector<int> seen_old, seen_now;
  for (V x : vv::each(vv::old(s.centre))) {
    seen_old.push_back(x->tag);
    vv::erase_from(x, s.centre);  // edits the current state only
  }
  for (V x : vv::each(s.centre)) seen_now.push_back(x->tag);
  EXPECT_EQ(seen_old, (std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(seen_now, std::vector<int>{});
  // A loop over the old state whose body synchronises again.
  vv::make_nb(s.centre, {s.ring[0]});
  seen_old.clear();
  for (V x : vv::each(vv::old(s.centre))) {
    seen_old.push_back(x->tag);
    vv::synchronise(M);
  }
  EXPECT_EQ(seen_old, (std::vector<int>{1, 2, 3, 4}));
  EXPECT_EQ(old_nb_labels(s.centre), Labels{s.ring[0].label()});
}

TEST(ForallNeighbourhood, NeverSynchronisedOldNeighbourhoodIsEmpty) {
  G::context ctx;
  Star s = make_star(ctx, 3);
  int visits = 0;
  for (V x : vv::each(vv::old(s.centre))) visits += x->tag + 1;
  EXPECT_EQ(visits, 0);
}

TEST(ForallNeighbourhood, AnyVertexExpression) {
  G::context ctx;
  Star s = make_star(ctx, 3);
  vv::make_nb(s.ring[1], {s.ring[0], s.centre, s.ring[2]});
  // forall x in nextto ring0 in centre  (= ring1)
  std::vector<int> seen;
  for (V x : vv::each(vv::next_to(s.ring[0], s.centre))) seen.push_back(x->tag);
  EXPECT_EQ(seen, (std::vector<int>{1, 0, 3}));
}

TEST(ForallNeighbourhood, NullTargetIsAnError) {
  G::context ctx;
  V null;
  EXPECT_THROW(
      {
        for (V x : vv::each(null)) (void)x;
      },
      vv::error);
}

TEST(ForallNeighbourhood, BreakAndContinue) {
  G::context ctx;
  Star s = make_star(ctx, 7);
  std::vector<int> seen;
  for (V x : vv::each(s.centre)) {
    if (x->tag % 2 == 0) continue;
    if (x->tag == 5) break;
    seen.push_back(x->tag);
  }
  EXPECT_EQ(seen, (std::vector<int>{1, 3}));
}

TEST(ForallNeighbourhood, NestedLoops) {
  G::context ctx;
  Star s = make_star(ctx, 3);
  std::vector<std::pair<int, int>> pairs;
  for (V a : vv::each(s.centre))
    for (V b : vv::each(s.centre)) {
      pairs.emplace_back(a->tag, b->tag);
      vv::erase_from(b, s.centre);
    }
  // The inner loop of the first outer visit erases all; later inner loops
  // find an empty neighbourhood.
  EXPECT_EQ(pairs, (std::vector<std::pair<int, int>>{{1, 1}, {1, 2}, {1, 3}}));
}

TEST(ForallNeighbourhood, ErasedNeighboursSurviveGarbageCollectionDuringTheLoop) {
  G::context ctx;
  V centre = tagged(ctx, 0);
  Labels expected_labels;
  {
    std::vector<V> ring = make_vertices(ctx, 5, 101);
    vv::make_nb_from(centre, ring);
    expected_labels = labels_of(ring);
  }  // the ring is referenced by centre's neighbourhood only
  ASSERT_EQ(ctx.live_vertices(), 6u);

  Labels seen;
  std::vector<int> seen_tags;
  std::size_t freed_inside = 1;
  for (V x : vv::each(centre)) {
    if (seen.empty()) {
      // Now nothing but this loop refers to the other four neighbours.
      vv::make_nb(centre, {});
      for (int i = 0; i < 100000; ++i) {
        V tmp = ctx.new_vertex();
        tmp->tag = -7;
        tmp->c = 1e9;
      }
      freed_inside = ctx.collect_garbage();
    }
    seen.push_back(x.label());
    seen_tags.push_back(x->tag);
    EXPECT_EQ(vv::valence(x), 0u);
  }
  EXPECT_EQ(seen, expected_labels);
  EXPECT_EQ(seen_tags, (std::vector<int>{101, 102, 103, 104, 105}));
  EXPECT_EQ(freed_inside, 0u);
  // Once the loop is over, the ring and the temporaries are garbage.
  EXPECT_EQ(ctx.collect_garbage(), 100005u);
  EXPECT_EQ(ctx.live_vertices(), 1u);
  // New vertices get fresh labels.
  V next = ctx.new_vertex();
  EXPECT_EQ(next.label(), expected_labels.back() + 100001u);
}

TEST(ForallNeighbourhood, NeighbourhoodLoopInsideMeshLoopWithEdits) {
  // A typical subdivision pattern: for each vertex, for each neighbour,
  // insert a new vertex on the edge (edits both neighbourhoods).
  G::context ctx;
  Mesh M(ctx);
  std::vector<V> tri = make_vertices(ctx, 3);
  vv::make_nb(tri[0], {tri[1], tri[2]});
  vv::make_nb(tri[1], {tri[2], tri[0]});
  vv::make_nb(tri[2], {tri[0], tri[1]});
  for (const V& v : tri) M.add(v);
  int inserted = 0;
  for (V v : vv::each(M))
    for (V u : vv::each(v)) {
      if (u->tag >= 10 || u < v) continue;  // each original edge once
      V x = tagged(ctx, 10 + inserted++);
      vv::make_nb(x, {v, u});
      vv::replace_in(u, x, v);
      vv::replace_in(v, x, u);
      M.add(x);
    }
  EXPECT_EQ(inserted, 3);
  EXPECT_EQ(M.size(), 6u);
  for (const V& v : tri) {
    EXPECT_EQ(vv::valence(v), 2u);
    for (V x : vv::each(v)) EXPECT_GE(x->tag, 10);
  }
  EXPECT_NO_THROW(vv::check_invariants(M, {true, false}));
}

}  // namespace
