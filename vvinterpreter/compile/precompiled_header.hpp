// The precompiled model/model.hpp every model includes first: built
// once per cache and set of compiler flags (a few seconds), in the cache's
// pch/ folder (model_cache.hpp), and checked before each use.
#pragma once

#include <string>
#include <vector>

namespace vvi {

struct header_request {
  std::string cache_dir;           // holds pch/
  std::string include;             // vvlib's headers
  std::vector<std::string> flags;  // the flags models are compiled with (they must match)
  std::string key;                 // a hash of the compiler, the flags and the headers
};

//! The folder to put first on the include path (it holds
//! model/model.hpp.gch), built when the cache has no sound one. ""
//! when it cannot be built (`error` says why; models then compile without
//! it). `damage` says why a cached one was found broken and rebuilt, or "".
std::string precompiled_header_dir(const header_request& request, std::string& damage, std::string& error);

//! Removes a build of the header the compiler could not read, so that the
//! next precompiled_header_dir builds it afresh.
void discard_precompiled_header(const std::string& dir);

//! Whether the compiler's output says it could not read a precompiled header.
bool unreadable_precompiled_header(const std::string& compiler_output);

}  // namespace vvi
