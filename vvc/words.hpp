// Facts about words and pieces the parser's decisions rest on.
#pragma once

#include <string_view>

#include "syntax.hpp"

namespace vvc {

//! C++ keywords after which an expression starts (a `(` after them is no
//! call): `return (a^b)` is a parenthesised expression.
bool is_expression_keyword(std::string_view w);

//! Words the translator reserves: vv keywords that are never identifiers.
bool is_reserved_vv_word(std::string_view w);

//! Names of the execution blocks (start, step, ...).
bool is_block_name(std::string_view w);

//! The last piece of `run` ends an operand: a `(` after it is a call, a `$`
//! after it is property access.
bool ends_operand(const pieces& run);
//! The same for the first n pieces of run.
bool ends_operand(const pieces& run, std::size_t n);

//! A single-token piece with this text.
bool is_token(const piece& p, std::string_view text);

}  // namespace vvc
