#pragma once
#include "bench_result.hpp"

#include <string>

// Empty if both results have the same V and F counts and the same vertex
// positions as a point set (within `tolerance` per coordinate); otherwise a
// short reason. Both results need their positions.
std::string compare_results(const bench_result& a, const bench_result& b, double tolerance);
