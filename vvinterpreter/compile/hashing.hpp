// A 128-bit content hash (two FNV-1a streams) for cache keys: collisions
// between different models' builds are not a practical concern.
#pragma once

#include <cstdint>
#include <cstdio>
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

}  // namespace vvi
