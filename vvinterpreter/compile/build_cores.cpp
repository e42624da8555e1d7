#include "compile/build_cores.hpp"

#include <sched.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace vvi {

unsigned idle_cores_for_a_build(unsigned limit) {
  cpu_set_t set;
  CPU_ZERO(&set);
  long usable = sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : 1;
  double load = 0;
  if (getloadavg(&load, 1) != 1) load = 0;  // unknown: as if idle
  // Rounded: this very process and a short-lived neighbour are no one's
  // whole core.
  long idle = std::max(1L, usable - std::lround(load));
  return limit == 0 ? static_cast<unsigned>(idle) : std::min(limit, static_cast<unsigned>(idle));
}

}  // namespace vvi
