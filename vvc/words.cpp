#include "words.hpp"

#include <algorithm>
#include <array>

namespace vvc {

namespace {
template <std::size_t N>
bool in(const std::array<std::string_view, N>& list, std::string_view w) {
  return std::find(list.begin(), list.end(), w) != list.end();
}
}  // namespace

bool is_expression_keyword(std::string_view w) {
  static constexpr std::array<std::string_view, 32> words = {
      "return",    "if",        "while",     "for",      "switch",       "case",     "throw",
      "sizeof",    "alignof",   "decltype",  "typeid",   "new",          "delete",   "co_return",
      "co_await",  "co_yield",  "not",       "and",      "or",           "xor",      "bitand",
      "bitor",     "compl",     "noexcept",  "static_assert", "else",    "do",       "in",
      "to",        "from",      "with",      "nb_of"};
  return in(words, w);
}

bool is_reserved_vv_word(std::string_view w) {
  static constexpr std::array<std::string_view, 10> words = {
      "nextto", "prevto", "valence", "labelof", "forall", "nb_of", "synchronise", "synchronize",
      "vertex", "mesh"};
  return in(words, w);
}

bool is_block_name(std::string_view w) {
  static constexpr std::array<std::string_view, 7> words = {
      "start", "step", "end", "close", "render_init", "render", "render_screen"};
  return in(words, w);
}

bool is_token(const piece& p, std::string_view text) {
  return p.kind == piece_kind::token && p.tok->text == text &&
         (p.tok->kind == tok::punct || p.tok->kind == tok::identifier);
}

bool ends_operand(const pieces& run) { return ends_operand(run, run.size()); }

bool ends_operand(const pieces& run, std::size_t n) {
  if (n == 0) return false;
  const piece& p = run[n - 1];
  switch (p.kind) {
    case piece_kind::token:
      switch (p.tok->kind) {
        case tok::identifier:
          return !is_expression_keyword(p.tok->text) && !is_reserved_vv_word(p.tok->text);
        case tok::number:
        case tok::string:
        case tok::character:
          return true;
        default:
          return false;
      }
    case piece_kind::group:
      return p.tok->text == "(" || p.tok->text == "[";
    case piece_kind::body:
    case piece_kind::class_body:
      return false;
    default:  // vv expressions are operands
      return true;
  }
}

}  // namespace vvc
