// Generated C++ compared without its layout: the translator's unit tests
// check what it emits, not how it is spaced.
#pragma once

#include <algorithm>
#include <cctype>
#include <string>

//! s without its white space.
inline std::string squeeze(std::string s) {
  s.erase(std::remove_if(s.begin(), s.end(), [](unsigned char c) { return std::isspace(c); }), s.end());
  return s;
}
