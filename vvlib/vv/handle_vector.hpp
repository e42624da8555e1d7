// Vectors of handles: `std::vector<vv::vertex<Tr>>` is vvlib's.
//
// A translated program collects a face's corners or a cell's wall in a
// std::vector<vertex>. A vector grows 1, 2, 4, 8: a Catmull-Clark step
// moved its handles into a new block three times per face, a tenth of its
// instructions. vvlib's vector is the standard one with two differences:
//
// * the first push_back or emplace_back makes room for four handles at
//   once (a quad's corners, a triangle's: util/first_room_vector.hpp);
// * blocks of 1, 2, 4 and 8 handles come from the context's recycled ones
//   (detail/handle_blocks.hpp) for a translated program's traits, which
//   name the model's context; other traits, parallel loops (whose threads
//   use the heap) and builds under AddressSanitizer (so that a use after
//   free is still reported) use operator new alone.
//
// Everything else is std::vector's own: it is a std::vector of handles
// with another allocator underneath, so a program sees no difference but
// the capacity after its first push_back.
#pragma once

#include "detail/inline.hpp"

#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>

#include "../util/first_room_vector.hpp"
#include "detail/handle_blocks.hpp"
#include "traits.hpp"

namespace vv {
template <class Tr>
class vertex;
}

namespace vv::detail {

//! The allocator of vectors of handles: recycled blocks for a translated
//! program's traits, operator new otherwise.
template <class Tr>
class handle_allocator {
 public:
  using value_type = vertex<Tr>;
  using size_type = std::size_t;
  using difference_type = std::ptrdiff_t;
  using propagate_on_container_move_assignment = std::true_type;
  using is_always_equal = std::true_type;
  // A vector rebinds its allocator to its own element type: to this one.
  template <class U>
  struct rebind {
    using other = std::conditional_t<std::is_same<U, vertex<Tr>>::value, handle_allocator, std::allocator<U>>;
  };

  handle_allocator() noexcept = default;
  handle_allocator(const handle_allocator&) noexcept = default;
  handle_allocator& operator=(const handle_allocator&) noexcept = default;
  template <class U>
  handle_allocator(const std::allocator<U>&) noexcept {}

  VV_INLINE value_type* allocate(std::size_t n) {
    if constexpr (recycles()) {
      const int c = handle_blocks::class_of(n);
      if (c >= 0)
        if (handle_blocks* blocks = Tr::context().handle_blocks())
          if (void* p = blocks->take(c)) return static_cast<value_type*>(p);
    }
    if (n > std::size_t(-1) / sizeof(value_type)) throw std::bad_array_new_length();
    return static_cast<value_type*>(::operator new(n * sizeof(value_type)));
  }
  VV_INLINE void deallocate(value_type* p, std::size_t n) noexcept {
    if constexpr (recycles()) {
      const int c = handle_blocks::class_of(n);
      if (c >= 0)
        if (handle_blocks* blocks = Tr::context().handle_blocks())
          if (blocks->keep(p, c)) return;
    }
    ::operator delete(p);
  }

  friend bool operator==(const handle_allocator&, const handle_allocator&) noexcept { return true; }
  friend bool operator!=(const handle_allocator&, const handle_allocator&) noexcept { return false; }

 private:
  // A function, not a constant: the class is instantiated wherever a
  // vector of handles is declared, in a property struct too, where Tr is
  // not yet complete and would not yet name its context.
  static constexpr bool recycles() noexcept {
    return VV_RECYCLE_HANDLE_BLOCKS && has_default_context<Tr>::value;
  }
};

}  // namespace vv::detail

//! vvlib's std::vector of handles (see the top of this file).
template <class Tr>
class std::vector<vv::vertex<Tr>, std::allocator<vv::vertex<Tr>>>
    : public util::detail::first_room_vector<vv::vertex<Tr>, vv::detail::handle_allocator<Tr>, 4> {
  using base = util::detail::first_room_vector<vv::vertex<Tr>, vv::detail::handle_allocator<Tr>, 4>;

 public:
  // Its own default, copy and move members are the implicit ones.
  using base::base;
  using base::operator=;
};
