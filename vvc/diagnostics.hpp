// Error reporting: every message is "file:line:col: error: message",
// followed by the source line and a caret under the column.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "token.hpp"

namespace vvc {

struct diagnostic {
  const source_file* file;
  int line, col;
  std::string message;
};

class diagnostics {
 public:
  void error(const token& at, std::string message);
  void error(const source_file* file, int line, int col, std::string message);
  bool any() const { return !list_.empty(); }
  std::size_t count() const { return list_.size(); }
  const std::vector<diagnostic>& list() const { return list_; }
  //! Writes every diagnostic in the order found.
  void print(std::ostream& os) const;
  //! Too many errors: later ones are dropped and translation gives up.
  bool saturated() const { return list_.size() >= limit; }

  //! Speculative parsing (lookahead by parsing): between hold() and
  //! release(), errors are counted, not kept. release() says whether any
  //! came. Holds nest.
  void hold() { held_from_.push_back(held_); }
  bool release() {
    bool any = held_ > held_from_.back();
    held_from_.pop_back();
    if (held_from_.empty()) held_ = 0;
    return any;
  }

  static constexpr std::size_t limit = 25;

 private:
  // Kept in source order (files in the order they first had an error), so
  // the first message is the first problem even when it is found last (an
  // unterminated block is noticed at the end of the file).
  std::size_t file_rank(const source_file* f);
  std::vector<diagnostic> list_;
  std::size_t held_ = 0;                // errors since the outermost hold()
  std::vector<std::size_t> held_from_;  // held_ at each open hold()
  std::vector<const source_file*> files_;
};

//! The most characters of a source line a diagnostic shows.
constexpr std::size_t max_shown_columns = 200;

//! One diagnostic as text (with its source line and caret; of a longer
//! line, the max_shown_columns around the caret).
std::string format(const diagnostic& d);

}  // namespace vvc
