// What a compiled object file defines, read from its ELF symbol table: the
// model cache links a model's declarations' part (compiled once) into
// every build of the model, which is sound only when that part holds no
// state of its own and defines nothing the program defines too.
#pragma once

#include <string>

namespace vvi {

//! "" when the object at `path` defines, besides what may be merged with
//! other copies (weak and unique symbols: inline functions, templates,
//! their static variables), only read-only data, functions of its own and
//! global functions whose names start with `allowed_prefix`. Otherwise
//! what else it defines, in a few words: a global symbol ("defines the
//! global symbol _Z7counter"), writable data of its own (a static
//! variable), a dynamic initialisation, or why the file cannot be read.
std::string definitions_beyond(const std::string& path, const std::string& allowed_prefix);

}  // namespace vvi
