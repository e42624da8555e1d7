// A model's state saved and restored (vvlib/model/state.hpp) without a
// host or a translator: two model objects with the same globals, one built
// up, saved, and restored into the other. The restored model saves the
// same bytes (nothing was lost or added), makes its next vertex in the same
// slot with the same label, and draws the same random numbers; every
// prefix of a state is refused with an error, never read on; a vertex the
// save cannot account for, and a global it cannot hold, are named.
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <model/model.hpp>

namespace {

struct tr;
using vertex = vv::vertex<tr>;
using mesh = vv::mesh<tr>;

struct vertex_props {
  util::Point<double> pos;
  vertex partner;
  double heat = 0;
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos), f("heat", heat);
  }
  template <class F>
  void vv_state_fields(F&& f) {
    f("pos", pos, 1), f("partner", partner, 2), f("heat", heat, 3);
  }
};
struct edge_props {
  double weight = 0;
  template <class F>
  void vv_fields(F&& f) {
    f("weight", weight);
  }
};
struct tr : vv::traits<vertex_props, edge_props> {};

// One model: its object and its globals, with their slots.
struct model {
  vv::model::program<tr> p{""};
  mesh S{p.ctx()};
  std::vector<vertex> kept;
  std::map<int, vertex> named;
  int count = 0;
  vv::model::global_slot<tr> slots[4] = {
      vv::model::global_of<tr, decltype(S)>("S", "mesh", 1, S),
      vv::model::global_of<tr, decltype(kept)>("kept", "std::vector<vertex>", 2, kept),
      vv::model::global_of<tr, decltype(named)>("named", "std::map<int, vertex>", 3, named),
      vv::model::global_of<tr, decltype(count)>("count", "int", 4, count),
  };
  model() { p.globals_made(); }

  std::string save() { return vv::model::save_state(p, slots, 4); }
  void restore(const std::string& state) { vv::model::restore_state(p, slots, 4, state.data(), state.size()); }
};

// A ring of six with records, flags, properties, old state, vertices in
// globals and properties, a vertex dropped (a free slot after the
// collector) and random numbers drawn.
void build(model& m) {
  vv::context<tr>& c = m.p.ctx();
  c.seed(17);
  std::vector<vertex> ring;
  for (int i = 0; i < 6; ++i) {
    vertex v = c.new_vertex();
    v->pos = util::Point<double>(i, i * i, -i);
    v->heat = 0.5 * i;
    ring.push_back(v);
    m.S.add(v);
  }
  for (int i = 0; i < 6; ++i) {
    vertex v = ring[i], a = ring[(i + 1) % 6], b = ring[(i + 5) % 6];
    vv::make_nb(v, {a, b});
    vv::edge(v, a).weight = i + 0.25;
    vv::flag_in(a, v);
    v->partner = ring[(i + 2) % 6];
  }
  vv::synchronise(m.S);
  ring[3]->heat = 99;  // differs from its old state
  {
    vertex hidden = c.new_vertex();  // held by no count, reached through ring[0]
    vv::splice_after(hidden, ring[1], ring[0]);
  }
  {
    vertex dropped = c.new_vertex();  // no handle left: garbage
  }
  c.collect_garbage();
  m.kept = {ring[1], ring[4]};
  m.named[7] = ring[5];
  m.count = 42;
  for (int i = 0; i < 3; ++i) c.random()();
  std::srand(5);
  std::rand();
  srand48(9);
  drand48();
}

TEST(ModelState, ARestoredModelSavesTheSameBytesAndGoesOnAsTheSavedOne) {
  model a;
  build(a);
  const std::string state = a.save();
  model b;
  b.restore(state);
  EXPECT_EQ(b.save(), state);
  EXPECT_EQ(b.count, 42);
  ASSERT_EQ(b.kept.size(), 2u);
  EXPECT_EQ(b.kept[0].label(), a.kept[0].label());
  EXPECT_EQ(b.named.at(7).label(), a.named.at(7).label());
  EXPECT_EQ(b.S.size(), 6u);
  // What comes next is the same: the slot and label of a new vertex (the
  // dropped one's slot is free), the model's random numbers.
  vertex next_a = a.p.ctx().new_vertex(), next_b = b.p.ctx().new_vertex();
  EXPECT_EQ(next_b.slot(), next_a.slot());
  EXPECT_EQ(next_b.label(), next_a.label());
  EXPECT_EQ(b.p.ctx().random()(), a.p.ctx().random()());
}

// A host restores inside a block (model/program.hpp), whose end counts the
// vertices it made that no count holds as the collector's suspects: not
// those the restore made, or the resumed run would collect at other times.
TEST(ModelState, ARestoreInsideABlockLeavesTheCollectorAsSaved) {
  model a;
  build(a);
  const std::string state = a.save();
  model b;
  b.p.ctx();  // a block needs the context
  ASSERT_EQ(b.p.run([&] { b.restore(state); }), nullptr);
  EXPECT_EQ(b.save(), state);
}

TEST(ModelState, TheCLibrarysGeneratorsGoOnWhereTheStateWasSaved) {
  model a;
  build(a);
  const std::string state = a.save();
  const int next_rand = std::rand();
  const double next_drand48 = drand48();
  std::srand(1234);
  srand48(1234);
  model b;
  b.restore(state);
  EXPECT_EQ(std::rand(), next_rand);
  EXPECT_EQ(drand48(), next_drand48);
}

TEST(ModelState, EveryPrefixOfAStateIsRefusedAndNeverReadOn) {
  model a;
  build(a);
  const std::string state = a.save();
  for (std::size_t n = 0; n < state.size(); n += 3) {
    model b;
    try {
      b.restore(state.substr(0, n));
      ADD_FAILURE() << "a state cut to " << n << " of " << state.size() << " bytes was read";
    } catch (const vv::model::state_error&) {
    }
  }
}

TEST(ModelState, AVertexHeldByWhatTheSaveDoesNotSeeIsNamed) {
  model a;
  build(a);
  vertex hidden = a.kept[0];  // a handle no global holds
  try {
    a.save();
    ADD_FAILURE() << "saved";
  } catch (const vv::model::state_error& e) {
    EXPECT_EQ(std::string(e.what()), "vertex " + std::to_string(hidden.label()) +
                                         " is held 5 times, but the checkpoint saves 4 of them: something the "
                                         "translator does not list as a global holds it");
  }
}

TEST(ModelState, AGlobalThatCannotBeSavedIsNamedWithItsLineAndWhy) {
  vv::model::program<tr> p("");
  p.globals_made();
  int value = 0;
  int* pointer = &value;
  vv::model::global_slot<tr> slots[] = {vv::model::global_of<tr, decltype(pointer)>("pointer", "int*", 12, pointer)};
  EXPECT_EQ(slots[0].entry.kept, VV_GLOBAL_UNSAVEABLE);
  try {
    vv::model::save_state(p, slots, 1);
    ADD_FAILURE() << "saved";
  } catch (const vv::model::state_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "the global pointer (line 12, int*) cannot be saved: a pointer (what it points at cannot be saved)");
  }
}

}  // namespace
