#include "spelling.hpp"

#include <algorithm>
#include <array>

namespace vvc {

namespace {

// Longer than any vv word by more than a misspelling's edits.
constexpr std::size_t max_word = 20;

}  // namespace

std::size_t edit_distance(std::string_view a, std::string_view b, std::size_t limit) {
  const std::size_t n = a.size(), m = b.size();
  if ((n > m ? n - m : m - n) > limit) return limit + 1;
  if (m >= max_word) return limit + 1;  // no vv word is that long
  // Three rows of the table: d[i][j] is the distance of a[0, i) and b[0, j).
  std::size_t rows[3][max_word];
  std::size_t *before = rows[0], *previous = rows[1], *row = rows[2];
  for (std::size_t j = 0; j <= m; ++j) previous[j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    row[0] = i;
    std::size_t smallest = row[0];
    for (std::size_t j = 1; j <= m; ++j) {
      std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      row[j] = std::min({previous[j] + 1, row[j - 1] + 1, previous[j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        row[j] = std::min(row[j], before[j - 2] + 1);
      smallest = std::min(smallest, row[j]);
    }
    // Every later row costs at least this row's least, less nothing: stop.
    if (smallest > limit) return limit + 1;
    std::size_t* spare = before;
    before = previous;
    previous = row;
    row = spare;
  }
  return std::min(previous[m], limit + 1);
}

std::size_t misspelling_edits(std::string_view word) { return word.size() <= 4 ? 1 : 2; }

const vv_word* misspelt_vv_word(std::string_view name, const std::function<bool(const vv_word&)>& fits) {
  if (name.size() < 2 || name.size() + 2 >= max_word) return nullptr;
  for (const vv_word& w : vv_words())
    if (w.text == name) return nullptr;  // a vv word is no misspelling
  const vv_word* best = nullptr;
  std::size_t best_edits = 0;
  for (const vv_word& w : vv_words()) {
    std::size_t limit = misspelling_edits(w.text);
    if (best) limit = std::min(limit, best_edits - 1);  // only a nearer word replaces the best
    std::size_t edits = edit_distance(w.text, name, limit);
    if (edits > limit || !fits(w)) continue;
    best = &w;
    best_edits = edits;
  }
  return best && !is_cxx_keyword(name) ? best : nullptr;
}

bool is_cxx_keyword(std::string_view w) {
  // Sorted, for a binary search.
  static constexpr std::array<std::string_view, 97> words = {
      "_Pragma",      "alignas",     "alignof",          "and",           "and_eq",      "asm",
      "auto",         "bitand",      "bitor",            "bool",          "break",       "case",
      "catch",        "char",        "char16_t",         "char32_t",      "char8_t",     "class",
      "co_await",     "co_return",   "co_yield",         "compl",         "concept",     "const",
      "const_cast",   "consteval",   "constexpr",        "constinit",     "continue",    "decltype",
      "default",      "delete",      "do",               "double",        "dynamic_cast", "else",
      "enum",         "explicit",    "export",           "extern",        "false",       "final",
      "float",        "for",         "friend",           "goto",          "if",          "import",
      "inline",       "int",         "long",             "module",        "mutable",     "namespace",
      "new",          "noexcept",    "not",              "not_eq",        "nullptr",     "operator",
      "or",           "or_eq",       "override",         "private",       "protected",   "public",
      "register",     "reinterpret_cast", "requires",    "return",        "short",       "signed",
      "sizeof",       "static",      "static_assert",    "static_cast",   "struct",      "switch",
      "template",     "this",        "thread_local",     "throw",         "true",        "try",
      "typedef",      "typeid",      "typename",         "union",         "unsigned",    "using",
      "virtual",      "void",        "volatile",         "wchar_t",       "while",       "xor",
      "xor_eq"};
  return std::binary_search(words.begin(), words.end(), w);
}

}  // namespace vvc
