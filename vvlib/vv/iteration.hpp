// `forall` (LANGUAGE.md section 6):
//
//   forall v in M { ... }     for (auto&& v : vv::each(M)) { ... }
//   forall x in v { ... }     for (auto&& x : vv::each(v)) { ... }
//   forall x in `v { ... }    for (auto&& x : vv::each(vv::old(v))) { ... }
//
// The set or neighbourhood is taken once, at loop entry. A neighbourhood
// loop visits a snapshot of the neighbours present at entry, in rotation
// order, whatever the body edits; a mesh loop is the mesh's own iterator.
#pragma once

#include "detail/inline.hpp"

#include <cstdint>
#include <utility>
#include <vector>

#include "mesh.hpp"
#include "queries.hpp"

namespace vv {

template <class Tr>
class neighbour_range {
 public:
  using vertex_type = vertex<Tr>;

  VV_INLINE neighbour_range(context<Tr>* ctx, const typename context<Tr>::nb_type& nb)
      : ctx_(ctx), pause_(*ctx), size_(nb.size()) {
    if (size_ <= inline_size) {
      nb.copy_ids(local_, inline_size);
    } else {
      spilled_.resize(size_);
      nb.copy_ids(spilled_.data(), size_);
    }
  }
  neighbour_range(const neighbour_range&) = delete;
  neighbour_range& operator=(const neighbour_range&) = delete;

  // The loop variable is the iterator's own handle, borrowed (uncounted):
  // `for (auto&& x : vv::each(v))`, as vvc writes forall, binds to it and
  // reads the neighbours without a count in and out for each; a
  // `for (vertex x : ...)` copies it into a counted handle. Either way a
  // copy or a return of x is counted.
  class iterator {
   public:
    vertex_type& operator*() const noexcept {
      current_.rebind_borrowed(ctx_, *p_);
      return current_;
    }
    iterator& operator++() noexcept {
      ++p_;
      return *this;
    }
    friend bool operator!=(const iterator& a, const iterator& b) noexcept { return a.p_ != b.p_; }
    friend bool operator==(const iterator& a, const iterator& b) noexcept { return a.p_ == b.p_; }

   private:
    friend class neighbour_range;
    iterator(context<Tr>* c, const std::uint32_t* p) noexcept : ctx_(c), p_(p) {}
    context<Tr>* ctx_;
    const std::uint32_t* p_;
    mutable vertex_type current_;
  };
  iterator begin() const noexcept { return iterator(ctx_, ids()); }
  iterator end() const noexcept { return iterator(ctx_, ids() + size_); }
  std::uint32_t size() const noexcept { return size_; }

 private:
  static constexpr std::uint32_t inline_size = 16;
  const std::uint32_t* ids() const noexcept { return size_ <= inline_size ? local_ : spilled_.data(); }

  context<Tr>* ctx_;
  // The snapshot holds slots without counting them: keep the collector off
  // until the loop ends, so none of them can be freed and reused meanwhile.
  typename context<Tr>::gc_pause pause_;
  std::uint32_t size_;
  std::uint32_t local_[inline_size];
  std::vector<std::uint32_t> spilled_;
};

template <class Tr>
const mesh<Tr>& each(const mesh<Tr>& m) noexcept {
  return m;
}
//! A mesh returned by value is kept alive by the loop.
template <class Tr>
mesh<Tr> each(mesh<Tr>&& m) noexcept {
  return std::move(m);
}
template <class Tr>
VV_INLINE neighbour_range<Tr> each(const vertex<Tr>& v, where w = where::here()) {
  auto s = detail::view(v, "forall", w);
  return neighbour_range<Tr>(s.ctx, *s.nb);
}
template <class Tr>
VV_INLINE neighbour_range<Tr> each(const old_vertex<Tr>& v, where w = where::here()) {
  auto s = detail::view(v, "forall", w);
  return neighbour_range<Tr>(s.ctx, *s.nb);
}

}  // namespace vv
