// The words of vv in one table, each with its role, and one predicate for
// each question the parser asks about a word or a token.
#pragma once

#include <string_view>
#include <vector>

#include "syntax.hpp"

namespace vvc {

enum class word_role {
  query,            // starts a query: nextto X in V, is X in V, valence V, ...
  edit,             // starts an edit statement: erase X from V; ...
  loop,             // forall v in V
  connective,       // in, to, from, with, nb_of: an operand follows
  property_block,   // edge { }, vertex { }, mesh { } (in this order)
  execution_block,  // start { }, step { }, ... (the plugin's blocks, in this order)
  parameter,        // param TYPE NAME = VALUE;
  action,           // action "NAME" [key 'c'] { }: before a string, at top level
  action_key,       // key 'c', after an action's name
  pick,             // pick (vertex v) { }: before '(', at top level
  path_step,        // next, prev, swap between @( ... ) and @
};

//! How an edit reads: `word first then second [last third] ;` (then and
//! or_then are the word's, below), or `word first ;` when it has no `then`
//! (clear, synchronise). make's first operand is a list `{a, b}`; `flag`
//! may stand for one operand of some.
struct edit_form {
  std::string_view last;  // the word before a third operand, or ""
  edit_kind kind = edit_kind::make, or_kind = edit_kind::make;  // with `then`, with `or_then`
  enum { nowhere, first, second } flag_may_be = nowhere;  // the operand `flag` may stand for
  bool list_first = false;                                 // make {a, b} nb_of V
};

struct vv_word {
  std::string_view text;
  word_role role;
  //! Never an identifier: the vv form starts with no lookahead.
  bool reserved = false;
  //! The word after the first operand (nextto X in, next(I) to, erase X
  //! from, forall v in), or right after the word when it takes none
  //! (any in); splice takes either of two.
  std::string_view then = {}, or_then = {};
  edit_form edit = {};  // word_role::edit only
};

//! Every vv word; a word with two roles has two rows.
const std::vector<vv_word>& vv_words();

//! The row of `w` in `role`, or null.
const vv_word* find_word(std::string_view w, word_role role);
inline bool has_role(std::string_view w, word_role role) { return find_word(w, role) != nullptr; }

//! vv words that are never identifiers (nextto, forall, vertex, ...).
bool is_reserved_vv_word(std::string_view w);

//! The edit with `flag` for an operand: erase -> erase_flag, splice_after
//! -> splice_after_flag, ...
edit_kind with_flag_operand(edit_kind k);

//! Names of the execution blocks, in the order of the table.
std::vector<std::string_view> execution_block_names();

//! edge 0, vertex 1, mesh 2; -1 for any other word.
int property_block_index(std::string_view w);
//! The word of property block i (0 edge, 1 vertex, 2 mesh).
std::string_view property_block_word(int i);

//! C++ keywords after which an expression starts (a `(` after them is no
//! call): `return (a^b)` is a parenthesised expression.
bool is_cxx_expression_keyword(std::string_view w);

//! An expression follows this word: a C++ expression keyword or a vv
//! connective (`in (a^b)`).
bool expression_follows(std::string_view w);

//! An identifier that names something of the program: no C++ expression
//! keyword, no connective, no reserved vv word.
bool is_plain_name(const token& t);

//! ! ~ - + * & ++ --: the operators an operand may start with.
bool is_prefix_operator(const token& t);

//! The last piece of `run` ends an operand: a `(` after it is a call, a `$`
//! after it is property access.
bool ends_operand(const pieces& run);
//! The same for the first n pieces of run.
bool ends_operand(const pieces& run, std::size_t n);

//! A single-token piece with this text.
bool is_token(const piece& p, std::string_view text);
//! A bracketed group opened by `open` ("(", "[" or "{").
bool is_group(const piece& p, std::string_view open);

}  // namespace vvc
