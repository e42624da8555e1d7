// One model file, however its path is typed. `examples/x.vvp`, `./x.vvp`,
// an absolute path, a path through `..` or through a symbolic link to the
// folder are one file and must share one cache entry, so a build uses one
// spelling of the path (its folder resolved) for everything that goes into
// the plugin: the #line names, the model's folder, the line tables. Messages
// go back to the spelling the user typed.
//
// A symbolic link to the file itself is the same model when the file it
// names lies in the same folder; a link in another folder makes that
// folder the model's folder (what the program includes and reads is
// looked up there), so it is a model of its own.
#pragma once

#include <string>

namespace vvi {

class model_path {
 public:
  explicit model_path(const std::string& typed);

  const std::string& typed() const { return typed_; }
  //! The spelling builds use: the folder resolved (absolute, no `.`, `..`
  //! or links), the file name kept unless it links to a file beside it.
  //! The typed path itself when that folder cannot be resolved.
  const std::string& built() const { return built_; }
  //! A path in the built spelling (a source the translator or the compiler
  //! names) in the typed one; any other path unchanged.
  std::string shown(const std::string& path) const;
  //! `text` with the path that starts each line ("f:12:3: error: ...",
  //! "f: In function ...") shown as above.
  std::string shown_in(const std::string& text) const;

 private:
  std::string typed_, built_;
  std::string typed_folder_, built_folder_;  // folder_of each ("" for a bare name)
};

}  // namespace vvi
