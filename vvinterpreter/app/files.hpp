// Small file-system helpers for the host.
#pragma once

#include <optional>
#include <string>

namespace vvi {

std::optional<std::string> read_file(const std::string& path);
//! Writes via a temporary beside path and a rename: readers never see half a file.
bool write_file(const std::string& path, const std::string& text);
//! The folder of a path ("." when it has none), absolute when possible.
std::string folder_of(const std::string& path);
//! The directory holding this executable.
std::string executable_dir();
//! $VV_CACHE_DIR, or $XDG_CACHE_HOME/vv, or ~/.cache/vv.
std::string default_cache_dir();

}  // namespace vvi
