// Whether a text starts or ends with another (C++17 has no such members).
#pragma once

#include <string>

namespace vvi {

inline bool starts_with(const std::string& s, const std::string& head) { return s.rfind(head, 0) == 0; }

inline bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

}  // namespace vvi
