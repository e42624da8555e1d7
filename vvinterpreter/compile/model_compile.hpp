// From a translated program to its plugin, in a work folder: compiled whole
// (one compiler run), or compiled with -DVV_DECLARATIONS_APART and linked
// with its declarations' part (declarations_part.hpp). The part comes
// from the cache, or is compiled at the same time as the program, on the
// other core. Whatever goes wrong with the part, the program is compiled
// whole: the result is the same plugin either way.
#pragma once

#include <string>
#include <vector>

#include "compile/process.hpp"

namespace vvi {

struct compile_job {
  //! The compiler and every option but the files (precompiled header,
  //! flags, warnings, the model's folder).
  std::vector<std::string> compiler;
  std::vector<std::string> libraries;  // -L, -l... for the link
  std::string work;                    // holds model.cpp; model.so and model.d are made there
  std::string cache_dir;
  std::string include;                 // vvlib's headers
  std::string declarations;            // the declarations' part, or "" to compile whole
  std::string declarations_key;
  //! No part for the declarations yet: make it now (else compile whole).
  bool make_part = true;
  int niceness = 0;  // of the compiler's processes (build_settings::in_background)
  //! Once set, the program's compiler is stopped and the outcome is
  //! `cancelled` (build_settings::cancel).
  const std::atomic<bool>* cancel = nullptr;
};

struct compile_outcome {
  //! What the compiler said of the program; status 0: work/model.so is made.
  process_result result;
  std::string commands;  // the commands that ran, a line each
  std::string notes;     // a damaged cache entry found and replaced, a line each (no path)
  bool apart = false;    // linked with the declarations' part
};

compile_outcome compile_model(const compile_job& job);

}  // namespace vvi
