// The model cache's folders (plugins/ and pch/) hold finished builds, each
// in a folder of its own named KEY.ID, and a symbolic link KEY naming the
// newest build of each key. A build is made in a work folder tmp-KEY-ID,
// ends with a manifest (the size, and for all but the 100 MB precompiled
// header a checksum, of each file it made), is renamed to KEY.ID and then published: the link is
// switched to it in one rename. So a reader sees a whole build or none;
// what it finds is checked against the manifest before it is used; and a
// killed build leaves only folders whose names say what they are, which the
// next build removes once they are old.
//
// IDs are random: processes in different PID namespaces (containers)
// sharing one cache never pick the same name.
#pragma once

#include <chrono>
#include <string>
#include <vector>

namespace vvi::cache {

//! A name no other process picks (128 random bits, in hex).
std::string unique_id();

//! How a file of a build is checked before use.
enum class check { size, content };
struct listed_file {
  std::string name;  // in the build's folder
  check how;
};

//! Writes `dir`/manifest for these files (false if one cannot be read or
//! the manifest cannot be written). Call it last, when the files are done.
bool write_manifest(const std::string& dir, const std::vector<listed_file>& files);

enum class verdict {
  good,      // every file the manifest lists is as it was written
  unlisted,  // no manifest: a build of an older interpreter (not damage)
  damaged,   // a listed file is missing or differs (`why` says how)
};
verdict verify(const std::string& dir, std::string& why);

//! Makes `folder`/`key` name the build `folder`/`build` (a sibling), in one
//! rename. An older cache's real folder under the key's name is replaced.
void publish(const std::string& folder, const std::string& key, const std::string& build);

//! A new work folder tmp-KEY-ID in `folder` (made, with `folder`, if need
//! be; old leftovers there removed first), or "" when it cannot be made.
std::string new_work_folder(const std::string& folder, const std::string& key);

//! Ends a build made in `work`: its manifest of `files`, then the folder
//! renamed to `folder`/KEY.ID and published under the key. False when
//! that fails (the work folder is then the caller's to remove).
bool store(const std::string& folder, const std::string& work, const std::string& key,
           const std::vector<listed_file>& files);

//! How old a leftover must be before the next build removes it: far more
//! than any build takes, so a build in progress elsewhere is never touched.
inline constexpr std::chrono::seconds leftover_age{3600};

//! Removes, from `folder`, what builds that never finished left (work
//! folders, links being made) and builds no key names any more, once they
//! are older than `age`.
void remove_leftovers(const std::string& folder, std::chrono::seconds age = leftover_age);

//! Held while one key is looked up and built: builds of the same key (two
//! tests, two sweeps, a viewer and a batch run) wait for each other, so the
//! second finds the first's build instead of compiling it again. The lock
//! is the file `folder`/lock-KEY under flock(2): the kernel releases it when
//! its holder dies, so a killed build never blocks the next. Without the
//! file (a read-only cache) builds go on unlocked, as before.
class build_lock {
 public:
  build_lock(const std::string& folder, const std::string& key);
  ~build_lock();
  build_lock(const build_lock&) = delete;
  build_lock& operator=(const build_lock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace vvi::cache
