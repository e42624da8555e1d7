// Which model files a cache has compiled before, so that a batch run knows
// a new model from an edited one. A model's declarations' part
// (declarations_part.hpp) pays off from its first edit on; compiled
// beside a model that is never edited, it costs half as much again as
// compiling the model whole. The viewer, which is there for editing,
// compiles the part from the first build; batch runs and --compile-only
// make it with a new file's first build only on an idle core
// (build_cores.hpp), and otherwise once the file has changed.
//
// A file is remembered, under a hash of its folder, its name and the
// compiler's options, as an empty file in the cache's built/ folder.
#pragma once

#include <string>

namespace vvi {

//! Whether this cache compiled the model `identity` names before (a hash
//! of the file's folder, its name and the compiler's options).
bool compiled_before(const std::string& cache_dir, const std::string& identity);

//! Remembers that the model `identity` names was compiled. A cache that
//! cannot be written only forgets it: the next build compiles whole again.
void remember_compiled(const std::string& cache_dir, const std::string& identity);

}  // namespace vvi
