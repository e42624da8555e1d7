// Checks inside test programs (.vvp): each records a failure with the
// program's file and line (through vvc's #line directives) instead of
// stopping, so one run reports every failed expectation.
#pragma once

#include <iostream>
#include <sstream>
#include <string>

namespace vv_check {

inline int checks = 0;
inline int failures = 0;

inline void fail(const char* file, int line, const std::string& what) {
  ++failures;
  std::cerr << file << ":" << line << ": check failed: " << what << "\n";
}

template <class A, class B>
void equal(const A& a, const B& b, const char* as, const char* bs, const char* file, int line) {
  ++checks;
  if (a == b) return;
  std::ostringstream os;
  os << as << " == " << bs << " (" << a << " vs " << b << ")";
  fail(file, line, os.str());
}

}  // namespace vv_check

#define CHECK(cond) \
  (++vv_check::checks, (cond) ? void() : vv_check::fail(__FILE__, __LINE__, #cond))
#define CHECK_EQ(a, b) vv_check::equal((a), (b), #a, #b, __FILE__, __LINE__)
