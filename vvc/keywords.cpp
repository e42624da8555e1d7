#include "keywords.hpp"

#include <algorithm>
#include <array>

namespace vvc {

const std::vector<vv_word>& vv_words() {
  using r = word_role;
  using e = edit_kind;
  using f = edit_form;
  static const std::vector<vv_word> table = {
      // query      role      reserved then
      {"nextto",   r::query, true,  "in"},
      {"prevto",   r::query, true,  "in"},
      {"valence",  r::query, true},
      {"labelof",  r::query, true},
      {"next",     r::query, false, "to"},  // next(I)to X in V
      {"prev",     r::query, false, "to"},
      {"any",      r::query, false, "in"},  // any in V
      {"flagged",  r::query, false, "in"},
      {"is",       r::query, false, "in"},  // is X in V
      // edit         role     reserved then    or_then   {last  kind            or_kind       flag may be  list}
      {"make",        r::edit, false, "nb_of", "",      {"",   e::make,        e::make,         f::nowhere, true}},
      {"erase",       r::edit, false, "from",  "",      {"",   e::erase,       e::erase,        f::first}},
      {"remove",      r::edit, false, "from",  "",      {"",   e::remove,      e::remove}},
      {"replace",     r::edit, false, "with",  "",      {"in", e::replace,     e::replace,      f::first}},
      {"merge",       r::edit, false, "with",  "",      {"",   e::merge,       e::merge}},
      {"splice",      r::edit, false, "after", "before", {"in", e::splice_after, e::splice_before, f::second}},
      {"flag",        r::edit, false, "in",    "",      {"",   e::flag,        e::flag}},
      {"add",         r::edit, false, "to",    "",      {"",   e::add,         e::add}},
      {"clear",       r::edit, false, "",      "",      {"",   e::clear,       e::clear}},
      {"synchronise", r::edit, true,  "",      "",      {"",   e::synchronise, e::synchronise}},
      {"synchronize", r::edit, true,  "",      "",      {"",   e::synchronise, e::synchronise}},
      {"forall",      r::loop, true,  "in"},
      {"in", r::connective},
      {"to", r::connective},
      {"from", r::connective},
      {"with", r::connective},
      {"nb_of", r::connective, true},
      {"edge", r::property_block},
      {"vertex", r::property_block, true},
      {"mesh", r::property_block, true},
      {"start", r::execution_block},
      {"step", r::execution_block},
      {"end", r::execution_block},
      {"close", r::execution_block},
      {"render_init", r::execution_block},
      {"render", r::execution_block},
      {"render_screen", r::execution_block},
      {"param", r::parameter},
      {"action", r::action},
      {"key", r::action_key},
      {"pick", r::pick},
      {"next", r::path_step},
      {"prev", r::path_step},
      {"swap", r::path_step},
  };
  return table;
}

edit_kind with_flag_operand(edit_kind k) {
  switch (k) {
    case edit_kind::erase: return edit_kind::erase_flag;
    case edit_kind::replace: return edit_kind::replace_flag;
    case edit_kind::splice_after: return edit_kind::splice_after_flag;
    case edit_kind::splice_before: return edit_kind::splice_before_flag;
    default: return k;
  }
}

const vv_word* find_word(std::string_view w, word_role role) {
  for (const vv_word& v : vv_words())
    if (v.role == role && v.text == w) return &v;
  return nullptr;
}

bool is_reserved_vv_word(std::string_view w) {
  for (const vv_word& v : vv_words())
    if (v.reserved && v.text == w) return true;
  return false;
}

std::vector<std::string_view> execution_block_names() {
  std::vector<std::string_view> names;
  for (const vv_word& v : vv_words())
    if (v.role == word_role::execution_block) names.push_back(v.text);
  return names;
}

int property_block_index(std::string_view w) {
  int i = 0;
  for (const vv_word& v : vv_words()) {
    if (v.role != word_role::property_block) continue;
    if (v.text == w) return i;
    ++i;
  }
  return -1;
}

std::string_view property_block_word(int i) {
  for (const vv_word& v : vv_words())
    if (v.role == word_role::property_block && i-- == 0) return v.text;
  return {};
}

bool is_cxx_expression_keyword(std::string_view w) {
  static constexpr std::array<std::string_view, 27> words = {
      "return",   "if",       "while",    "for",    "switch",  "case",     "throw",
      "sizeof",   "alignof",  "decltype", "typeid", "new",     "delete",   "co_return",
      "co_await", "co_yield", "not",      "and",    "or",      "xor",      "bitand",
      "bitor",    "compl",    "noexcept", "static_assert",     "else",     "do"};
  return std::find(words.begin(), words.end(), w) != words.end();
}

bool expression_follows(std::string_view w) {
  return is_cxx_expression_keyword(w) || has_role(w, word_role::connective);
}

bool is_plain_name(const token& t) {
  return t.is_identifier() && !expression_follows(t.text) && !is_reserved_vv_word(t.text);
}

bool is_prefix_operator(const token& t) {
  if (t.kind != tok::punct) return false;
  for (std::string_view op : {"!", "~", "-", "+", "*", "&", "++", "--"})
    if (t.text == op) return true;
  return false;
}

bool is_token(const piece& p, std::string_view text) {
  return p.kind == piece_kind::token && p.tok->text == text &&
         (p.tok->kind == tok::punct || p.tok->kind == tok::identifier);
}

bool is_group(const piece& p, std::string_view open) { return p.kind == piece_kind::group && p.tok->text == open; }

bool ends_operand(const pieces& run) { return ends_operand(run, run.size()); }

bool ends_operand(const pieces& run, std::size_t n) {
  if (n == 0) return false;
  const piece& p = run[n - 1];
  switch (p.kind) {
    case piece_kind::token:
      switch (p.tok->kind) {
        case tok::identifier:
          return is_plain_name(*p.tok);
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
