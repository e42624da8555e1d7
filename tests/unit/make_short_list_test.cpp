// `make` of a short list without half-edge records (vv/edits.hpp: up to
// eight entries, checked for repeats by comparing rotations of the ids,
// vv/detail/repeated_ids.hpp, and copied into the inline storage whole).
// Every length up to and past the short lists', every pair of positions
// repeated, with inline capacities below, at and above the list: the list
// is set in order, or refused naming the repeated vertex with the
// neighbourhood as it was.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <vv/vv.hpp>
#include <vv/detail/repeated_ids.hpp>

#include "test_meshes.hpp"

// A namespace of its own: the algebra tests are built as one unity source.
namespace make_short_list {

struct props {
  int index = -1;
};
using plain = vv::traits<props>;  // six inline
using capacity_three = vv::traits<props, vv::no_props, vv::no_props, 3>;
using capacity_eight = vv::traits<props, vv::no_props, vv::no_props, 8>;
using capacity_twelve = vv::traits<props, vv::no_props, vv::no_props, 12>;

// Some context and some vertices, with the neighbourhood `before` on hub.
template <class Tr>
struct scene {
  vv::context<Tr> ctx;
  vv::vertex<Tr> hub = ctx.new_vertex();
  std::vector<vv::vertex<Tr>> others;
  std::vector<vv::vertex<Tr>> before;

  explicit scene(std::size_t count, std::size_t before_count) {
    for (std::size_t i = 0; i < count; ++i) {
      others.push_back(ctx.new_vertex());
      others.back()->index = int(i);
    }
    // The old neighbourhood: vertices of their own, so a refused make can
    // be told from a partial one.
    for (std::size_t i = 0; i < before_count; ++i) before.push_back(ctx.new_vertex());
    if (!before.empty()) vv::make_nb_from(hub, before);
  }
};

template <class Tr>
std::vector<vv::vertex<Tr>> neighbours(const vv::vertex<Tr>& v) {
  std::vector<vv::vertex<Tr>> out;
  if (vv::valence(v) == 0) return out;
  vv::vertex<Tr> first = vv::any_in(v), x = first;
  do {
    out.push_back(x);
    x = vv::next_to(x, v);
  } while (x != first);
  return out;
}

template <class Tr>
void check_every_length_and_repeat(std::size_t longest) {
  for (std::size_t n = 0; n <= longest; ++n) {
    for (std::size_t before_count : {std::size_t(0), std::size_t(2), std::size_t(Tr::inline_valence) + 2}) {
      const std::string what = std::to_string(n) + " entries over " + std::to_string(before_count);
      // Distinct: set in the list's order, the flag cleared.
      {
        scene<Tr> s(n, before_count);
        vv::make_nb_from(s.hub, s.others);
        EXPECT_EQ(vv::valence(s.hub), n) << what;
        if (n > 0) {
          // any_in is the list's first entry; walking gives the order.
          EXPECT_EQ(neighbours(s.hub), s.others) << what;
        }
        for (const auto& b : s.before) EXPECT_FALSE(vv::is_in(b, s.hub)) << what;
      }
      // Entry j repeated at position i: refused, naming it, nothing changed.
      for (std::size_t i = 1; i < n; ++i)
        for (std::size_t j = 0; j < i; ++j) {
          scene<Tr> s(n, before_count);
          std::vector<vv::vertex<Tr>> list = s.others;
          list[i] = list[j];
          const std::string where = what + ", entry " + std::to_string(j) + " again at " + std::to_string(i);
          EXPECT_TRUE(vvtest::throws_vv_error([&] { vv::make_nb_from(s.hub, list); },
                                              {"vertex " + std::to_string(list[j].label()) + " is listed twice"}))
              << where;
          EXPECT_EQ(neighbours(s.hub), s.before) << where;
        }
    }
  }
}

TEST(MakeShortList, EveryLengthIsSetInOrderAndEveryRepeatIsRefused) {
  check_every_length_and_repeat<plain>(vv::detail::repeat_check_lanes + 3);
}

TEST(MakeShortList, InlineCapacitiesBelowAtAndAboveTheShortListsAgree) {
  check_every_length_and_repeat<capacity_three>(vv::detail::repeat_check_lanes + 2);
  check_every_length_and_repeat<capacity_eight>(vv::detail::repeat_check_lanes + 2);
  check_every_length_and_repeat<capacity_twelve>(vv::detail::repeat_check_lanes + 5);
}

// The check itself, on ids that differ only in high bits or in one bit,
// and on the largest slot numbers (no id is 0: that is the padding).
TEST(MakeShortList, RepeatsAmongTellsEveryPairApart) {
  const std::vector<std::uint32_t> pools[] = {
      {1, 2, 3, 4, 5, 6, 7, 8},
      {1u << 31, (1u << 31) | 1, 1u << 30, 3u << 30, 65, 129, 193, 257},
      {0xffffffffu, 0xfffffffeu, 0xfffffffdu, 0x7fffffffu, 0x80000000u, 64, 128, 192}};
  for (const auto& pool : pools)
    for (std::size_t n = 0; n <= vv::detail::repeat_check_lanes; ++n) {
      alignas(16) std::uint32_t ids[vv::detail::repeat_check_lanes] = {};
      for (std::size_t k = 0; k < n; ++k) ids[k] = pool[k];
      EXPECT_FALSE(vv::detail::repeats_among(ids, n)) << n << " distinct ids from " << pool[0];
      for (std::size_t i = 1; i < n; ++i)
        for (std::size_t j = 0; j < i; ++j) {
          alignas(16) std::uint32_t repeated[vv::detail::repeat_check_lanes] = {};
          for (std::size_t k = 0; k < n; ++k) repeated[k] = ids[k];
          repeated[i] = repeated[j];
          EXPECT_TRUE(vv::detail::repeats_among(repeated, n)) << n << " ids, " << j << " again at " << i;
        }
    }
}

}  // namespace make_short_list
