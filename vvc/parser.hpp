// The recursive-descent parser.
//
// vv extends C++, and a translator that had to understand all of C++
// would be a compiler. This one understands exactly what it must to find
// every vv construct and its operands with certainty:
//
//  * the top level: preprocessor lines, property blocks, execution blocks,
//    and C++ declarations (whose function and class bodies it enters);
//  * statements in bodies: compound, if, while, do, for, switch, try,
//    labels, the vv statements, and anything else up to its `;`;
//  * inside those, balanced token sequences (C++'s balanced-token-seq), in
//    which groups ( [ { nest and the vv expressions are recognised where
//    they start: a vv keyword, a backtick, `$`, `@`, or a parenthesised
//    `(X ^ Y)` / `(X | Y)`.
//
// vv expression operands are unary expressions (like the operand of
// sizeof): `nextto b in c$x` takes `c$x`, and `a + nextto b in c` adds.
// Everything else passes through token for token.
//
// Rules that decide between vv and C++ look only at tokens, never at names
// a program chose: a vv word is a keyword where the vv form it starts is
// complete (`next(i)to`, `any in`, `is X in`, `erase X from`), and C++
// otherwise (a call `next(i)`, a variable `any`). What each word is lives
// in one table (keywords.hpp).
//
// There is one grammar. Where a form is known only once part of it is read
// (`is X in`: is X followed by `in`?), the parser looks ahead by parsing:
// it remembers the cursor, parses X with diagnostics held back, looks at
// the next token and returns to where it was (looks_ahead). The parser
// keeps all its state in the cursor, so going back costs nothing. Each
// answer is kept per token, so a lookahead nested in another (is (is (...
// in b) in b) is tried once: the work stays within the nesting limit times
// the input. Recursion is bounded by max_nesting, speculative or not.
//
// Each parse function documents its grammar in the comment above it.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "diagnostics.hpp"
#include "syntax.hpp"

namespace vvc {

struct vv_word;

class parser {
 public:
  parser(const std::vector<token>& tokens, diagnostics& diag)
      : toks_(tokens), diag_(diag), looked_ahead_(tokens.size(), unknown) {}
  program parse_program();

 private:
  // ---- cursor (parser.cpp) ----
  const token& peek(std::size_t k = 0) const;
  const token* take();
  bool at(std::string_view text) const { return peek().is(text); }
  bool accept(std::string_view text);
  //! Consumes `text` or reports "expected `text` <context>".
  const token* expect(std::string_view text, const std::string& context);
  bool at_end() const { return peek().kind == tok::eof; }
  //! Reports an error, unless the parser has given up on input nested too
  //! deeply: everything it would say after that ("unterminated '('" at
  //! each open level) is noise, not another error.
  void error(const token& at, std::string message) {
    if (!gave_up_) diag_.error(at, std::move(message));
  }
  //! How a message names a token: 'x', or "the end of the file".
  static std::string found(const token& t);
  //! Skips to just after the next ; or to a } that closes the statement.
  void recover();

  // ---- lookahead by parsing ----
  //! Whether the vv form that would start at the cursor is there: runs
  //! `attempt` (which parses part of the form and says whether what
  //! follows fits) with diagnostics held back, then returns to the cursor.
  //! A form nested too deeply to parse counts as there: the real parse
  //! then takes the same path and reports the depth. Answers are kept per
  //! position, so nested lookaheads try each position once.
  template <class Attempt>
  bool looks_ahead(Attempt attempt);

  // ---- balanced token sequences (parser_balanced.cpp) ----
  enum class mode {
    expression,   // a statement or initializer: lambdas have bodies
    declaration,  // namespace or class scope: function bodies too
  };
  //! balanced = { group | vv-expression | "$" name | token } up to one of
  //! `stops` or a closer at depth 0, neither consumed (or, with
  //! `declaration_ends`, just after a function or namespace body)
  pieces parse_balanced(std::initializer_list<std::string_view> stops, mode m,
                   bool declaration_ends = false);
  //! group = "(" balanced ")" | "[" balanced "]" | "{" balanced "}"
  //!       | "{" statements "}" | "{" declarations "}"   (a body; a class or namespace body)
  piece parse_group(const pieces& before, mode m);
  bool starts_lambda_body(const pieces& before) const;
  bool starts_function_body(const pieces& before) const;
  //! Whether the first n pieces of `before` head a class (1) or namespace (2) body.
  int opens_scope_body(const pieces& before, std::size_t n) const;

  // ---- vv expressions (parser_vv.cpp) ----
  //! vv-expression = old-state | path | query: parses one starting here,
  //! if one does; false otherwise.
  bool parse_vv_expression(pieces& out);
  //! operand = prefix-op operand | query | (old-state | path) postfix*
  //!         | "(" balanced ")" postfix* | ["::"] name postfix*
  //!         | (number | character) postfix* | string {string}
  pieces parse_operand(const std::string& context);
  bool starts_operand(const token& t) const;
  //! postfix = "(" balanced ")" | "[" balanced "]" | ("." | "->" | "::") ["template"] ["~"] name
  //!         | "$" name (when allow_property) | "++" | "--" | template-arguments (after a name)
  void parse_postfix(pieces& out, bool allow_property);
  //! property = "$" name, appended to `out`; false after an error.
  bool parse_property(pieces& out);
  //! Template arguments after a name, appended to `out`; false (nothing
  //! taken) when the `<` is a comparison.
  bool parse_template_arguments(pieces& out);
  piece parse_old_state();
  void refuse_writing_the_old_state(const pieces& out, const token& op);
  piece parse_path();
  piece parse_query();
  //! Turns a parenthesised group that holds exactly `operand ^ operand`
  //! (or `|`) into an edge access.
  static void as_edge_access(piece& group);

  // ---- statements (parser_statements.cpp) ----
  stmt_ptr parse_statement();
  stmt_ptr parse_compound();
  stmt_ptr parse_simple();
  bool parse_edit(stmt& s);
  bool parse_make_list(const std::string& w, std::string_view then, std::vector<pieces>& list);
  bool edit_follows();
  stmt_ptr parse_forall();
  bool parse_vertex_declaration(stmt& s);
  void body_statements(stmt_list& out);

  // ---- misspelt vv words (parser_spelling.cpp) ----
  //! Each reports "unknown word 'W'; did you mean 'V'?" when the name at
  //! the cursor stands where C++ could not use a name (the places are
  //! listed in parser_spelling.cpp), and says whether it did (which word).
  const vv_word* misspelt_word_in_expression(std::initializer_list<std::string_view> stops = {});
  bool misspelt_edit_at_statement_start();
  //! At the top level, also reads the block the name was meant to start.
  bool misspelt_block_word_at_top_level();
  bool near_a_statement_or_query_word(std::string_view name);
  const token& token_after_operand(std::size_t start_at);
  bool declared_as_handle(std::string_view name);
  bool only_before_a_name_and_semicolon(std::string_view word);

  // ---- top level (parser_top.cpp) ----
  void parse_property_block(program& p);
  void parse_execution_block(program& p);
  void parse_top_declaration(program& p);
  bool starts_parameter() const;
  void parse_parameter(program& p);
  bool starts_action() const;
  void parse_action(program& p);
  bool starts_pick() const;
  void parse_pick(program& p);
  void analyse_fields(property_block& block);
  void add_field(property_block& block, std::size_t first, std::size_t last, bool first_declarator,
                 bool& type_has_handle);

  const std::vector<token>& toks_;
  diagnostics& diag_;
  std::size_t pos_ = 0;
  int nesting_ = 0;           // groups, operands and statements open now
  bool gave_up_ = false;      // nested past max_nesting: the rest is not parsed
  //! Guards recursion: past max_nesting the input is given up on (with an
  //! error), so no input can exhaust the stack.
  bool enter();
  void leave() { --nesting_; }
  static constexpr int max_nesting = 256;
  class nesting_guard {
   public:
    explicit nesting_guard(parser& p) : p_(p), ok_(p.enter()) {}
    nesting_guard(const nesting_guard&) = delete;
    nesting_guard& operator=(const nesting_guard&) = delete;
    ~nesting_guard() { p_.leave(); }
    bool ok() const { return ok_; }

   private:
    parser& p_;
    bool ok_;
  };
  const token* first_use_[3] = {nullptr, nullptr, nullptr};  // edge, vertex, mesh outside blocks
  enum : signed char { unknown, there, not_there };
  std::vector<signed char> looked_ahead_;  // per token: the answer of looks_ahead there
  std::vector<std::size_t> operand_ends_;  // per token: token_after_operand's answer plus one
  std::unordered_map<std::string_view, bool> near_vv_word_;  // per name: near a statement's or query's word
  bool handles_found_ = false;              // handle_names_ filled
  std::vector<std::string_view> handle_names_;  // names declared as mesh or vertex, sorted
};

template <class Attempt>
bool parser::looks_ahead(Attempt attempt) {
  if (looked_ahead_[pos_] != unknown) return looked_ahead_[pos_] == there;
  const std::size_t start = pos_;
  const bool gave_up = gave_up_;
  diag_.hold();
  bool fits = attempt();
  bool errors = diag_.release();
  bool too_deep = gave_up_ && !gave_up;
  pos_ = start;
  gave_up_ = gave_up;
  bool answer = too_deep || (fits && !errors);
  looked_ahead_[start] = answer ? there : not_there;
  return answer;
}

}  // namespace vvc
