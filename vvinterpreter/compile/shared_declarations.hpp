// Declarations' parts that models in different folders share. vvc names
// the model's file in its #line directives by its path, so the same
// program in two folders (a test suite's scratch folders, copies of an
// example, a sweep's working copies) would compile the same declarations
// twice. The part is compiled with the model's folder in those names
// replaced by a marker folder; a crash report puts the folder of the
// model that ran back in (runner/crash_report.cpp), and so does a run-time
// error's message (runner/session.cpp).
#pragma once

#include <string>

namespace vvi {

//! The folder that stands for the model's own in a shared part's #line
//! names and line tables.
extern const char* const model_folder_marker;

//! The declarations' text with each #line name inside model_dir (an
//! absolute folder, no trailing slash) moved into the marker folder.
std::string declarations_without_folder(const std::string& text, const std::string& model_dir);

//! Whether the compiler could find a header of the declarations in
//! model_dir, which models are compiled with as an include folder (-I): a
//! file of a name the declarations include, or a folder of vvlib's
//! (vv/, util/, algorithms/, model/) there. Such a part is the folder's own.
bool declarations_may_read_folder(const std::string& text, const std::string& model_dir);

//! A file named inside the marker folder, named inside model_dir instead;
//! any other file unchanged.
std::string in_model_folder(const std::string& file, const std::string& model_dir);

//! text (a run-time error's message) with every file named inside the
//! marker folder named inside model_dir instead.
std::string with_model_folder(std::string text, const std::string& model_dir);

//! The folder of the model a plugin in the cache was built from: that of
//! the first .vvp file its translated source (model.cpp, kept beside
//! model.so) names; "" when there is none.
std::string model_folder_of_build(const std::string& plugin);

//! A message of that plugin's model with its files named in the model's
//! folder (with_model_folder); read from the cache only when it names the
//! marker folder.
std::string message_of_build(const std::string& message, const std::string& plugin);

}  // namespace vvi
