// A context saved and restored slot for slot (model/state.hpp): every live
// vertex keeps its slot and its label, its neighbourhood with its flag and
// half-edge records, its properties, and its old state; the free slots
// keep their order and the counters their values (the next slot and label,
// the collector's suspects and threshold), and the random generator its
// state. A restored model therefore makes the same vertices, with the same
// labels, in the same slots, and collects garbage at the same points, as
// the model that was saved.
//
// A saved vertex's reference count is not written back: the handles the
// restore makes (in meshes, globals, properties) count again. The save
// counts the handles it writes and refuses a vertex held by something it
// did not see, so the counts that come back are the counts that were.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <vv/context.hpp>

#include "state_parts.hpp"
#include "state_stream.hpp"
#include "state_values.hpp"

namespace vv::model {

template <class Tr>
struct context_state {
  using C = context<Tr>;
  using nb_type = typename C::nb_type;
  using entry = typename C::entry;
  using entry_traits = typename C::entry_traits;
  using edge_props = typename C::edge_props;
  static constexpr bool has_records = !std::is_empty_v<edge_props>;

  //! The pool, slots and counters. `a.handles` must have a count per slot.
  static void save(state_saving<Tr>& a) {
    C& c = a.ctx;
    state_writer& w = a.out;
    w.u32(c.next_slot_);
    w.u32(c.next_label_);
    w.u64(c.gc_threshold_);
    w.u64(c.free_slots_.size());
    for (std::uint32_t id : c.free_slots_) w.u32(id);
    save_engine(w, c.rng_);
    save_texts(w, c.warned_);
    w.u64(c.chunks_.size());
    for (const auto& chunk : c.chunks_) w.u8(chunk->old ? 1 : 0);
    // The slots first, then what each holds: a restore knows every live
    // slot before it reads a handle to one.
    std::vector<std::uint32_t> live;
    for (std::uint32_t id = 1; id < c.next_slot_; ++id)
      if (c.labels_[id]) live.push_back(id);
    w.u64(live.size());
    for (std::uint32_t id : live) w.u32(id), w.u32(c.labels_[id]);
    for (std::uint32_t id : live) {
      save_nb(a, c.nb(id));
      state_value(a, c.props(id));
      if (c.at(id).old) {
        save_nb(a, c.at(id).old->nb[id & C::mask]);
        state_value(a, c.at(id).old->props[id & C::mask]);
      }
    }
  }

  //! After the rest of the model is saved: every vertex's count is the
  //! handles the save wrote (and `extra`, held by the host's exchange);
  //! else the error names a vertex held by something the save did not see.
  static void check_counts(const C& c, const std::vector<std::uint32_t>& handles,
                           const std::vector<std::uint32_t>& extra) {
    for (std::uint32_t id = 1; id < c.next_slot_; ++id) {
      if (!c.labels_[id]) continue;
      std::uint32_t seen = handles[id] + (id < extra.size() ? extra[id] : 0);
      if (seen != c.refs_[id])
        throw state_error("vertex " + std::to_string(c.labels_[id]) + " is held " + std::to_string(c.refs_[id]) +
                          " times, but the checkpoint saves " + std::to_string(seen) +
                          " of them: something the translator does not list as a global holds it");
    }
  }

  //! The counters a restore sets last (the handles it made changed them).
  struct counters {
    std::uint64_t live = 0, suspects = 0;
  };
  static void save_counters(const C& c, state_writer& w) {
    w.u64(c.live_);
    w.u64(c.suspects_);
  }

  //! Into a fresh context (no vertex made yet).
  static void load(state_loading<Tr>& a) {
    C& c = a.ctx;
    state_reader& r = a.in;
    if (c.next_slot_ != 1 || c.live_ != 0)
      throw state_error("the model made vertices before the checkpoint was read (in the initialiser of a global)");
    const std::uint32_t next_slot = r.u32("the slot count");
    const std::uint32_t next_label = r.u32("the label count");
    if (next_slot == 0) throw state_error("a slot count of 0");
    c.gc_threshold_ = static_cast<std::size_t>(r.u64("the collector's threshold"));
    std::vector<std::uint32_t> free_slots(static_cast<std::size_t>(r.count("the free slots", 4)));
    for (std::uint32_t& id : free_slots) id = slot_below(r.u32("a free slot"), next_slot);
    restore_engine(r, c.rng_);
    restore_texts(r, c.warned_);
    const std::uint64_t chunks = r.count("the chunks");
    if (chunks != ((next_slot - 1) >> C::chunk_bits) + 1) throw state_error("a chunk count that does not fit the slots");
    while (c.chunks_.size() < chunks) c.add_chunk();
    for (std::uint64_t i = 0; i < chunks; ++i)
      if (r.u8("a chunk's old state")) c.old_block_of(static_cast<std::uint32_t>(i << C::chunk_bits));
    c.next_slot_ = next_slot;
    c.next_label_ = next_label;
    c.free_slots_ = std::move(free_slots);
    std::vector<std::uint32_t> live(static_cast<std::size_t>(r.count("the vertices", 8)));
    std::uint32_t previous = 0;
    for (std::uint32_t& id : live) {
      id = slot_below(r.u32("a vertex's slot"), next_slot);
      if (id <= previous) throw state_error("vertex slots out of order");
      previous = id;
      const std::uint32_t label = r.u32("a vertex's label");
      if (label == 0 || label >= next_label) throw state_error("a vertex label that cannot be");
      c.labels_[id] = label;
    }
    for (std::uint32_t id : c.free_slots_)
      if (c.labels_[id]) throw state_error("a slot both free and holding a vertex");
    for (std::uint32_t id : live) {
      if (!c.labels_[id]) continue;
      load_nb(a, c.nb(id));
      state_value(a, c.props(id));
      if (c.at(id).old) {
        load_nb(a, c.at(id).old->nb[id & C::mask]);
        state_value(a, c.at(id).old->props[id & C::mask]);
      }
    }
  }

  static counters load_counters(state_reader& r) {
    counters k;
    k.live = r.u64("the live vertices");
    k.suspects = r.u64("the collector's suspects");
    return k;
  }
  //! Once every handle is back: the counters as they were.
  static void finish(C& c, const counters& k) {
    std::size_t live = 0;
    for (std::uint32_t id = 1; id < c.next_slot_; ++id) live += c.labels_[id] != 0;
    if (live != k.live) throw state_error("a live vertex count that does not match its vertices");
    c.live_ = live;
    c.suspects_ = static_cast<std::size_t>(k.suspects);
    // The restored vertices were not made by the block that restores them:
    // its end must not count them as suspects (context::block_scope), or
    // the resumed run would collect at other times than the saved one.
    if (c.uncounted_size_) c.first_block_slot_ = c.next_slot_;
    c.reused_in_block_.clear();
  }

 private:
  static std::uint32_t slot_below(std::uint32_t id, std::uint32_t next_slot) {
    if (id == 0 || id >= next_slot) throw state_error("a slot out of range");
    return id;
  }

  static void save_nb(state_saving<Tr>& a, nb_type& n) {
    a.out.u32(n.size());
    a.out.u32(static_cast<std::uint32_t>(n.flag()));
    for (entry& e : n) {
      a.out.u32(entry_traits::id(e));
      if constexpr (has_records) state_value(a, entry_traits::rec(e, a.ctx.empty_record()));
    }
  }

  static void load_nb(state_loading<Tr>& a, nb_type& n) {
    state_reader& r = a.in;
    const std::uint32_t size = r.u32("a neighbourhood's size");
    if (size > r.left() / 4) throw state_error("a neighbourhood larger than the state");
    const auto flag = static_cast<std::int32_t>(r.u32("a neighbourhood's flag"));
    if (flag < nb_type::never_synchronised || flag >= static_cast<std::int32_t>(size) ||
        (flag == nb_type::never_synchronised && size != 0))
      throw state_error("a neighbourhood's flag out of range");
    std::vector<entry> entries;
    entries.reserve(size);
    for (std::uint32_t i = 0; i < size; ++i) {
      const std::uint32_t id = r.u32("a neighbour");
      if (!a.ctx.is_live(id)) throw state_error("a neighbour of slot " + std::to_string(id) + ", which holds none");
      entries.push_back(entry_traits::make(id));
      if constexpr (has_records) state_value(a, entry_traits::rec(entries.back(), a.ctx.empty_record()));
    }
    n.assign(entries.data(), size);
    n.set_flag(flag);
  }
};

}  // namespace vv::model
