// The compiler the host compiles models with is the one it was built with,
// and so the one these tests were built with. g++ and clang word their
// messages differently; the tests expect the words of the one in use.
#pragma once

#include <string>

namespace model_compiler {

#ifdef __clang__
inline constexpr bool clang = true;
#else
inline constexpr bool clang = false;
#endif

//! The line g++ puts before the first message about a function (clang has none).
inline std::string in_function(const std::string& file, const std::string& function = "void vv_block_start()") {
  return clang ? "" : file + ": In function '" + function + "':\n";
}

//! The file of the precompiled vvlib header of optimised builds.
inline const char* const precompiled_header = clang ? "model.hpp.pch" : "model.hpp.gch";

}  // namespace model_compiler
