// Source files held in memory for the whole translation: tokens and
// diagnostics refer into them by pointer, so they never move.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace vvc {

struct source_file {
  std::string path;
  std::string text;  // with LF line ends: CR LF and a lone CR became LF
  std::vector<std::size_t> line_starts;  // offset of each line's first byte

  source_file(std::string p, std::string t);
  //! Line n (1-based) without its newline.
  std::string_view line(int n) const;
  //! The folder of path as written ("" for a bare name): vv::io::folder_of.
  std::string folder() const;
};

class source_set {
 public:
  //! Reads a regular file of at most vv::io::program_file_limit (a
  //! generated program can be big, but not without bound), without a
  //! leading UTF-8 byte-order mark; nullptr (and *why set) when it cannot
  //! be read.
  const source_file* load(const std::string& path, std::string* why);
  //! Adds text under a name (tests, fuzzing, standard input).
  const source_file* add(std::string path, std::string text);
  //! The paths of every file read, in order.
  std::vector<std::string> paths() const;
  //! A hash of the text of every file read, in order (32 hex digits): a
  //! checkpoint is only resumed by the program it was saved from.
  std::string text_hash() const;

 private:
  std::vector<std::unique_ptr<source_file>> files_;
};

}  // namespace vvc
