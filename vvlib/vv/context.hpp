// The per-model state: pooled vertex storage, labels, the garbage
// collector and the random generator. (The host's proxy is the model
// layer's: model/program.hpp.)
//
// Storage. Vertices live in fixed-size chunks that never move, so a
// reference to a property stays valid while other vertices are created.
// Inside a chunk the parts of a vertex (current neighbourhood, current
// properties) are separate arrays that grow in lockstep: a scan touches
// only the array it needs. Reference counts and labels, which no reference
// outlives, are flat arrays over all slots (one load fewer per access).
// Creating a vertex reuses a freed slot or takes the next one; nothing is
// allocated per vertex.
//
// Old state. The synchronised neighbourhoods and properties of a chunk live
// in a block of their own, made when the first vertex of the chunk is
// synchronised. Vertices are created in order, so after a subdivision step
// the vertices it created (three quarters of a Loop mesh) fill chunks that
// no synchronise has reached and cost no old state; a vertex never
// synchronised reads as an empty neighbourhood and value-initialised
// properties (one shared instance).
//
// Lifetime. A vertex lives while anything refers to it. Handles (program
// variables) and mesh memberships are counted; neighbourhood entries are
// not, because every edge is a two-vertex cycle that counting alone could
// never free. Instead, a tracing pass from the counted vertices through
// current and old neighbourhoods frees the unreachable ones. It runs when
// enough counts have dropped to zero since the last pass (so its cost is
// amortised over that work), never inside a neighbourhood loop whose
// snapshot holds uncounted slots, and on demand (collect_garbage).
//
// Blocks (block_scope). While a translated program's block runs, the
// handles on its thread's stack below the block's frame hold no count (a
// fifth of a subdivision step's instructions went to counting its locals,
// parameters and temporaries), and the tracing pass waits for the block's
// end: then those handles are gone, and the counts are complete again.
// Handles anywhere else (globals, properties, containers, other threads)
// are counted as always. Vertices the block made that no count holds at
// its end are counted among the pass's suspects.
//
// Parallel loops (vv/parallel.hpp). While one runs, the context is in a
// parallel scope: the collector is paused, edits, vertex creation, mesh
// changes and random numbers are errors, and the loop's threads keep their
// reference count changes apart (detail/thread_counts.hpp), added to the
// counts when the loop ends. Outside a loop the only cost is one test of a
// byte per count change.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <mutex>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "detail/block_arena.hpp"
#include "detail/handle_blocks.hpp"
#include "detail/inline.hpp"
#include "detail/neighbourhood.hpp"
#include "detail/parallel_scope.hpp"
#include "detail/run_allocator.hpp"
#include "detail/thread_counts.hpp"
#include "error.hpp"
#include "traits.hpp"

namespace vv {

namespace model {
// Saves and restores a context slot for slot (model/state_context.hpp).
template <class Tr>
struct context_state;
}  // namespace model

template <class Tr>
class context {
  friend struct model::context_state<Tr>;

 public:
  using traits_type = Tr;
  using vertex_props = typename Tr::vertex_props;
  using edge_props = typename Tr::edge_props;
  using mesh_props = typename Tr::mesh_props;
  using entry_traits = detail::entry_traits<edge_props>;
  using entry = typename entry_traits::type;
  using nb_type = detail::neighbourhood<entry, Tr::inline_valence>;

  static constexpr std::uint32_t chunk_bits = 10;
  static constexpr std::uint32_t chunk_size = 1u << chunk_bits;

  context() { add_chunk(); }  // slot 0 is the null vertex and never used
  context(const context&) = delete;
  context& operator=(const context&) = delete;
  //! Handles and meshes must not outlive their context.
  ~context() {
    // From here on, vectors of handles give their storage back to the heap.
    handle_blocks_.close();
    // Properties may hold handles into this context: release them while the
    // storage is still whole.
    for (std::uint32_t id = 1; id < next_slot_; ++id) {
      props(id) = vertex_props();
      if (at(id).old) writable_old_props(id) = vertex_props();
    }
  }

  //! Create a vertex with value-initialised properties.
  vertex<Tr> new_vertex(where w = where::here()) { return vertex<Tr>::from_slot(this, allocate_slot(w)); }
  //! Create a vertex with the given properties.
  vertex<Tr> new_vertex(const vertex_props& p, where w = where::here()) {
    std::uint32_t id = allocate_slot(w);
    props(id) = p;
    return vertex<Tr>::from_slot(this, id);
  }

  //! The scope of a block of a translated program (model/program.hpp),
  //! running on this thread, whose frame is at `frame` and whose thread's
  //! stack begins at stack_low (0: unknown). Until it ends, handles made or
  //! assigned on this stack below `frame` hold no count (counts_at), and
  //! the collector waits. Nested scopes change nothing; the outermost one
  //! counts the vertices made meanwhile that nothing holds as suspects
  //! (collect_if_due collects them).
  class block_scope {
   public:
    block_scope(context& c, std::uintptr_t stack_low, const void* frame) noexcept : c_(c) {
      if (c.block_depth_++ != 0 || stack_low == 0 || c.parallel_) return;
      const auto high = reinterpret_cast<std::uintptr_t>(frame);
      if (high <= stack_low) return;
      c.uncounted_low_ = stack_low;
      c.uncounted_size_ = high - stack_low;
      c.first_block_slot_ = c.next_slot_;
      ++c.gc_pauses_;
    }
    block_scope(const block_scope&) = delete;
    block_scope& operator=(const block_scope&) = delete;
    ~block_scope() {
      if (--c_.block_depth_ == 0 && c_.uncounted_size_ != 0) c_.end_uncounted_block();
    }

   private:
    context& c_;
  };
  //! Whether a handle at address `at` holds a count: everywhere but on the
  //! stack of a running block (block_scope).
  VV_INLINE bool counts_at(const void* at) const noexcept {
    return reinterpret_cast<std::uintptr_t>(at) - uncounted_low_ >= uncounted_size_;
  }
  //! Runs the tracing pass if enough counts dropped to zero since the last.
  void collect_if_due() {
    if (suspects_ >= gc_threshold_ && gc_pauses_ == 0) collect_garbage();
  }

  //! Vertices alive (reachable or not yet collected).
  std::size_t live_vertices() const noexcept { return live_; }
  //! Slots ever used; bounds every slot id.
  std::uint32_t slot_count() const noexcept { return next_slot_; }
  //! Bytes held by vertex storage (for memory reports).
  std::size_t storage_bytes() const noexcept;

  //! Free every vertex that no handle or mesh can reach. Returns how many
  //! were freed. Does nothing (returns 0) inside a neighbourhood loop.
  std::size_t collect_garbage();

  //! The model's random numbers. Inside a parallel loop an error: the
  //! numbers drawn would depend on the threads' timing.
  std::mt19937_64& random(where w = where::here()) {
    if (parallel_) refuse_in_parallel(w, "random", "draw random numbers");
    return rng_;
  }
  void seed(std::uint64_t s) { rng_.seed(s); }

  //! Folder that relative file paths of the program resolve against.
  std::string base_dir;
  //! Reading the old state of a never-synchronised vertex is an error.
  bool strict_old_state = false;
  //! Threads a parallel loop may use (vv/parallel.hpp); 0: the machine's
  //! cores. The results do not depend on it.
  unsigned threads = 0;
  //! A parallel loop runs its iterations in order and checks that each
  //! changes the properties of its own vertex only (the host's --strict).
  bool strict_parallel = false;
  //! Where the library's warnings go (a host may collect them); stderr when unset.
  std::function<void(const std::string&)> warning_sink;

  //! Remember where each neighbourhood was last edited (vvinterpreter
  //! --check names that line when a neighbourhood is found broken).
  void track_edits(bool on) {
    tracking_edits_ = on;
    watch_edits_ = tracking_edits_ || parallel_;
  }
  //! On every edit: a test and a branch unless tracking is on or a
  //! parallel loop runs (then the edit is an error).
  void note_edit(std::uint32_t id, const char* op, const where& w) {
    if (watch_edits_) watched_edit(id, op, w);
  }
  struct edit_mark {
    where at;               //!< file null: not edited while tracked
    std::uint64_t seq = 0;  //!< edits are numbered in the order they were made
  };
  //! Where v's neighbourhood was last edited.
  edit_mark last_edit(std::uint32_t id) const noexcept {
    return id < last_edit_.size() ? last_edit_[id] : edit_mark{};
  }

  //! Says message once per key over the context's life, so that a file read
  //! every step warns once.
  void warn_once(const std::string& key, const std::string& message) {
    std::lock_guard<std::mutex> lock(warned_mutex_);  // file objects may warn inside a parallel loop
    if (!warned_.insert(key).second) return;
    if (warning_sink) warning_sink(message);
    else std::fprintf(stderr, "%s\n", message.c_str());
  }

  // ---- slot access, used by the algebra (ids come from handles) ----
  std::uint32_t& refs(std::uint32_t id) noexcept { return refs_[id]; }
  std::uint32_t label(std::uint32_t id) const noexcept { return labels_[id]; }
  nb_type& nb(std::uint32_t id) noexcept { return at(id).nb[id & mask]; }
  vertex_props& props(std::uint32_t id) noexcept { return at(id).props[id & mask]; }
  //! The old state: what the last synchronise saved, read-only.
  const nb_type& old_nb(std::uint32_t id) const noexcept {
    const chunk& c = at(id);
    return c.old ? c.old->nb[id & mask] : never_synchronised_nb_;
  }
  const vertex_props& old_props(std::uint32_t id) const noexcept {
    const chunk& c = at(id);
    return c.old ? c.old->props[id & mask] : never_synchronised_props_;
  }
  //! The old state to write (synchronise), made on first use.
  nb_type& writable_old_nb(std::uint32_t id) { return old_block_of(id).nb[id & mask]; }
  vertex_props& writable_old_props(std::uint32_t id) { return old_block_of(id).props[id & mask]; }
  //! Makes the storage of id's old state (before threads write it).
  void make_old_state(std::uint32_t id) { old_block_of(id); }
  bool is_live(std::uint32_t id) const noexcept {
    return id != 0 && id < next_slot_ && label(id) != 0;
  }

  // Inside a parallel loop each thread counts apart (counts_apart_): a
  // plain increment of a shared count would lose updates. Every handle
  // copy comes here: the rest is out of line, so this stays small enough
  // to inline at the models' -O1, and a model without parallel loops
  // (Tr::parallel_loops false) does not even test.
  VV_INLINE void retain(std::uint32_t id) noexcept {
    if constexpr (Tr::parallel_loops)
      if (__builtin_expect(counts_apart_, 0)) return count_on_this_thread(id, 1);
    ++refs_[id];
  }
  VV_INLINE void release(std::uint32_t id) noexcept {
    if constexpr (Tr::parallel_loops)
      if (__builtin_expect(counts_apart_, 0)) return count_on_this_thread(id, -1);
    if (--refs_[id] == 0) ++suspects_;
  }

  //! Freed storage of short vectors of handles, for reuse (vertex.hpp's
  //! allocator); null inside a parallel loop, whose threads would race on it.
  detail::handle_blocks* handle_blocks() noexcept { return parallel_ ? nullptr : &handle_blocks_; }

  //! The shared record handed out when edge records have no fields.
  edge_props& empty_record() noexcept { return empty_record_; }

  //! Keeps the collector from running while slots are held uncounted.
  //! Inside a parallel loop, which pauses it for its whole run, it does
  //! nothing (the loop's threads would race on the pause count).
  class gc_pause {
   public:
    explicit gc_pause(context& c) noexcept : c_(c.parallel_ ? nullptr : &c) {
      if (c_) ++c_->gc_pauses_;
    }
    gc_pause(const gc_pause&) = delete;
    gc_pause& operator=(const gc_pause&) = delete;
    ~gc_pause() {
      if (c_) --c_->gc_pauses_;
    }

   private:
    context* c_;
  };

  // ---- parallel loops (vv/parallel.hpp) ----
  //! The loop running on this context, or null.
  const detail::parallel_loop* parallel_loop() const noexcept { return parallel_; }
  //! An operation a parallel loop's body must not do: the error, naming
  //! its line and the loop's.
  [[noreturn, gnu::noinline, gnu::cold]] void refuse_in_parallel(const where& w, const char* op,
                                                               const char* what) const {
    throw error(w, op, detail::parallel_refusal(*parallel_, what));
  }
  //! For the properties' accessors: in a strict parallel loop, note that
  //! the iteration used vertex id's properties.
  void note_props_use(std::uint32_t id, const where& w) {
    if (__builtin_expect(watch_props_, 0)) watched_props_use(id, w);
  }
  //! Enters a parallel loop (vv/parallel.hpp): pauses the collector and
  //! turns on the checks. Loops do not overlap on a context.
  void begin_parallel(detail::parallel_loop& loop) noexcept {
    parallel_ = &loop;
    watch_edits_ = true;
    ++gc_pauses_;
  }
  void end_parallel() noexcept {
    parallel_ = nullptr;
    watch_edits_ = tracking_edits_;
    watch_props_ = false;
    counts_apart_ = false;
    --gc_pauses_;
  }
  //! Counts on the threads' own tables from now on; merge_thread_counts
  //! adds them to the shared ones.
  void count_apart(std::size_t thread_count) {
    thread_counts_.prepare(thread_count, next_slot_);
    counts_apart_ = true;
  }
  detail::thread_count_tables& thread_count_tables() noexcept { return thread_counts_; }
  void merge_thread_counts() noexcept {
    counts_apart_ = false;
    // A count that ends at zero is a suspect for the collector; one that
    // passed through zero meanwhile (in an order the threads' timing
    // chose) is not, so the collector runs at the same points whatever
    // the number of threads.
    thread_counts_.merge(refs_.data(), [this] { ++suspects_; });
  }
  //! Strict loops: watch the properties used in each iteration.
  void watch_props(bool on) noexcept { watch_props_ = on; }
  //! The bytes of vertex id's properties and current neighbourhood (with
  //! its records), to compare before and after an iteration.
  void snapshot(std::uint32_t id, std::vector<unsigned char>& out) {
    const vertex_props& p = props(id);
    const nb_type& n = nb(id);
    const auto* pb = reinterpret_cast<const unsigned char*>(&p);
    const auto* nbb = reinterpret_cast<const unsigned char*>(n.data());
    out.assign(pb, pb + sizeof(vertex_props));
    out.insert(out.end(), nbb, nbb + n.size() * sizeof(entry));
  }

 private:
  static constexpr std::uint32_t mask = chunk_size - 1;

  struct old_block {
    old_block() {
      for (nb_type& o : nb) o.set_flag(nb_type::never_synchronised);
    }
    nb_type nb[chunk_size];
    vertex_props props[chunk_size];
  };
  // Blocks live in blocks_ (detail/block_arena.hpp): owning one destroys it,
  // the arena frees the memory.
  struct destroy_block {
    template <class Block>
    void operator()(Block* b) const noexcept {
      b->~Block();
    }
  };
  template <class Block>
  using block_ptr = std::unique_ptr<Block, destroy_block>;
  template <class Block>
  block_ptr<Block> make_block() {
    // Value-initialisation zeroes the properties.
    return block_ptr<Block>(new (blocks_.take(sizeof(Block), alignof(Block))) Block());
  }

  struct chunk {
    nb_type nb[chunk_size];
    vertex_props props[chunk_size];
    block_ptr<old_block> old;  // null until a vertex of the chunk is synchronised
  };

  chunk& at(std::uint32_t id) noexcept { return *chunks_[id >> chunk_bits]; }
  const chunk& at(std::uint32_t id) const noexcept { return *chunks_[id >> chunk_bits]; }

  void add_chunk() {
    // Everything that may throw before the chunk counts: the arrays by
    // slot may be longer than the chunks, never shorter.
    refs_.resize((chunks_.size() + 1) * chunk_size, 0u);
    labels_.resize((chunks_.size() + 1) * chunk_size, 0u);
    if (chunks_.size() == chunks_.capacity()) chunks_.reserve(2 * chunks_.size() + 8);
    chunks_.push_back(make_block<chunk>());
  }
  old_block& old_block_of(std::uint32_t id) {
    chunk& c = at(id);
    if (!c.old) c.old = make_block<old_block>();
    return *c.old;
  }

  std::uint32_t allocate_slot(const where& w);
  [[gnu::noinline]] static void count_on_this_thread(std::uint32_t id, std::int32_t by) noexcept {
    detail::this_thread_counts.change(id, by);
  }
  [[gnu::noinline]] void watched_edit(std::uint32_t id, const char* op, const where& w) {
    if (parallel_) refuse_in_parallel(w, op, "edit a neighbourhood");
    if (id >= last_edit_.size()) last_edit_.resize(std::max<std::size_t>(next_slot_, id + 1));
    last_edit_[id] = {w, ++edits_};
  }
  [[gnu::noinline]] void watched_props_use(std::uint32_t id, const where& w) {
    parallel_->strict->note_use(id, w, [&](std::vector<unsigned char>& out) { snapshot(id, out); });
  }
  void free_slot(std::uint32_t id);
  void end_uncounted_block() noexcept;

  // Before the vertex storage, so that it outlives the properties' vectors.
  detail::handle_blocks handle_blocks_;
  // Counts and labels are one array each over all slots, not per chunk:
  // every handle copy touches a count, every `p < q` two labels, and no
  // reference to either outlives a call, so they may move when they grow.
  detail::slot_list refs_;
  detail::slot_list labels_;  // 0: the slot is free
  detail::block_arena blocks_;  // before the blocks, which it outlives
  std::vector<block_ptr<chunk>> chunks_;
  std::vector<std::uint32_t> free_slots_;
  std::uint32_t next_slot_ = 1;
  std::uint32_t next_label_ = 1;
  std::size_t live_ = 0;
  std::size_t suspects_ = 0;  // counts that dropped to zero since the last pass
  std::size_t gc_threshold_ = min_gc_threshold;
  unsigned gc_pauses_ = 0;
  // block_scope: the uncounted stack range, the nesting depth, the first
  // slot made in the block and the freed slots it made vertices in again.
  std::uintptr_t uncounted_low_ = 0, uncounted_size_ = 0;
  unsigned block_depth_ = 0;
  std::uint32_t first_block_slot_ = 0;
  std::vector<std::uint32_t> reused_in_block_;
  std::mt19937_64 rng_{5489u};
  std::set<std::string> warned_;  // keys of the warnings said
  std::mutex warned_mutex_;
  bool tracking_edits_ = false;
  // Tested on hot paths: each one byte, read-only while a loop's threads run.
  bool watch_edits_ = false;   // tracking_edits_ or a parallel loop
  bool counts_apart_ = false;  // retain/release go to this_thread_counts
  bool watch_props_ = false;   // a strict parallel loop notes property uses
  detail::parallel_loop* parallel_ = nullptr;
  detail::thread_count_tables thread_counts_;
  std::vector<edit_mark> last_edit_;  // by slot, while tracking
  std::uint64_t edits_ = 0;
  edge_props empty_record_{};
  nb_type never_synchronised_nb_{typename nb_type::never_synchronised_tag()};
  vertex_props never_synchronised_props_{};

  static constexpr std::size_t min_gc_threshold = 1u << 14;
};

template <class Tr>
std::uint32_t context<Tr>::allocate_slot(const where& w) {
  if (parallel_) refuse_in_parallel(w, "vertex", "create a vertex");
  if (suspects_ >= gc_threshold_ && gc_pauses_ == 0) collect_garbage();
  if (next_label_ == 0) throw error(where{}, "vertex", "the 2^32 vertex labels are used up");
  std::uint32_t id;
  if (!free_slots_.empty()) {
    id = free_slots_.back();
    free_slots_.pop_back();
    if (uncounted_size_) reused_in_block_.push_back(id);
  } else {
    if ((next_slot_ >> chunk_bits) == chunks_.size()) add_chunk();
    id = next_slot_++;
  }
  labels_[id] = next_label_++;
  refs_[id] = 0;
  ++live_;
  return id;
}

template <class Tr>
void context<Tr>::end_uncounted_block() noexcept {
  uncounted_low_ = uncounted_size_ = 0;
  // Made in the block and held by no count now: only its stack held them,
  // or nothing (they may still be reachable through a neighbourhood).
  auto suspect = [this](std::uint32_t id) {
    if (labels_[id] != 0 && refs_[id] == 0) ++suspects_;
  };
  for (std::uint32_t id = first_block_slot_; id < next_slot_; ++id) suspect(id);
  for (std::uint32_t id : reused_in_block_) suspect(id);
  reused_in_block_.clear();
  --gc_pauses_;
}

template <class Tr>
void context<Tr>::free_slot(std::uint32_t id) {
  chunk& c = at(id);
  std::uint32_t i = id & mask;
  labels_[id] = 0;
  c.nb[i].clear();
  c.nb[i].set_flag(nb_type::no_flag);
  // Resetting the properties may release handles they hold.
  c.props[i] = vertex_props();
  if (c.old) {
    c.old->nb[i].clear();
    c.old->nb[i].set_flag(nb_type::never_synchronised);
    c.old->props[i] = vertex_props();
  }
  free_slots_.push_back(id);
  --live_;
}

template <class Tr>
std::size_t context<Tr>::collect_garbage() {
  if (gc_pauses_ != 0) return 0;
  std::vector<std::uint64_t> marked((next_slot_ + 63) / 64, 0);
  auto is_marked = [&](std::uint32_t id) { return (marked[id >> 6] >> (id & 63)) & 1u; };
  auto mark = [&](std::uint32_t id) { marked[id >> 6] |= std::uint64_t(1) << (id & 63); };
  std::vector<std::uint32_t> stack;
  for (std::uint32_t id = 1; id < next_slot_; ++id)
    if (label(id) != 0 && refs(id) != 0) mark(id), stack.push_back(id);
  auto visit = [&](const nb_type& n) {
    for (const entry& e : n) {
      std::uint32_t v = entry_traits::id(e);
      if (!is_marked(v)) mark(v), stack.push_back(v);
    }
  };
  while (!stack.empty()) {
    std::uint32_t u = stack.back();
    stack.pop_back();
    visit(nb(u));
    visit(old_nb(u));
  }
  // Unmarked vertices have no counted reference, so no handle (not even one
  // inside another garbage vertex's properties) can observe their release.
  std::size_t freed = 0;
  for (std::uint32_t id = 1; id < next_slot_; ++id)
    if (label(id) != 0 && !is_marked(id)) free_slot(id), ++freed;
  suspects_ = 0;
  gc_threshold_ = std::max(min_gc_threshold, live_ / 2);
  return freed;
}

template <class Tr>
std::size_t context<Tr>::storage_bytes() const noexcept {
  std::size_t bytes = chunks_.size() * sizeof(chunk) +
                      (refs_.capacity() + labels_.capacity()) * sizeof(std::uint32_t) +
                      chunks_.capacity() * sizeof(block_ptr<chunk>) +
                      free_slots_.capacity() * sizeof(std::uint32_t);
  for (const auto& c : chunks_) {
    if (c->old) bytes += sizeof(old_block);
    for (std::uint32_t i = 0; i < chunk_size; ++i) {
      if (c->nb[i].size() > Tr::inline_valence) bytes += c->nb[i].size() * sizeof(entry);
      if (c->old && c->old->nb[i].size() > Tr::inline_valence) bytes += c->old->nb[i].size() * sizeof(entry);
    }
  }
  return bytes;
}

}  // namespace vv
