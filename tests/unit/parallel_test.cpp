// Parallel loops (vv/parallel.hpp, LANGUAGE.md section 6.1): the same bytes
// on one thread and on several, reference counts kept right when handles
// are copied on several threads at once, the rules of the body checked in
// every build with the lines they were broken on, strict mode's check of
// writes to other vertices, and a parallel synchronise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include <util/point.hpp>
#include <vv/vv.hpp>

namespace {

using Pt = util::Point<double>;

struct vertex_props;
struct edge_props {
  int mark;
};
using graph = vv::graph<vertex_props, edge_props>;
using vertex = graph::vertex;
struct vertex_props {
  Pt pos;
  double value;
  vertex partner;  // a handle in the properties: counted
};

// A torus of n x n quads: each vertex's neighbours counter-clockwise
// (right, up, left, down).
struct torus {
  graph::context ctx;
  graph::mesh S{ctx};
  std::vector<vertex> at;
  explicit torus(int n) {
    for (int i = 0; i < n * n; ++i) {
      vertex v = ctx.new_vertex();
      v->pos = Pt(i % n, i / n, ((i * 7919) % 101) / 100.0);
      S.add(v);
      at.push_back(v);
    }
    auto id = [n](int x, int y) { return ((y + n) % n) * n + (x + n) % n; };
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        vv::make_nb(at[id(x, y)], {at[id(x + 1, y)], at[id(x, y + 1)], at[id(x - 1, y)], at[id(x, y - 1)]});
  }
  // One smoothing step: each vertex to the mean of its old neighbours and
  // itself, with a non-associative sum (the order must not change).
  void smooth() {
    vv::synchronise(S);
    vv::parallel_for_each(S, [](vertex v) {
      Pt sum = vv::old(v)->pos;
      for (vertex n : vv::each(vv::old(v))) sum += vv::old(n)->pos * 0.3;
      v->pos = sum / 2.2;
      v->value = sum.x() * sum.y() - sum.z();
    });
  }
  std::vector<unsigned char> bytes() const {
    std::vector<unsigned char> out;
    for (const vertex& v : at) {
      const auto* p = reinterpret_cast<const unsigned char*>(&v->pos);
      out.insert(out.end(), p, p + sizeof(Pt));
      const auto* q = reinterpret_cast<const unsigned char*>(&v->value);
      out.insert(out.end(), q, q + sizeof(double));
    }
    return out;
  }
};

// The message of the error fn throws (empty: none).
template <class Fn>
std::string error_of(Fn&& fn) {
  try {
    fn();
  } catch (const vv::error& e) {
    return e.what();
  }
  return "";
}

std::string here(int line) { return std::string(__FILE__) + ":" + std::to_string(line) + ": "; }

TEST(ParallelLoop, RunsOnSeveralThreadsWhenTheMeshIsLarge) {
  torus t(64);
  t.ctx.threads = 2;
  EXPECT_EQ(vv::parallel_threads(t.S), 2u);
  t.ctx.threads = 1;
  EXPECT_EQ(vv::parallel_threads(t.S), 1u);
  torus small(4);  // 16 vertices: not worth a second thread
  small.ctx.threads = 2;
  EXPECT_EQ(vv::parallel_threads(small.S), 1u);
}

TEST(ParallelLoop, GivesTheSameBytesOnOneAndOnSeveralThreads) {
  std::vector<std::vector<unsigned char>> results;
  for (unsigned threads : {1u, 2u, 3u}) {
    torus t(120);
    t.ctx.threads = threads;
    for (int i = 0; i < 5; ++i) t.smooth();
    results.push_back(t.bytes());
  }
  EXPECT_EQ(results[0], results[1]);
  EXPECT_EQ(results[0], results[2]);
  // And the same as a loop in order.
  torus plain(120);
  for (int i = 0; i < 5; ++i) {
    vv::synchronise(plain.S);
    for (vertex v : vv::each(plain.S)) {
      Pt sum = vv::old(v)->pos;
      for (vertex n : vv::each(vv::old(v))) sum += vv::old(n)->pos * 0.3;
      v->pos = sum / 2.2;
      v->value = sum.x() * sum.y() - sum.z();
    }
  }
  EXPECT_EQ(results[0], plain.bytes());
}

// Every handle made on a loop's threads is counted: handles stored into
// the loop's vertices count, those of the body's locals are gone.
TEST(ParallelLoop, KeepsReferenceCountsRightWhenHandlesAreCopiedOnSeveralThreads) {
  torus t(100);
  t.ctx.threads = 2;
  ASSERT_EQ(vv::parallel_threads(t.S), 2u);
  vertex hub = t.at[0];  // copied by every iteration: on both threads at once
  vv::parallel_for_each(t.S, [&](vertex v) {
    std::vector<vertex> copies;
    for (int k = 0; k < 3; ++k)
      for (vertex n : vv::each(v)) copies.push_back(n);
    for (int k = 0; k < 50; ++k) copies.push_back(hub), copies.pop_back();
    v->partner = vv::any_in(v);  // the right-hand neighbour
  });
  // Each vertex: one count for the mesh, one for the table `at`, one for
  // the left-hand neighbour whose partner it is.
  for (const vertex& v : t.at) ASSERT_EQ(t.ctx.refs(v.slot()), v == hub ? 4u : 3u) << vv::name_of(v);
  // Dropping the partners takes their counts back; dropping the rest
  // leaves the vertices to the collector.
  vv::parallel_for_each(t.S, [](vertex v) { v->partner = vertex(); });
  for (const vertex& v : t.at) ASSERT_EQ(t.ctx.refs(v.slot()), v == hub ? 3u : 2u);
  t.S.clear();
  t.at.clear();
  hub = vertex();
  EXPECT_EQ(t.ctx.collect_garbage(), 10000u);
  EXPECT_EQ(t.ctx.live_vertices(), 0u);
}

// Each iteration's vertex is handed to the body uncounted (the mesh keeps
// it alive); what the body keeps of it, or puts in its place, is counted.
TEST(ParallelLoop, TheLoopsVertexKeptOrReplacedByTheBodyIsCounted) {
  torus t(100);
  t.ctx.threads = 2;
  ASSERT_EQ(vv::parallel_threads(t.S), 2u);
  vertex hub = t.at[0];
  vv::parallel_for_each(t.S, [&](vertex v) {
    v->partner = v;  // kept: counted
    vertex keep = v;
    v = hub;  // replaced: hub counted while the body holds it
    keep->value = v == hub ? 1 : 0;
  });
  // Each vertex: the mesh, the table `at`, its own partner; hub: `hub` too.
  for (const vertex& v : t.at) {
    ASSERT_EQ(t.ctx.refs(v.slot()), v == hub ? 4u : 3u) << vv::name_of(v);
    ASSERT_EQ(v->partner, v);
    ASSERT_EQ(v->value, 1.0);
  }
  vv::parallel_for_each(t.S, [](const vertex& v) { v->partner = vertex(); });
  for (const vertex& v : t.at) ASSERT_EQ(t.ctx.refs(v.slot()), v == hub ? 3u : 2u);
  t.S.clear();
  t.at.clear();
  hub = vertex();
  EXPECT_EQ(t.ctx.collect_garbage(), 10000u);
}

TEST(ParallelLoop, RefusesAnEditNamingItsLineAndTheLoops) {
  torus t(40);
  t.ctx.threads = 2;
  const int loop = __LINE__ + 2;
  std::string e = error_of([&] {
    vv::parallel_for_each(t.S, [](vertex v) {
      if (v.label() == 1000) vv::erase_from(vv::any_in(v), v);
    });
  });
  EXPECT_EQ(e, here(loop + 1) + "erase: inside the parallel forall of line " + std::to_string(loop) +
                   ", which must not edit a neighbourhood (its iterations run at once)");
}

TEST(ParallelLoop, RefusesFlagsCreationMeshChangesRandomNumbersAndSymmetricRecords) {
  torus t(8);
  graph::mesh other(t.ctx);
  const int line = __LINE__ + 2;
  auto refusal = [&](auto body) { return error_of([&] { vv::parallel_for_each(t.S, body, vv::where{"model.vvp", 7}); }); };
  EXPECT_EQ(refusal([](vertex v) { vv::flag_in(vv::any_in(v), v, vv::where{"model.vvp", 9}); }),
            "model.vvp:9: flag: inside the parallel forall of line 7, which must not edit a neighbourhood (its iterations run at once)");
  EXPECT_EQ(refusal([&](vertex) { t.ctx.new_vertex(vv::where{"model.vvp", 9}); }),
            "model.vvp:9: vertex: inside the parallel forall of line 7, which must not create a vertex (its iterations run at once)");
  EXPECT_EQ(refusal([&](vertex v) { other.add(v, vv::where{"model.vvp", 9}); }),
            "model.vvp:9: add: inside the parallel forall of line 7, which must not change a mesh (its iterations run at once)");
  for (const char* op : {"remove", "clear", "synchronise"}) {
    std::string e = refusal([&](vertex v) {
      const vv::where w{"model.vvp", 9};
      if (std::string(op) == "remove") t.S.remove(v, w);
      else if (std::string(op) == "clear") other.clear(w);
      else vv::synchronise(other, w);
    });
    EXPECT_EQ(e, std::string("model.vvp:9: ") + op +
                     ": inside the parallel forall of line 7, which must not change a mesh (its iterations run at once)");
  }
  EXPECT_EQ(refusal([&](vertex) { t.ctx.random(vv::where{"model.vvp", 9})(); }),
            "model.vvp:9: random: inside the parallel forall of line 7, which must not draw random numbers (its iterations run at once)");
  EXPECT_EQ(refusal([&](vertex v) { vv::sym_edge(v, vv::any_in(v), vv::where{"model.vvp", 9}).mark = 1; }),
            "model.vvp:9: |: inside the parallel forall of line 7, which must not write the record of another vertex's half-edge (its iterations run at once)");
  (void)line;
  // Nothing was changed, and the context works as before the loops.
  EXPECT_EQ(t.S.size(), 64u);
  EXPECT_EQ(other.size(), 0u);
  vertex x = t.ctx.new_vertex();
  other.add(x);
  vv::erase_from(vv::any_in(t.at[0]), t.at[0]);
  EXPECT_EQ(vv::valence(t.at[0]), 3u);
}

TEST(ParallelLoop, ReportsTheFirstFailingIterationInTheMeshsOrder) {
  for (unsigned threads : {1u, 2u}) {
    torus t(100);
    t.ctx.threads = threads;
    std::string e = error_of([&] {
      vv::parallel_for_each(t.S, [](vertex v) {
        if (v.label() % 997 == 0) throw vv::error(vv::where{"model.vvp", 3}, "test", "failed at " + vv::name_of(v));
      });
    });
    EXPECT_EQ(e, "model.vvp:3: test: failed at vertex 997") << threads << " threads";
    // The counts were merged: the handles of the loop are all gone.
    for (const vertex& v : t.at) ASSERT_EQ(t.ctx.refs(v.slot()), 2u);
  }
}

TEST(ParallelLoop, InsideAnotherRunsInOrder) {
  torus t(40);
  t.ctx.threads = 2;
  graph::mesh few(t.ctx);
  for (int i = 0; i < 5; ++i) few.add(t.at[static_cast<std::size_t>(i * 3)]);
  vv::parallel_for_each(t.S, [&](vertex v) {
    std::vector<unsigned> order;
    vv::parallel_for_each(few, [&](vertex w) { order.push_back(w.label()); });
    v->value = order == std::vector<unsigned>{1, 4, 7, 10, 13} ? 1 : 0;
  });
  for (const vertex& v : t.at) ASSERT_EQ(v->value, 1.0);
}

TEST(ParallelLoop, LetsTheBodyIterateMeshesWithHoles) {
  torus t(60);
  t.ctx.threads = 2;
  graph::mesh some(t.ctx);
  for (const vertex& v : t.at) some.add(v);
  for (std::size_t i = 0; i < t.at.size(); i += 2) some.remove(t.at[i]);  // holes, not yet squeezed out
  vv::parallel_for_each(t.S, [&](vertex v) {
    double count = 0;
    for (vertex w : vv::each(some)) count += w == v ? 1000 : 1;
    v->value = count;
  });
  for (std::size_t i = 0; i < t.at.size(); ++i) ASSERT_EQ(t.at[i]->value, i % 2 ? 2799.0 : 1800.0);
  // The mesh still works: removing more squeezes the holes out.
  for (std::size_t i = 1; i < t.at.size(); i += 4) some.remove(t.at[i]);
  std::size_t n = 0;
  for (vertex w : vv::each(some)) n += w ? 1 : 0;
  EXPECT_EQ(n, 900u);
}

TEST(ParallelLoop, InStrictModeCatchesAWriteToAnotherVertexAtItsFirstUse) {
  torus t(40);
  t.ctx.strict_parallel = true;
  const int loop = __LINE__ + 2;
  std::string e = error_of([&] {
    vv::parallel_for_each(t.S, [](vertex v) {
      vertex right = vv::any_in(v);
      double seen = right.props().value;  // the first use: a read
      if (v.label() == 5) right->value = seen + 1;
    });
  });
  EXPECT_EQ(e, here(loop + 2) + "parallel forall: vertex 6 was changed by the iteration of vertex 5 of the parallel forall of line " +
                   std::to_string(loop) + ", which may change only the properties of its own vertex (strict mode; first used here)");
  // A record of another vertex's half-edge is checked too.
  const int loop2 = __LINE__ + 2;
  e = error_of([&] {
    vv::parallel_for_each(t.S, [](vertex v) {
      vertex right = vv::any_in(v);
      if (v.label() == 7) vv::edge(right, v).mark = 2;
    });
  });
  EXPECT_EQ(e, here(loop2 + 2) + "parallel forall: vertex 8 was changed by the iteration of vertex 7 of the parallel forall of line " +
                   std::to_string(loop2) + ", which may change only the properties of its own vertex (strict mode; first used here)");
}

TEST(ParallelLoop, InStrictModeLetsTheBodyReadOthersAndWriteItsOwnVertex) {
  torus t(40);
  t.ctx.strict_parallel = true;
  vv::synchronise(t.S);
  vv::parallel_for_each(t.S, [](vertex v) {
    double sum = 0;
    for (vertex n : vv::each(v)) sum += n->pos.x() + vv::old(n)->pos.y() + vv::edge(n, v).mark;
    v->value = sum;
    vv::edge(v, vv::any_in(v)).mark = 1;
  });
  EXPECT_EQ(t.at[0]->value, 1 + 39 + 0 + 0 + 39 + 0 + 0 + 1);
}

TEST(ParallelSynchronise, CopiesALargeMeshAsInOrderAndKeepsCountsRight) {
  std::vector<std::vector<unsigned char>> olds;
  for (unsigned threads : {1u, 2u}) {
    torus t(100);
    t.ctx.threads = threads;
    for (std::size_t i = 0; i < t.at.size(); ++i) t.at[i]->partner = t.at[(i * 31) % t.at.size()];
    vv::synchronise(t.S);
    vv::synchronise(t.S);  // over an old state: the old partners released
    std::vector<unsigned char> bytes;
    for (const vertex& v : t.at) {
      const auto o = vv::old(v);
      bytes.push_back(static_cast<unsigned char>(vv::valence(o)));
      for (vertex n : vv::each(o)) bytes.push_back(static_cast<unsigned char>(n.label() & 0xff));
      const auto* p = reinterpret_cast<const unsigned char*>(&o->pos);
      bytes.insert(bytes.end(), p, p + sizeof(Pt));
      bytes.push_back(static_cast<unsigned char>(o->partner.label() & 0xff));
    }
    olds.push_back(bytes);
    // mesh + table + current partner + old partner
    for (const vertex& v : t.at) ASSERT_EQ(t.ctx.refs(v.slot()), 4u);
  }
  EXPECT_EQ(olds[0], olds[1]);
}

// A model without parallel loops (as vvc makes a program without `parallel
// forall`): its handle copies count without the test for parallel loops,
// so a loop that copies handles runs in order, with the same result and
// right counts; a synchronise of plain data, which copies no handle, is
// still shared out.
struct sequential_props {
  Pt pos;
};
struct sequential_traits : vv::traits<sequential_props> {
  static constexpr bool parallel_loops = false;
};

TEST(ParallelLoop, RunsInOrderInAModelWithoutParallelLoops) {
  vv::context<sequential_traits> ctx;
  ctx.threads = 2;
  vv::mesh<sequential_traits> S(ctx);
  std::vector<vv::vertex<sequential_traits>> at;
  const int n = 4096;
  for (int i = 0; i < n; ++i) {
    vv::vertex<sequential_traits> v = ctx.new_vertex();
    v->pos = Pt(i, 0, 0);
    S.add(v);
    at.push_back(v);
  }
  for (int i = 0; i < n; ++i) vv::make_nb(at[i], {at[(i + 1) % n], at[(i + n - 1) % n]});
  EXPECT_EQ(vv::parallel_threads(S), 1u);
  vv::synchronise(S);  // shared out: plain data
  std::vector<double> order;
  vv::parallel_for_each(S, [&](vv::vertex<sequential_traits> v) {
    double sum = 0;
    for (vv::vertex<sequential_traits> u : vv::each(vv::old(v))) sum += vv::old(u)->pos.x();
    v->pos = Pt(sum / 2, 0, 0);
    order.push_back(vv::old(v)->pos.x());  // in order: no other thread appends
  });
  ASSERT_EQ(order.size(), std::size_t(n));
  for (int i = 0; i < n; ++i) ASSERT_EQ(order[i], double(i));
  EXPECT_EQ(at[0]->pos.x(), (1 + n - 1) / 2.0);
  EXPECT_EQ(at[5]->pos.x(), 5.0);
  for (const auto& v : at) ASSERT_EQ(ctx.refs(v.slot()), 2u);  // mesh + table
}

TEST(ParallelSynchronise, SharesOutPlainPropertiesEvenWithoutParallelLoops) {
  // Plain data: the synchronise copies no handle, so it needs no counting
  // apart; its old state is the same as in order.
  for (unsigned threads : {1u, 2u}) {
    vv::context<sequential_traits> ctx;
    ctx.threads = threads;
    vv::mesh<sequential_traits> S(ctx);
    std::vector<vv::vertex<sequential_traits>> at;
    for (int i = 0; i < 20000; ++i) {
      at.push_back(ctx.new_vertex());
      at.back()->pos = Pt(i, 2 * i, 3 * i);
      S.add(at.back());
    }
    for (int i = 0; i + 1 < 20000; i += 2) vv::make_nb(at[i], {at[i + 1]});
    vv::synchronise(S);
    for (int i = 0; i < 20000; ++i) {
      ASSERT_EQ(vv::old(at[i])->pos, Pt(i, 2 * i, 3 * i));
      ASSERT_EQ(vv::valence(vv::old(at[i])), i % 2 ? 0u : 1u);
    }
  }
}

}  // namespace
