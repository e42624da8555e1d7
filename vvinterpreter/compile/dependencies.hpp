// The files a compiled build read besides vvlib's and the system's (the
// model's own headers), with their content hashes: a cached build is good
// only while they are unchanged.
#pragma once

#include <string>
#include <vector>

namespace vvi {

//! From the compiler's make-style dependency file (-MD -MF): one line
//! "HASH PATH" per header of the model's own (not under `include`, not
//! under /usr/, not in the model cache `cache_dir`, whose entries are
//! checked by their own manifests, not the compiled source itself).
std::string dependency_list(const std::string& depfile, const std::string& include,
                            const std::string& cache_dir = "");

//! Whether every file of the list still has its hash.
bool dependencies_unchanged(const std::string& list);

//! The paths of the list.
std::vector<std::string> dependency_paths(const std::string& list);

}  // namespace vvi
