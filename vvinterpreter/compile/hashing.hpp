// A 128-bit content hash (two FNV-1a streams) for cache keys: collisions
// between different models' builds are not a practical concern. And a
// checksum for the files of a cached build, eight bytes a step.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>

namespace vvi {

class content_hash {
 public:
  content_hash& add(std::string_view s) {
    for (unsigned char c : s) {
      a_ = (a_ ^ c) * 0x100000001b3ULL;
      b_ = (b_ ^ c) * 0x100000001b3ULL + 0x9e3779b97f4a7c15ULL;
    }
    // A separator, so ("ab", "c") and ("a", "bc") differ.
    a_ = (a_ ^ 0xffu) * 0x100000001b3ULL;
    b_ = (b_ ^ 0xfeu) * 0x100000001b3ULL;
    return *this;
  }
  std::string hex() const {
    char out[33];
    std::snprintf(out, sizeof out, "%016llx%016llx", static_cast<unsigned long long>(a_),
                  static_cast<unsigned long long>(b_));
    return out;
  }

 private:
  std::uint64_t a_ = 0xcbf29ce484222325ULL;
  std::uint64_t b_ = 0x84222325cbf29ce4ULL;
};

//! A 128-bit checksum of a file's bytes, to tell a damaged file from the
//! one that was written. It is read on every start of a cached model (a
//! plugin is about 1 MB), so it takes eight bytes a step in two
//! independent lanes: about a tenth of the time of content_hash.
inline std::string checksum(std::string_view bytes) {
  constexpr std::uint64_t p1 = 0x9e3779b185ebca87ULL, p2 = 0xc2b2ae3d27d4eb4fULL;
  auto round = [](std::uint64_t acc, std::uint64_t word) {
    acc += word * p2;
    acc = (acc << 31) | (acc >> 33);
    return acc * p1;
  };
  auto finish = [](std::uint64_t h) {
    h ^= h >> 33;
    h *= p2;
    h ^= h >> 29;
    h *= p1;
    return h ^ (h >> 32);
  };
  std::uint64_t a = 0x6a09e667f3bcc908ULL + bytes.size(), b = 0xbb67ae8584caa73bULL;
  std::size_t i = 0;
  for (; i + 16 <= bytes.size(); i += 16) {
    std::uint64_t w1, w2;
    std::memcpy(&w1, bytes.data() + i, 8);
    std::memcpy(&w2, bytes.data() + i + 8, 8);
    a = round(a, w1);
    b = round(b, w2);
  }
  for (; i < bytes.size(); ++i) a = round(a, static_cast<unsigned char>(bytes[i]));
  char out[33];
  std::snprintf(out, sizeof out, "%016llx%016llx", static_cast<unsigned long long>(finish(a ^ (b * p1))),
                static_cast<unsigned long long>(finish(b ^ a)));
  return out;
}

}  // namespace vvi
