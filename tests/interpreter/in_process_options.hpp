// The options of an in-process test's model build: the model from the
// suite's cache, built as a batch run of the suite builds it (at $VV_OPT's
// level, which the sanitizer run sets to 0; compiled whole on a busy
// machine), not as a viewer's build, which makes the declarations' part
// for edits that never come.
#pragma once

#include <cstdlib>
#include <string>

#include "app/options.hpp"

inline vvi::options in_process_options(const std::string& model) {
  vvi::options o;
  o.model = model;
  o.cache = VV_TEST_CACHE;
  o.batch = true;
  if (const char* level = std::getenv("VV_OPT"); level && *level) o.optimization = std::atoi(level);
  return o;
}
