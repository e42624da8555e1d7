// Small file-system helpers for the host.
#pragma once

#include <string>

#include <vv/io/files.hpp>

namespace vvi {

// Reading a file and the folder of a path: vvlib's, shared with vvc.
using vv::io::read_file;
using vv::io::absolute_folder_of;

//! Writes via a temporary beside path and a rename: readers never see half a file.
bool write_file(const std::string& path, const std::string& text);
//! The directory holding this executable.
std::string executable_dir();
//! $VV_CACHE_DIR, or $XDG_CACHE_HOME/vv, or ~/.cache/vv.
std::string default_cache_dir();
//! The path made absolute and normal (no "." or ".."); as given if that fails.
std::string absolute_path(const std::string& path);

}  // namespace vvi
