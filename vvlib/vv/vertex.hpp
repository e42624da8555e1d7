// Vertex handles: references to a vertex of a context (counted, but on a
// running block's stack: context::block_scope), and the
// read-only view of a vertex's synchronised (old) state.
#pragma once

#include "detail/inline.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <new>
#include <ostream>
#include <string>
#include <utility>

#include "context.hpp"
#include "error.hpp"

namespace vv {

//! A handle may be declared while Tr is still incomplete (a property
//! struct may hold vertices), so nothing here names Tr's members until used.
template <class Tr>
class vertex {
 public:
  using traits_type = Tr;
  using context_type = context<Tr>;

  //! The null vertex (label 0).
  vertex() noexcept = default;
  vertex(std::nullptr_t) noexcept {}  // `vertex v = 0;`
  VV_INLINE vertex(const vertex& o) noexcept : ctx_(o.ctx_), id_(o.id_) {
    if (id_) hold();
  }
  // A borrowed handle (see rebind_borrowed) is copied, never robbed: its
  // loop still reads it, and the new handle must hold a count of its own
  // (unless it is on a running block's stack too: hold).
  VV_INLINE vertex(vertex&& o) noexcept : ctx_(o.ctx_), id_(o.id_) {
    if (o.counted_) {
      counted_ = true;
      o.counted_ = false;
      o.id_ = 0;
    } else if (id_) {
      hold();
    }
  }
  VV_INLINE vertex& operator=(const vertex& o) noexcept {
    assign_slot(o.ctx_, o.id_);
    return *this;
  }
  VV_INLINE vertex& operator=(vertex&& o) noexcept {
    if (!o.counted_) return *this = static_cast<const vertex&>(o);
    if (this != &o) {
      drop();
      ctx_ = o.ctx_;
      id_ = o.id_;
      counted_ = true;
      o.id_ = 0;
      o.counted_ = false;
    }
    return *this;
  }
  VV_INLINE ~vertex() { drop(); }

  //! A vertex converts to bool, the non-null test: in conditions and
  //! `static_cast<bool>` through this operator, and implicitly (`return v;`
  //! in a function returning bool, `bool b = v;`, a bool argument) through
  //! the one below. An implicit `operator bool` would also make `v + 1`,
  //! `int i = v` and `v * 2` compile; a pointer to a member converts to
  //! bool and to nothing arithmetic, so those stay errors.
  explicit operator bool() const noexcept { return id_ != 0; }
 private:
  struct bool_tag {
    int non_null;
  };
  using safe_bool = int bool_tag::*;

 public:
  operator safe_bool() const noexcept { return id_ ? &bool_tag::non_null : nullptr; }
  //! The label (creation order, 0 for null).
  unsigned label() const noexcept { return id_ ? ctx_->label(id_) : 0u; }

  //! The current properties (`v$name`); null is an error.
  template <class T = Tr>
  typename T::vertex_props& props(where w = where::here()) const {
    if (!id_) raise(w, "$", [] { return std::string("property access on the null vertex"); });
    ctx_->note_props_use(id_, w);
    return ctx_->props(id_);
  }
  template <class T = Tr>
  typename T::vertex_props* operator->() const {
    return &props(where{});
  }

  // ---- for the library: the storage behind the handle ----
  context_type* ctx() const noexcept { return ctx_; }
  std::uint32_t slot() const noexcept { return id_; }
  //! A new handle to a slot: counted, unless it is made on a running
  //! block's stack (context::block_scope).
  VV_INLINE static vertex from_slot(context_type* c, std::uint32_t id) noexcept {
    return vertex(c, id, hold_tag{});
  }
  //! Makes this handle name a slot without counting it: a neighbourhood
  //! loop's variable (neighbour_range), valid while the loop keeps the
  //! collector paused. Copies and moves of it are counted handles, so
  //! only the loop's own handle goes uncounted; a loop body reads its
  //! neighbours without touching their counts.
  VV_INLINE void rebind_borrowed(context_type* c, std::uint32_t id) noexcept {
    drop();
    ctx_ = c;
    id_ = id;
  }
  //! Makes this handle name slot id of c ({nullptr, 0}: null), counted
  //! as a copy assigned to it would be.
  VV_INLINE void assign_slot(context_type* c, std::uint32_t id) noexcept {
    const bool counted = id && c->counts_at(this);
    if (counted) c->retain(id);
    drop();
    ctx_ = c;
    id_ = id;
    counted_ = counted;
  }
  //! An uncounted handle to slot id, as a prvalue: the parameter it
  //! initialises is that handle itself, not a counted copy. A parallel
  //! loop hands each iteration its vertex so (the mesh keeps it alive and
  //! the collector is paused): no count changes on the loop's threads.
  VV_INLINE static vertex borrowed(context_type* c, std::uint32_t id) noexcept {
    return vertex(c, id, borrow_tag{});
  }

  friend bool operator==(const vertex& a, const vertex& b) noexcept {
    return a.id_ == b.id_ && (a.id_ == 0 || a.ctx_ == b.ctx_);
  }
  friend bool operator!=(const vertex& a, const vertex& b) noexcept { return !(a == b); }
  // `v == 0`: without these, the comparison of pointers to members (through
  // the conversion above) would be as good a match as vertex(nullptr).
  friend bool operator==(const vertex& a, std::nullptr_t) noexcept { return !a.id_; }
  friend bool operator==(std::nullptr_t, const vertex& a) noexcept { return !a.id_; }
  friend bool operator!=(const vertex& a, std::nullptr_t) noexcept { return a.id_ != 0; }
  friend bool operator!=(std::nullptr_t, const vertex& a) noexcept { return a.id_ != 0; }
  friend bool operator<(const vertex& a, const vertex& b) noexcept { return a.label() < b.label(); }
  friend bool operator>(const vertex& a, const vertex& b) noexcept { return b < a; }
  friend bool operator<=(const vertex& a, const vertex& b) noexcept { return !(b < a); }
  friend bool operator>=(const vertex& a, const vertex& b) noexcept { return !(a < b); }
  friend std::ostream& operator<<(std::ostream& os, const vertex& v) {
    return os << "vertex " << v.label();
  }

 private:
  struct hold_tag {};
  // Guaranteed copy elision makes `this` the handle's final address, also
  // through from_slot.
  vertex(context_type* c, std::uint32_t id, hold_tag) noexcept : ctx_(c), id_(id) {
    if (id_) hold();
  }
  struct borrow_tag {};
  vertex(context_type* c, std::uint32_t id, borrow_tag) noexcept : ctx_(c), id_(id) {}
  // Takes a count for id_, or, on the stack of a running block, none: the
  // collector waits for the block's end, when this handle is gone.
  VV_INLINE void hold() noexcept {
    if (ctx_->counts_at(this)) {
      ctx_->retain(id_);
      counted_ = true;
    }
  }
  VV_INLINE void drop() noexcept {
    if (counted_) ctx_->release(id_);
    id_ = 0;
    counted_ = false;
  }

  context_type* ctx_ = nullptr;
  std::uint32_t id_ = 0;
  // Whether this handle holds a count of id_ (so drop releases one). A
  // null handle, a borrowed one (rebind_borrowed, borrowed) and one on a
  // running block's stack hold none. One flag, so that dropping a handle
  // costs one test.
  bool counted_ = false;
};

//! `labelof v`
template <class Tr>
unsigned label_of(const vertex<Tr>& v) noexcept {
  return v.label();
}

//! The context of a vertex (`vv::context_of(v).new_vertex()`).
//! \throw vv::error for the null vertex, which belongs to no context.
template <class Tr>
context<Tr>& context_of(const vertex<Tr>& v, where w = where::here()) {
  if (!v) raise(w, "context_of", [] { return std::string("the null vertex has no context"); });
  return *v.ctx();
}

//! How errors name a vertex.
template <class Tr>
std::string name_of(const vertex<Tr>& v) {
  return v ? "vertex " + std::to_string(v.label()) : std::string("the null vertex");
}

//! A vertex named by its slot, without a count: a query's result that is
//! read at once (vv/uncounted.hpp). {nullptr, 0} is the null vertex.
template <class Tr>
struct vertex_ref {
  context<Tr>* ctx;
  std::uint32_t id;
};

//! `` `v ``: the state saved by the last synchronise of a mesh holding v.
//! Read-only; neighbourhood queries on it walk the old neighbourhood.
//!
//! A view for use within an expression (as a translated program uses it):
//! it does not keep the vertex alive, so do not store it beyond the handle
//! it came from.
template <class Tr>
class old_vertex {
 public:
  using traits_type = Tr;

  VV_INLINE old_vertex(const vertex<Tr>& v, where w) : ctx_(v.ctx()), id_(v.slot()) {
    if (!v) raise(w, "`", [] { return std::string("old state of the null vertex"); });
    if (ctx_->strict_old_state && !synchronised())
      raise(w, "`", [&] { return name_of(v) + " has never been synchronised (strict mode)"; });
  }

  template <class T = Tr>
  const typename T::vertex_props& props(where = where::here()) const noexcept {
    return ctx_->old_props(id_);
  }
  template <class T = Tr>
  const typename T::vertex_props* operator->() const noexcept {
    return &props();
  }
  //! The vertex itself (edits through `` `v `` change its current state).
  vertex<Tr> current() const noexcept { return vertex<Tr>::from_slot(ctx_, id_); }
  bool synchronised() const noexcept {
    return ctx_->old_nb(id_).flag() != context<Tr>::nb_type::never_synchronised;
  }

  // ---- for the library ----
  context<Tr>* ctx() const noexcept { return ctx_; }
  std::uint32_t slot() const noexcept { return id_; }
  //! The old state of a live slot, unchecked (the caller checked).
  static old_vertex from_slot(context<Tr>* c, std::uint32_t id) noexcept { return old_vertex(c, id); }

 private:
  old_vertex(context<Tr>* c, std::uint32_t id) noexcept : ctx_(c), id_(id) {}
  context<Tr>* ctx_;
  std::uint32_t id_;
};

template <class Tr>
VV_INLINE old_vertex<Tr> old(const vertex<Tr>& v, where w = where::here()) {
  return old_vertex<Tr>(v, w);
}
//! `` ``v `` is `` `v ``: the old state has no old state of its own.
template <class Tr>
VV_INLINE old_vertex<Tr> old(const old_vertex<Tr>& v, where = where::here()) {
  return v;
}

}  // namespace vv

template <class Tr>
struct std::hash<vv::vertex<Tr>> {
  std::size_t operator()(const vv::vertex<Tr>& v) const noexcept {
    return std::hash<unsigned>()(v.label());
  }
};

#include "handle_vector.hpp"
