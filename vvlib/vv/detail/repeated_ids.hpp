// Whether a short `make` list names a vertex twice, without a branch per
// pair of entries. The ids (up to eight slots, 0 past the list's end) are
// compared with rotations of each other: two rotations cover the six pairs
// within four lanes, four rotations the sixteen pairs across two groups.
// A branch per pair mispredicted about once per six-entry list.
#pragma once

#include <cstddef>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "inline.hpp"

namespace vv::detail {

//! The most ids repeats_among takes.
inline constexpr std::size_t repeat_check_lanes = 8;

//! True when two of ids[0..n) are equal. ids holds eight readable ids, 0
//! from n on; no listed id is 0 (slot 0 is the null vertex, refused first).
VV_INLINE bool repeats_among(const std::uint32_t* ids, std::size_t n) noexcept {
  if (n <= 2) return n == 2 && ids[0] == ids[1];
#if defined(__SSE2__)
  const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(ids));
  const __m128i zero = _mm_setzero_si128();
  // Lane i against lane i+1 and i+2 (mod 4): every pair of the four.
  __m128i in_a = _mm_or_si128(_mm_cmpeq_epi32(a, _mm_shuffle_epi32(a, _MM_SHUFFLE(0, 3, 2, 1))),
                              _mm_cmpeq_epi32(a, _mm_shuffle_epi32(a, _MM_SHUFFLE(1, 0, 3, 2))));
  __m128i in_b = zero;
  if (n > 4) {
    const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(ids + 4));
    in_b = _mm_or_si128(_mm_cmpeq_epi32(b, _mm_shuffle_epi32(b, _MM_SHUFFLE(0, 3, 2, 1))),
                        _mm_cmpeq_epi32(b, _mm_shuffle_epi32(b, _MM_SHUFFLE(1, 0, 3, 2))));
    // Every lane of the first four against every lane of the last four.
    in_a = _mm_or_si128(in_a, _mm_or_si128(_mm_cmpeq_epi32(a, b),
                                           _mm_cmpeq_epi32(a, _mm_shuffle_epi32(b, _MM_SHUFFLE(0, 3, 2, 1)))));
    in_a = _mm_or_si128(in_a, _mm_or_si128(_mm_cmpeq_epi32(a, _mm_shuffle_epi32(b, _MM_SHUFFLE(1, 0, 3, 2))),
                                           _mm_cmpeq_epi32(a, _mm_shuffle_epi32(b, _MM_SHUFFLE(2, 1, 0, 3)))));
    // The padding lanes (0) equal each other: only a listed id's match counts.
    in_b = _mm_andnot_si128(_mm_cmpeq_epi32(b, zero), in_b);
  }
  in_a = _mm_andnot_si128(_mm_cmpeq_epi32(a, zero), in_a);
  return _mm_movemask_epi8(_mm_or_si128(in_a, in_b)) != 0;
#else
  for (std::size_t i = 1; i < n; ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (ids[i] == ids[j]) return true;
  return false;
#endif
}

}  // namespace vv::detail
