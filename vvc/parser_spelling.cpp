// Misspelt vv words: "unknown word 'nexto'; did you mean 'nextto'?".
//
// Without this, `nexto u in v` reaches the C++ compiler, which suggests
// some name of its own (`nextup`). A name is taken for a misspelt vv word
// only where C++ could not use a name, so that no valid program is ever
// refused:
//
//  1. a name, a connective and an operand: `ani in v`, `eras from v`
//     (three names in a row are no C++);
//  2. a name, an operand, and the connective that a vv word takes after
//     its operand: `nexto u in v`, `eras x from v;`, `replce a with b in
//     v;`, `nxt(1) to u in v`, `mak {a, b} nb_of v;` (an operand followed by
//     a name is no C++; in 1 and 2 the connective must not be a word that
//     ends the sequence, as `in` ends a parameter's value);
//  3. after an operator that an expression must follow (`=`, `return`,
//     `+`, `&&`, ...), a name and a name or literal: `n = valance v`;
//  4. at a statement start, `synchronis M;` or `clera M;`, which C++ reads
//     as declaring M of type `synchronis`: only when M is declared as a
//     mesh or a vertex elsewhere in the program, the misspelt name appears
//     nowhere but in this shape, and the program includes no header of its
//     own (so it can name no type of the program's);
//  5. at the top level, a name followed by `{`: `stpe {`, `vertx {`.
//
// Nearness: misspelt_vv_word (spelling.hpp). The vv word must also fit the
// place: in 1 and 2, a word taking that connective; in 3, valence or
// labelof; in 4, clear or synchronise; in 5, a block name.
#include <algorithm>

#include "keywords.hpp"
#include "parser.hpp"
#include "spelling.hpp"

namespace vvc {

namespace {

std::string unknown_word(const token& name, const vv_word& meant) {
  return "unknown word '" + std::string(name.text) + "'; did you mean '" + std::string(meant.text) + "'?";
}

// Tokens after which only an expression may come: a name there starts one,
// and `W x` (two names) cannot be C++. (Not `(`, `,`, `<`, `>`, `*`, `&`
// or `:`, after which C++ may declare: `f(Type x)`, `template <Type x>`.)
bool expression_must_follow(const token& t) {
  if (t.is_word("return")) return true;
  if (t.kind != tok::punct) return false;
  static constexpr std::string_view ops[] = {"=",  "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=",
                                             ">>=", "==", "!=", "<=", ">=", "&&", "||", "!",  "+",  "-",
                                             "/",  "%",  "|",  "^",  "?",  "<<"};
  return std::find(std::begin(ops), std::end(ops), t.text) != std::end(ops);
}

// A token that starts an operand and could not follow a name in C++: a
// name (no C++ keyword), a number, a backtick or a path's `@`.
bool starts_operand_after_a_name(const token& t) {
  switch (t.kind) {
    case tok::identifier:
      return !is_cxx_keyword(t.text) && !has_role(t.text, word_role::connective);
    case tok::number:
    case tok::backtick:
    case tok::at:
      return true;
    default:
      return false;
  }
}

// The words some vv word takes after its first operand.
bool is_then_word(const token& t) {
  if (!t.is_identifier()) return false;
  for (const vv_word& w : vv_words())
    if (!w.then.empty() && (t.text == w.then || t.text == w.or_then)) return true;
  return false;
}

auto takes(std::string_view connective) {
  return [connective](const vv_word& w) {
    return w.role != word_role::path_step && !w.then.empty() && (w.then == connective || w.or_then == connective);
  };
}

// `#include "x.hpp"` (not <x>): a header of the program's own.
bool includes_own_header(std::string_view line) {
  std::size_t i = line.find_first_not_of(" \t", 1);
  if (i == std::string_view::npos || line.compare(i, 7, "include") != 0) return false;
  i = line.find_first_not_of(" \t", i + 7);
  return i != std::string_view::npos && line[i] == '"';
}

}  // namespace

const vv_word* parser::misspelt_word_in_expression(std::initializer_list<std::string_view> stops) {
  const token& name = peek();
  if (!name.is_identifier() || pos_ + 1 >= toks_.size()) return nullptr;
  if (pos_ > 0 && (toks_[pos_ - 1].is(".") || toks_[pos_ - 1].is("->") || toks_[pos_ - 1].is("::")))
    return nullptr;  // a member's name
  const token& next = peek(1);
  // Most names are followed by punctuation no operand starts with: `x;`,
  // `a.b`, `x =`, `v$pos` (a first look: ( { :: ! ~ - + * & ++ --).
  if (next.kind == tok::punct && std::string_view("({:!~-+*&").find(next.text[0]) == std::string_view::npos)
    return nullptr;
  if (next.kind == tok::dollar || next.kind == tok::eof || next.kind == tok::preproc) return nullptr;
  if (!near_a_statement_or_query_word(name.text)) return nullptr;
  const bool operand_next = starts_operand(next) || next.is("{");
  const bool connective_next = is_then_word(next) && starts_operand_after_a_name(peek(2));
  const bool after_operator =
      pos_ > 0 && expression_must_follow(toks_[pos_ - 1]) && starts_operand_after_a_name(next);
  // A word that ends the sequence is no connective: `param double x =
  // f(2) in [0, 3];`.
  auto ends_sequence = [&](const token& t) {
    return std::any_of(stops.begin(), stops.end(), [&](std::string_view s) { return t.is(s); });
  };
  const vv_word* meant = nullptr;
  if (connective_next && !ends_sequence(next)) meant = misspelt_vv_word(name.text, takes(next.text));  // 1
  if (!meant && operand_next) {                                                                       // 2
    const token& after = token_after_operand(pos_ + 1);
    if (after.is_identifier() && !ends_sequence(after)) meant = misspelt_vv_word(name.text, takes(after.text));
  }
  if (!meant && after_operator)  // 3
    meant = misspelt_vv_word(name.text, [](const vv_word& w) { return w.role == word_role::query && w.then.empty(); });
  if (!meant) return nullptr;
  error(name, unknown_word(name, *meant));
  return meant;
}

// Most names are far from every vv word: asked once a name.
bool parser::near_a_statement_or_query_word(std::string_view name) {
  auto known = near_vv_word_.find(name);
  if (known == near_vv_word_.end()) {
    bool near = misspelt_vv_word(name, [](const vv_word& w) {
                  return w.role == word_role::query || w.role == word_role::edit || w.role == word_role::loop;
                }) != nullptr;
    known = near_vv_word_.emplace(name, near).first;
  }
  return known->second;
}

// The token after the operand (or braced list) that starts at token `start_at`,
// found by parsing it with diagnostics held back; the cursor stays. Kept
// per position, as looks_ahead keeps its answers.
const token& parser::token_after_operand(std::size_t start_at) {
  if (operand_ends_.empty()) operand_ends_.assign(toks_.size(), 0);
  if (operand_ends_[start_at] == 0) {
    const std::size_t cursor = pos_;
    const bool gave_up = gave_up_;
    pos_ = start_at;
    diag_.hold();
    if (at("{")) parse_group({}, mode::expression);  // make's list
    else if (!at_end()) parse_operand("");
    bool errors = diag_.release();
    // Kept plus one (0: not known yet); an operand with errors ends nowhere.
    operand_ends_[start_at] = errors || (gave_up_ && !gave_up) ? toks_.size() : pos_ + 1;
    pos_ = cursor;
    gave_up_ = gave_up;
  }
  return toks_[operand_ends_[start_at] - 1];
}

bool parser::misspelt_edit_at_statement_start() {
  const token& name = peek();
  if (!peek(2).is(";") || !name.is_identifier() || !peek(1).is_identifier() ||
      !near_a_statement_or_query_word(name.text) || !declared_as_handle(peek(1).text) || !is_plain_name(peek(1)))
    return false;
  const vv_word* meant =
      misspelt_vv_word(name.text, [](const vv_word& w) { return w.role == word_role::edit && w.then.empty(); });
  if (!meant || !only_before_a_name_and_semicolon(name.text)) return false;
  error(name, unknown_word(name, *meant));
  return true;
}

// Whether the program declares `name` as a mesh or a vertex anywhere:
// `mesh M`, `vertex& v`, `const mesh* m`.
bool parser::declared_as_handle(std::string_view name) {
  if (!handles_found_) {
    handles_found_ = true;
    for (std::size_t i = 0; i + 1 < toks_.size(); ++i) {
      if (!toks_[i].is_word("mesh") && !toks_[i].is_word("vertex")) continue;
      std::size_t k = i + 1;
      while (k < toks_.size() && (toks_[k].is("&") || toks_[k].is("&&") || toks_[k].is("*") || toks_[k].is_word("const")))
        ++k;
      if (k < toks_.size() && toks_[k].is_identifier()) handle_names_.push_back(toks_[k].text);
    }
    std::sort(handle_names_.begin(), handle_names_.end());
  }
  return std::binary_search(handle_names_.begin(), handle_names_.end(), name);
}

// Whether `word` can name nothing of the program's: every use of it is
// `word NAME ;`, no preprocessor line mentions it, and the program includes
// no header of its own (`#include "x.hpp"`), where it could be a type.
// (Included .vvp files are part of the tokens.)
bool parser::only_before_a_name_and_semicolon(std::string_view word) {
  for (std::size_t i = 0; i < toks_.size(); ++i) {
    const token& t = toks_[i];
    if (t.kind == tok::preproc && (t.text.find(word) != std::string_view::npos || includes_own_header(t.text)))
      return false;
    if (!t.is_word(word)) continue;
    if (i + 2 >= toks_.size() || !toks_[i + 1].is_identifier() || !toks_[i + 2].is(";")) return false;
  }
  return true;
}

bool parser::misspelt_block_word_at_top_level() {
  const token& name = peek();
  if (!name.is_identifier() || !peek(1).is("{")) return false;
  const vv_word* meant = misspelt_vv_word(name.text, [](const vv_word& w) {
    return w.role == word_role::execution_block || w.role == word_role::property_block;
  });
  if (!meant) return false;
  error(name, unknown_word(name, *meant));
  // Read the block as what it was meant to be, so that its body is checked
  // and nothing more is said about the name.
  take();
  if (meant->role == word_role::execution_block) {
    parse_compound();
  } else {
    parse_group({}, mode::declaration);
    accept(";");
  }
  return true;
}

}  // namespace vvc
