// A std::vector whose first push_back or emplace_back makes room for a few
// elements at once.
//
// A model collects a face's corners, or their positions, in a vector that
// lives for one call: a standard vector grows 1, 2, 4, moving what it holds
// into a new block each time, which cost a Catmull-Clark step a tenth of
// its instructions and a Doo-Sabin step a fifth. vvlib makes std::vector of its handles
// (vv/handle_vector.hpp) and of util::Point (util/point.hpp) this class:
// the standard vector over an allocator of their own, with room for four
// from the first push. Everything else is std::vector's; a program sees no
// difference but the capacity after its first push.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace util::detail {

//! std::allocator under another name, so that a std::vector specialised
//! for T can derive from the standard vector of T over it. It rebinds to
//! itself for T, as a vector rebinds its allocator to its element type.
template <class T>
struct own_allocator : std::allocator<T> {
  using value_type = T;
  template <class U>
  struct rebind {
    using other = std::conditional_t<std::is_same<U, T>::value, own_allocator, std::allocator<U>>;
  };
  own_allocator() noexcept = default;
  template <class U>
  own_allocator(const std::allocator<U>&) noexcept {}
};

template <class T, class Alloc, std::size_t FirstRoom>
class first_room_vector : public std::vector<T, Alloc> {
  using base = std::vector<T, Alloc>;

 public:
  //! Room made by the first push_back or emplace_back.
  static constexpr std::size_t first_capacity = FirstRoom;

  using typename base::reference;

  using base::base;
  first_room_vector() noexcept = default;
  first_room_vector(const first_room_vector&) = default;
  first_room_vector(first_room_vector&&) noexcept = default;
  explicit first_room_vector(const std::allocator<T>&) noexcept {}
  first_room_vector& operator=(const first_room_vector&) = default;
  first_room_vector& operator=(first_room_vector&&) noexcept = default;
  first_room_vector& operator=(std::initializer_list<T> list) {
    base::operator=(list);
    return *this;
  }

  void push_back(const T& v) {
    make_room();
    base::push_back(v);
  }
  void push_back(T&& v) {
    make_room();
    base::push_back(std::move(v));
  }
  template <class... A>
  reference emplace_back(A&&... args) {
    make_room();
    return base::emplace_back(std::forward<A>(args)...);
  }

 private:
  // Only a vector without storage is given room, so the element pushed
  // cannot be one of its own. With libstdc++ the block is installed
  // directly (its vector keeps its three pointers in _M_impl, which a
  // derived class may set): reserve() would check, relocate and free for
  // nothing, half of what the first push costs.
  void make_room() {
    if (this->capacity() != 0) return;
#if defined(__GLIBCXX__)
    auto* block = this->_M_allocate(first_capacity);
    this->_M_impl._M_start = this->_M_impl._M_finish = block;
    this->_M_impl._M_end_of_storage = block + first_capacity;
#else
    this->reserve(first_capacity);
#endif
  }
};

}  // namespace util::detail
