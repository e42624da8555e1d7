// Path expressions (LANGUAGE.md section 4.1): walk a pair of vertices with
// next / prev / swap over current or old neighbourhoods.
//
//   @(a, b) swap next @      vv::path(a, b).swap().next().second()
//   `@(a, b) ... @           vv::old_path(a, b)...
//   @&(a, b) ... @           vv::path_into(a, b)....store()
#pragma once

#include "queries.hpp"

namespace vv {

template <class Tr>
class path_walk {
 public:
  path_walk(vertex<Tr> a, vertex<Tr> b, bool on_old, where w)
      : a_(std::move(a)), b_(std::move(b)), old_(on_old), w_(w) {}

  //! (a, b) -> (a, nextto b in a)
  path_walk& next() {
    b_ = old_ ? next_to(b_, old(a_, w_), w_) : next_to(b_, a_, w_);
    return *this;
  }
  //! (a, b) -> (a, prevto b in a)
  path_walk& prev() {
    b_ = old_ ? prev_to(b_, old(a_, w_), w_) : prev_to(b_, a_, w_);
    return *this;
  }
  //! (a, b) -> (b, a)
  path_walk& swap() {
    std::swap(a_, b_);
    return *this;
  }

  const vertex<Tr>& first() const noexcept { return a_; }
  //! The value of the path: the second vertex of the final pair.
  const vertex<Tr>& second() const noexcept { return b_; }

 protected:
  vertex<Tr> a_, b_;
  bool old_;
  where w_;
};

//! A walk that assigns the final pair back to the two variables it started
//! from (`@&(a, b) ... @`).
template <class Tr>
class path_into_walk : public path_walk<Tr> {
 public:
  path_into_walk(vertex<Tr>& a, vertex<Tr>& b, bool on_old, where w)
      : path_walk<Tr>(a, b, on_old, w), a_ref_(a), b_ref_(b) {}
  path_into_walk& next() { return path_walk<Tr>::next(), *this; }
  path_into_walk& prev() { return path_walk<Tr>::prev(), *this; }
  path_into_walk& swap() { return path_walk<Tr>::swap(), *this; }
  //! Writes the pair back and gives the second vertex.
  vertex<Tr> store() {
    a_ref_ = this->a_;
    b_ref_ = this->b_;
    return this->b_;
  }

 private:
  vertex<Tr>& a_ref_;
  vertex<Tr>& b_ref_;
};

template <class Tr>
path_walk<Tr> path(const vertex<Tr>& a, const vertex<Tr>& b, where w = where::here()) {
  return path_walk<Tr>(a, b, false, w);
}
template <class Tr>
path_walk<Tr> old_path(const vertex<Tr>& a, const vertex<Tr>& b, where w = where::here()) {
  return path_walk<Tr>(a, b, true, w);
}
template <class Tr>
path_into_walk<Tr> path_into(vertex<Tr>& a, vertex<Tr>& b, where w = where::here()) {
  return path_into_walk<Tr>(a, b, false, w);
}
template <class Tr>
path_into_walk<Tr> old_path_into(vertex<Tr>& a, vertex<Tr>& b, where w = where::here()) {
  return path_into_walk<Tr>(a, b, true, w);
}

}  // namespace vv
