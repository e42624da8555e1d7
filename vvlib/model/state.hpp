// A model's whole state as bytes, and back (vv_plugin::save_state and
// restore_state, model/abi.hpp): what a checkpoint holds. The translator
// lists every global of the program (its name, type, line); this saves
// each one that can change, with the context (model/state_context.hpp),
// the proxy's settings and plots, and the random generators (the model's
// and the C library's: model/c_random.hpp). A restored model goes on as
// the saved one would have: the same vertices in the same order with the
// same labels, the same random numbers.
//
// Layout (all numbers little-endian, docs/interpreter.md "Checkpoints"):
//   "vv-state" u32 version
//   then six sections, each a u64 length and its bytes:
//   context, globals (u64 count; each: name, u64 length, value),
//   proxy, exchange (the neighbourhood check's memory), C random, counters.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include <vv/context.hpp>
#include <vv/mesh.hpp>

#include "abi.hpp"
#include "c_random.hpp"
#include "file_object.hpp"
#include "program.hpp"
#include "state_context.hpp"
#include "state_parts.hpp"
#include "state_stream.hpp"
#include "state_values.hpp"

namespace vv::model {

inline constexpr std::uint32_t state_version = 1;

//! One global of the program: what the host is told (vv_global_entry) and
//! how its value is saved and restored.
template <class Tr>
struct global_slot {
  vv_global_entry entry{};
  std::string type, why;  // entry.type and entry.why point into these
  void* object = nullptr;
  const file_object* as_file = nullptr;  // the object, when it is a file object
  void (*save)(void*, state_saving<Tr>&) = nullptr;
  void (*load)(void*, state_loading<Tr>&) = nullptr;
};

//! The slot of a global `T name;` declared at `line` (T is decltype(name)).
template <class Tr, class T>
global_slot<Tr> global_of(const char* name, const char* type, int line, T& object) {
  using U = std::remove_reference_t<T>;
  global_slot<Tr> g;
  g.entry.name = name;
  g.entry.line = line;
  g.type = type;
  if constexpr (std::is_function_v<U>) {
    g.entry.kept = VV_GLOBAL_CONSTANT;  // a function, not a variable
    (void)object;
  } else if constexpr (std::is_reference_v<T> || std::is_const_v<U>) {
    g.entry.kept = VV_GLOBAL_CONSTANT;  // a constant, or a reference (always to the same object)
  } else {
    if constexpr (std::is_base_of_v<file_object, U>) g.as_file = &object;
    g.why = why_unsaveable(object);
    // The declared type is named beside the global already.
    const std::string own = state_detail::type_name<U>() + ": ";
    if (g.why.compare(0, own.size(), own) == 0) g.why.erase(0, own.size());
    g.entry.kept = g.why.empty() ? VV_GLOBAL_SAVED : VV_GLOBAL_UNSAVEABLE;
    g.object = const_cast<void*>(static_cast<const volatile void*>(&object));  // volatile globals too
    g.save = [](void* o, state_saving<Tr>& a) { state_value(a, *static_cast<U*>(o)); };
    g.load = [](void* o, state_loading<Tr>& a) { state_value(a, *static_cast<U*>(o)); };
  }
  return g;
}

//! A `static` variable inside a function: state the host cannot reach.
template <class Tr>
global_slot<Tr> static_in_function(const char* name, const char* type, int line) {
  global_slot<Tr> g;
  g.entry.name = name;
  g.entry.line = line;
  g.type = type;
  g.entry.kept = VV_GLOBAL_UNSAVEABLE;
  g.why = "a static variable inside a function, which the host cannot reach (make it a global)";
  return g;
}

//! Points the host's table at the slots' texts (once the slots are in place).
template <class Tr>
bool list_globals(global_slot<Tr>* slots, vv_global_entry* table, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    global_slot<Tr>& g = slots[i];
    g.entry.type = g.type.c_str();
    g.entry.why = g.why.empty() ? nullptr : g.why.c_str();
    table[i] = g.entry;
  }
  return true;
}

namespace state_detail {

//! The slots as a range.
template <class Tr>
struct slot_range {
  global_slot<Tr>* first;
  std::size_t n;
  global_slot<Tr>* begin() const { return first; }
  global_slot<Tr>* end() const { return first + n; }
};
template <class Tr>
slot_range<Tr> all(global_slot<Tr>* first, std::size_t n) {
  return {first, n};
}

// A section: its length, then its bytes.
template <class Write>
void section(state_writer& w, Write write) {
  std::size_t at = w.reserve_u64();
  write();
  w.fill_u64(at, w.size() - at - 8);
}

template <class Read>
void read_section(state_reader& r, const char* name, Read read) {
  std::uint64_t n = r.u64(name);
  state_reader part = r.part(n, name);
  read(part);
  if (part.left()) throw state_error(std::string("the section ") + name + " holds more than the program reads");
}

//! Why the property blocks' fields cannot be saved ("" when they can).
template <class Tr>
std::string props_problem() {
  struct block {
    const char* name;
    std::string problem;
  };
  typename Tr::vertex_props v{};
  typename Tr::edge_props e{};
  typename Tr::mesh_props m{};
  for (const block& b : {block{"vertex", why_unsaveable(v)}, block{"edge", why_unsaveable(e)},
                         block{"mesh", why_unsaveable(m)}})
    if (!b.problem.empty()) return std::string("the ") + b.name + " block's " + b.problem;
  return "";
}

//! The globals that are file objects, by their index (null elsewhere).
template <class Tr>
std::vector<const file_object*> file_globals(const global_slot<Tr>* globals, std::size_t n) {
  std::vector<const file_object*> files(n, nullptr);
  for (std::size_t i = 0; i < n; ++i) files[i] = globals[i].as_file;
  return files;
}

}  // namespace state_detail

//! The model's whole state (the layout above); throws what cannot be saved.
template <class Tr>
std::string save_state(program<Tr>& p, global_slot<Tr>* globals, std::size_t N) {
  using namespace state_detail;
  for (const global_slot<Tr>& g : all(globals, N))
    if (g.entry.kept == VV_GLOBAL_UNSAVEABLE)
      throw state_error("the global " + std::string(g.entry.name) + " (line " + std::to_string(g.entry.line) + ", " +
                        g.type + ") cannot be saved: " + g.why);
  if (std::string why = props_problem<Tr>(); !why.empty()) throw state_error(why + " cannot be saved");
  context<Tr>& c = p.ctx();
  std::vector<std::uint32_t> handles(c.slot_count(), 0);
  state_writer w;
  state_saving<Tr> a{w, c, handles};
  w.text("vv-state");
  w.u32(state_version);
  section(w, [&] { context_state<Tr>::save(a); });
  section(w, [&] {
    std::uint64_t saved = 0;
    for (const global_slot<Tr>& g : all(globals, N)) saved += g.entry.kept == VV_GLOBAL_SAVED;
    w.u64(saved);
    for (global_slot<Tr>& g : all(globals, N)) {
      if (g.entry.kept != VV_GLOBAL_SAVED) continue;
      w.text(g.entry.name);
      section(w, [&] { g.save(g.object, a); });
    }
  });
  section(w, [&] {
    const std::vector<const file_object*> files = file_globals(globals, N);
    save_proxy(w, p.host(), files.data(), N);
  });
  exchange& x = p.host_exchange();
  section(w, [&] {
    w.u64(x.was_symmetric.size());
    for (char s : x.was_symmetric) w.u8(static_cast<std::uint8_t>(s));
  });
  section(w, [&] { save_c_random(w); });
  section(w, [&] { context_state<Tr>::save_counters(c, w); });
  // The host's last union of meshes holds its members too.
  std::vector<std::uint32_t> extra(c.slot_count(), 0);
  if (x.union_mesh)
    for (std::uint32_t id : std::static_pointer_cast<mesh<Tr>>(x.union_mesh)->slots())
      if (id) ++extra[id];
  context_state<Tr>::check_counts(c, handles, extra);
  return std::move(w.bytes());
}

//! Restores a state save_state gave, into a model that has not started.
template <class Tr>
void restore_state(program<Tr>& p, global_slot<Tr>* globals, std::size_t N, const void* data, std::size_t size) {
  using namespace state_detail;
  context<Tr>& c = p.ctx();
  state_reader r(data, size);
  if (r.text("the state's header") != "vv-state") throw state_error("not a model's state");
  if (std::uint32_t v = r.u32("the state's version"); v != state_version)
    throw state_error("a state of version " + std::to_string(v) + "; this model reads version " +
                      std::to_string(state_version));
  read_section(r, "context", [&](state_reader& in) {
    state_loading<Tr> part{in, c};
    context_state<Tr>::load(part);
  });
  read_section(r, "globals", [&](state_reader& in) {
    std::uint64_t count = in.count("the globals", 9);
    std::size_t next = 0;
    for (std::uint64_t k = 0; k < count; ++k) {
      while (next < N && globals[next].entry.kept != VV_GLOBAL_SAVED) ++next;
      std::string name = in.text("a global's name");
      if (next == N || name != globals[next].entry.name)
        throw state_error("the state holds a global " + name + " where the program has " +
                          (next == N ? std::string("no more") : std::string(globals[next].entry.name)));
      global_slot<Tr>& g = globals[next++];
      read_section(in, g.entry.name, [&](state_reader& value) {
        state_loading<Tr> one{value, c};
        g.load(g.object, one);
      });
    }
    while (next < N && globals[next].entry.kept != VV_GLOBAL_SAVED) ++next;
    if (next != N) throw state_error(std::string("the state lacks the global ") + globals[next].entry.name);
  });
  read_section(r, "proxy", [&](state_reader& in) {
    const std::vector<const file_object*> files = file_globals(globals, N);
    restore_proxy(in, p.host(), files.data(), N);
  });
  read_section(r, "exchange", [&](state_reader& in) {
    exchange& x = p.host_exchange();
    x.was_symmetric.assign(static_cast<std::size_t>(in.count("the checked meshes")), 0);
    for (char& s : x.was_symmetric) s = static_cast<char>(in.u8("a checked mesh"));
  });
  read_section(r, "C random", [&](state_reader& in) { restore_c_random(in); });
  read_section(r, "counters", [&](state_reader& in) {
    context_state<Tr>::finish(c, context_state<Tr>::load_counters(in));
  });
  if (r.left()) throw state_error("the state goes on past its last section");
}

}  // namespace vv::model
