// Meshes (LANGUAGE.md section 5): sets of vertices with O(1) membership and
// insertion-ordered iteration. A mesh refers to its members (they stay
// alive while in it) but does not own them: a vertex may be in many meshes.
//
// Representation: `order_` lists member slots in insertion order, with 0 for
// a removed member (a hole); `index_` maps a slot to its position there
// (detail/member_index.hpp). Holes are squeezed out when they outnumber the
// members, but never during an iteration, so a loop's positions stay valid
// (LANGUAGE.md section 6).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "detail/member_index.hpp"
#include "detail/parallel_run.hpp"
#include "vertex.hpp"

namespace vv {

template <class Tr>
class mesh : public Tr::mesh_props {
 public:
  using traits_type = Tr;
  using context_type = context<Tr>;
  using vertex_type = vertex<Tr>;
  using props_type = typename Tr::mesh_props;

  //! A mesh of the model's context when the traits name one (translated
  //! programs), else of the context of the first vertex added.
  mesh() : props_type() {
    if constexpr (detail::has_default_context<Tr>::value) ctx_ = &Tr::context();
  }
  explicit mesh(context_type& ctx) : props_type(), ctx_(&ctx) {}
  mesh(const mesh& o) : props_type(o), ctx_(o.ctx_) { copy_members(o); }
  //! A mesh being iterated is copied, then emptied in place: its loop's
  //! positions stay valid and it sees the members removed.
  mesh(mesh&& o) noexcept : props_type(std::move(static_cast<props_type&>(o))), ctx_(o.ctx_) {
    if (o.iterating_ > 0) {
      copy_members(o);
      o.clear_members();
      return;
    }
    order_.swap(o.order_);
    index_.swap(o.index_);
    count_ = o.count_;
    holes_ = o.holes_;
    o.count_ = o.holes_ = 0;
  }
  //! `M = N`: the same set (vertices are shared) and the same properties.
  mesh& operator=(const mesh& o) {
    if (this == &o) return *this;
    check_unchanging(where{}, "=");
    static_cast<props_type&>(*this) = o;
    if (iterating_ > 0) {
      assign_during_iteration(o);
    } else {
      mesh copy(o);
      swap_members(copy);
    }
    return *this;
  }
  mesh& operator=(mesh&& o) noexcept(false) {
    if (this == &o) return *this;
    check_unchanging(where{}, "=");
    if (iterating_ > 0 || o.iterating_ > 0) {  // `N = std::move(S)` or std::swap inside a loop
      *this = static_cast<const mesh&>(o);
      o.clear_members();
      return *this;
    }
    static_cast<props_type&>(*this) = std::move(static_cast<props_type&>(o));
    swap_members(o);
    o.clear_members();
    return *this;
  }
  ~mesh() { release_all(); }

  //! `add v to M;` (no effect if v is already a member)
  VV_INLINE void add(const vertex_type& v, where w = where::here()) {
    if (!v) raise(w, "add", [] { return std::string("cannot add the null vertex to a mesh"); });
    adopt_context(v, w);
    check_unchanging(w, "add");
    if (find_position(v.slot()) >= 0) return;
    add_slot(v.slot());
  }

  //! `remove v from M;` (no effect if v is not a member)
  void remove(const vertex_type& v, where w = where::here()) {
    check_unchanging(w, "remove");
    if (!v || v.ctx() != ctx_) return;
    std::ptrdiff_t pos = find_position(v.slot());
    if (pos < 0) return;
    index_.erase(v.slot(), order_);
    order_[static_cast<std::size_t>(pos)] = 0;
    ++holes_;
    --count_;
    ctx_->release(v.slot());
    if (iterating_ == 0) compact_if_sparse();
  }

  //! `is v in M`
  bool contains(const vertex_type& v) const noexcept {
    return v && v.ctx() == ctx_ && find_position(v.slot()) >= 0;
  }

  //! `merge M with N;` / `M += N`
  void merge(const mesh& o, where w = where::here()) {
    check_unchanging(w, "merge");
    if (&o == this) return;
    // Room for all of o at once (at least 1.5x growth, so repeated small
    // merges stay linear): a big merge then leaves no slack behind.
    std::size_t needed = order_.size() + o.count_;
    if (needed > order_.capacity())
      order_.reserve(std::max(needed, order_.capacity() + order_.capacity() / 2));
    if (o.ctx_ != ctx_ && ctx_ && o.count_) {
      // Another context's vertices: add names the first as the error.
      for (std::uint32_t id : o.order_)
        if (id) add(vertex_type::from_slot(o.ctx_, id), w);
      return;
    }
    if (!ctx_) ctx_ = o.ctx_;
    // Slot by slot, without a handle per member (a count in and out).
    for (std::uint32_t id : o.order_)
      if (id && find_position(id) < 0) add_slot(id);
  }
  mesh& operator+=(const mesh& o) {
    merge(o, where{});
    return *this;
  }

  //! `clear M;`
  void clear(where w = where::here()) {
    check_unchanging(w, "clear");
    clear_members();
  }

  std::size_t size() const noexcept { return count_; }
  bool empty() const noexcept { return count_ == 0; }
  //! vv 1.1 name of size().
  std::size_t vertexCount() const noexcept { return count_; }

  //! `M.readXMLFile(path)`: replace M by a .vvm file (vv/io/vvm.hpp).
  //! Relative paths resolve against the context's base_dir. An error names
  //! the calling line first, then the file's own line and problem.
  void readXMLFile(const std::string& path, where w = where::here());
  //! `M.writeXMLFile(path)`: save M as a .vvm file (vv/io/vvm.hpp).
  void writeXMLFile(const std::string& path, where w = where::here()) const;
  //! `M.readFile(path)`: replace M by a mesh file, the format chosen by
  //! its extension: .vvm, .obj, .off, .ply or .stl (vv/io/mesh_io.hpp).
  void readFile(const std::string& path, where w = where::here());
  //! `M.writeFile(path)`: save M in the format of the extension.
  void writeFile(const std::string& path, where w = where::here()) const;

  context_type* ctx() const noexcept { return ctx_; }
  //! Inside a parallel loop a mesh must not change: the error, at w.
  void check_unchanging(const where& w, const char* op) const {
    if (ctx_ && ctx_->parallel_loop()) ctx_->refuse_in_parallel(w, op, "change a mesh");
  }
  //! Bytes held by the set (for memory reports).
  std::size_t storage_bytes() const noexcept {
    return order_.capacity() * sizeof(std::uint32_t) + index_.bytes();
  }

  // ---- iteration: members present at the start, in insertion order,
  // skipping those removed before their turn ----
  // Inside a parallel loop, whose threads may iterate a mesh at once, an
  // iterator leaves the count of iterations alone: the mesh cannot change
  // there anyway.
  class iterator {
   public:
    iterator(const iterator& o) noexcept : m_(o.m_), pos_(o.pos_), end_(o.end_), counted_(o.counted_) {
      if (counted_) ++m_->iterating_;
    }
    iterator& operator=(const iterator&) = delete;
    ~iterator() {
      if (counted_) m_->end_iteration();
    }
    vertex_type operator*() const { return vertex_type::from_slot(m_->ctx_, m_->order_[pos_]); }
    iterator& operator++() {
      ++pos_;
      skip_holes();
      return *this;
    }
    struct sentinel {};
    friend bool operator!=(const iterator& it, sentinel) noexcept { return it.pos_ < it.end_; }
    friend bool operator==(const iterator& it, sentinel) noexcept { return it.pos_ >= it.end_; }

   private:
    friend class mesh;
    explicit iterator(const mesh* m) noexcept
        : m_(m), pos_(0), end_(m->order_.size()), counted_(!m->ctx_ || !m->ctx_->parallel_loop()) {
      if (counted_) ++m_->iterating_;
      skip_holes();
    }
    void skip_holes() noexcept {
      while (pos_ < end_ && m_->order_[pos_] == 0) ++pos_;
    }
    const mesh* m_;
    std::size_t pos_, end_;
    bool counted_;
  };
  iterator begin() const noexcept { return iterator(this); }
  typename iterator::sentinel end() const noexcept { return {}; }

  //! Slots of the members in order (holes are 0), for library algorithms.
  const detail::slot_list& slots() const noexcept { return order_; }

 private:
  void adopt_context(const vertex_type& v, const where& w) {
    if (!ctx_) ctx_ = v.ctx();
    else if (v.ctx() != ctx_)
      raise(w, "add", [&] { return name_of(v) + " belongs to another context than the mesh"; });
  }

  std::ptrdiff_t find_position(std::uint32_t id) const noexcept { return index_.find(id, order_); }
  // Adds a slot of ctx_ that is not a member.
  VV_INLINE void add_slot(std::uint32_t id) {
    ctx_->retain(id);
    order_.push_back(id);
    ++count_;
    index_.insert(id, order_.size() - 1, order_, count_, ctx_->slot_count());
  }

  // Squeeze out holes once they outnumber the members.
  void compact_if_sparse() {
    if (iterating_ > 0 || holes_ < 64 || holes_ < count_) return;
    order_.erase(std::remove(order_.begin(), order_.end(), 0u), order_.end());
    holes_ = 0;
    index_.rebuild(order_, count_);
  }
  void end_iteration() const noexcept {
    if (--iterating_ == 0) const_cast<mesh*>(this)->compact_if_sparse();
  }

  void copy_members(const mesh& o) {
    order_.reserve(o.count_);
    for (std::uint32_t id : o.order_)
      if (id) order_.push_back(id), ctx_->retain(id);
    count_ = order_.size();
    if (count_) index_.rebuild(order_, count_);
  }
  void swap_members(mesh& o) noexcept {
    std::swap(ctx_, o.ctx_);
    order_.swap(o.order_);
    index_.swap(o.index_);
    std::swap(count_, o.count_);
    std::swap(holes_, o.holes_);
  }
  // M = N inside a loop over M: keep positions, change membership only.
  void assign_during_iteration(const mesh& o) {
    for (std::size_t pos = 0; pos < order_.size(); ++pos) {
      std::uint32_t id = order_[pos];
      if (id && !o.contains(vertex_type::from_slot(ctx_, id))) remove(vertex_type::from_slot(ctx_, id));
    }
    for (std::uint32_t id : o.order_)
      if (id) add(vertex_type::from_slot(o.ctx_, id), where{});
  }
  void clear_members() noexcept {
    release_all();
    index_.clear();
    if (iterating_ > 0) {
      std::fill(order_.begin(), order_.end(), 0u);
      holes_ = order_.size();
    } else {
      order_.clear();
      holes_ = 0;
    }
    count_ = 0;
  }
  void release_all() noexcept {
    for (std::uint32_t id : order_)
      if (id) ctx_->release(id);
  }

  context_type* ctx_ = nullptr;
  detail::slot_list order_;
  detail::member_index index_;
  std::size_t count_ = 0;
  std::size_t holes_ = 0;
  mutable unsigned iterating_ = 0;
};

//! `is v in M`
template <class Tr>
bool is_in(const vertex<Tr>& v, const mesh<Tr>& m, where = where::here()) noexcept {
  return m.contains(v);
}

//! The context of a mesh, for ordinary code (`G::mesh N(vv::context_of(S));`,
//! `vv::context_of(S).new_vertex()`).
//! \throw vv::error when the mesh has none yet (default-constructed, empty).
template <class Tr>
context<Tr>& context_of(const mesh<Tr>& m, where w = where::here()) {
  if (!m.ctx()) raise(w, "context_of", [] { return std::string("the mesh has no context yet"); });
  return *m.ctx();
}

//! `synchronise M;`: save the current state of every member as its old
//! state (properties, neighbourhood with records, flag).
//! A large mesh is copied on the context's threads (vv/parallel.hpp).
template <class Tr>
void synchronise(const mesh<Tr>& m, where w = where::here()) {
  context<Tr>* ctx = m.ctx();
  if (!ctx) return;
  m.check_unchanging(w, "synchronise");
  detail::synchronise_members(*ctx, m.slots());
}
template <class Tr>
void synchronize(const mesh<Tr>& m, where w = where::here()) {
  synchronise(m, w);
}

}  // namespace vv
