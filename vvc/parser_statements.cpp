// Statements in function, lambda and execution-block bodies.
#include <iterator>

#include "parser.hpp"
#include "keywords.hpp"

namespace vvc {

namespace {

stmt_ptr make_stmt(stmt_kind k, const token* t) {
  auto s = std::make_unique<stmt>();
  s->kind = k;
  s->tok = t;
  return s;
}

}  // namespace

// statements = { statement } up to "}"
void parser::body_statements(stmt_list& out) {
  while (!at_end() && !at("}") && !diag_.saturated()) {
    std::size_t before = pos_;
    out.push_back(parse_statement());
    if (pos_ == before) {  // nothing consumed: a stray closer
      error(peek(), "unexpected '" + std::string(peek().text) + "'");
      take();
    }
  }
}

// compound = "{" statements "}"
stmt_ptr parser::parse_compound() {
  auto s = make_stmt(stmt_kind::compound, take());
  body_statements(s->children);
  if (at("}")) s->end = take();
  else
    error(*s->tok, "unterminated block: this '{' has no matching '}'");
  return s;
}

// statement = compound | ";" | preprocessor-line
//           | "if" ["constexpr"] "(" balanced ")" statement ["else" statement]
//           | "while" "(" balanced ")" statement | "do" statement "while" "(" balanced ")" ";"
//           | "for" "(" balanced ")" statement | "switch" "(" balanced ")" statement
//           | "try" compound { "catch" "(" balanced ")" compound }
//           | ("case" balanced | "default" | name) ":"
//           | forall | edit | vertex-declaration | balanced ";"
stmt_ptr parser::parse_statement() {
  nesting_guard guard(*this);
  if (!guard.ok()) return make_stmt(stmt_kind::empty, &peek());
  const token& t = peek();
  if (t.kind == tok::preproc) return make_stmt(stmt_kind::preproc, take());
  if (t.is("{")) return parse_compound();
  if (t.is(";")) {
    auto s = make_stmt(stmt_kind::empty, take());
    s->end = s->tok;
    return s;
  }
  if (t.is_identifier()) {
    std::string_view w = t.text;
    auto header = [&](stmt& s) {
      if (!at("(")) {
        error(peek(), "expected '(' after '" + std::string(w) + "'");
        return;
      }
      s.head.push_back(parse_group(s.head, mode::expression));
    };
    if (w == "if") {
      auto s = make_stmt(stmt_kind::if_, take());
      if (at("constexpr")) s->head.push_back(token_piece(take()));
      header(*s);
      s->children.push_back(parse_statement());
      if (at("else")) {
        s->else_tok = take();
        s->children.push_back(parse_statement());
      }
      return s;
    }
    if (w == "while" || w == "for" || w == "switch") {
      auto s = make_stmt(w == "while" ? stmt_kind::while_ : w == "for" ? stmt_kind::for_ : stmt_kind::switch_, take());
      header(*s);
      s->children.push_back(parse_statement());
      return s;
    }
    if (w == "do") {
      auto s = make_stmt(stmt_kind::do_while, take());
      s->children.push_back(parse_statement());
      if (expect("while", "after the body of 'do'")) header(*s);
      s->end = expect(";", "after 'do ... while (...)'");
      return s;
    }
    if (w == "try") {
      auto s = make_stmt(stmt_kind::try_, take());
      if (!at("{")) error(peek(), "expected '{' after 'try'");
      else s->children.push_back(parse_compound());
      while (at("catch")) {
        take();
        pieces h;
        if (at("(")) h.push_back(parse_group(h, mode::expression));
        else error(peek(), "expected '(' after 'catch'");
        s->heads.push_back(std::move(h));
        if (!at("{")) {
          error(peek(), "expected '{' after the catch clause");
          break;
        }
        s->children.push_back(parse_compound());
      }
      return s;
    }
    if (w == "case" || w == "default" || (peek(1).is(":") && is_plain_name(t))) {
      auto s = make_stmt(stmt_kind::label, &t);
      s->head = parse_balanced({":"}, mode::expression);
      if (const token* colon = expect(":", "after the label")) s->head.push_back(token_piece(colon));
      return s;
    }
    if (w == "forall") return parse_forall();
    // `parallel` is a word of vv only before `forall` (reserved: no C++
    // could read `parallel forall`).
    if (w == "parallel" && peek(1).is_word("forall")) return parse_parallel_forall();
    // `foral v in M {...}`: reported, and read as the loop it was meant to
    // be (its body is a statement, which C++ would not end).
    if (peek(1).is_identifier() && peek(2).is_word("in"))
      if (const vv_word* meant = misspelt_word_in_expression(); meant && meant->role == word_role::loop)
        return parse_forall();
    if (has_role(w, word_role::edit) && edit_follows()) {
      auto s = make_stmt(stmt_kind::edit, &t);
      if (!parse_edit(*s)) recover();
      return s;
    }
    // `vertex& r = v;`, `vertex* p;`, `vertex::x`: plain C++.
    if (w == "vertex" && peek(1).is_identifier() && !is_reserved_vv_word(peek(1).text)) {
      auto s = make_stmt(stmt_kind::vertex_decl, &t);
      if (!parse_vertex_declaration(*s)) recover();
      return s;
    }
    misspelt_edit_at_statement_start();  // `synchronis M;` (parsed on as C++)
  }
  return parse_simple();
}

// simple = balanced ";"
stmt_ptr parser::parse_simple() {
  auto s = make_stmt(stmt_kind::simple, &peek());
  s->head = parse_balanced({";"}, mode::expression);
  if (at_end()) return s;  // inside an unterminated block, which reports itself
  s->end = expect(";", "at the end of the statement");
  if (!s->end) recover();
  return s;
}

// A vv edit starts here (not a C++ use of the same word): the word is
// followed by an operand, and, when that operand is parenthesised, by the
// edit's next keyword (`erase (x) from v;` but `erase(x);` is a call).
bool parser::edit_follows() {
  const vv_word& edit = *find_word(peek().text, word_role::edit);
  if (edit.reserved) return true;  // synchronise
  auto continues_at = [&](const token& t) {
    return !edit.then.empty() && (t.is(edit.then) || (!edit.or_then.empty() && t.is(edit.or_then)));
  };
  const token& next = peek(1);
  if (edit.edit.list_first) return next.is("{") || next.is_word(edit.then);
  // The operand is missing but the edit's next word is there: `add to M;`.
  if (next.is_identifier() && continues_at(next)) return true;
  if (next.is("("))
    return looks_ahead([&] {
      take();
      parse_group({}, mode::expression);
      return continues_at(peek());
    });
  // `erase * x` and `erase - x` are arithmetic on a variable `erase`.
  return starts_operand(next) && (!is_prefix_operator(next) || next.is("!") || next.is("~"));
}

// edit = "make" make-list "nb_of" operand ";"
//      | word first then second [last third] ";"   (each word's form: keywords.cpp)
// so that:
//        "erase" ("flag" | operand) "from" operand ";"
//      | "remove" operand "from" operand ";"
//      | "replace" ("flag" | operand) "with" operand "in" operand ";"
//      | "merge" operand "with" operand ";"
//      | "splice" operand ("after" | "before") ("flag" | operand) "in" operand ";"
//      | "flag" operand "in" operand ";"
//      | "add" operand "to" operand ";"
//      | ("clear" | "synchronise" | "synchronize") operand ";"
bool parser::parse_edit(stmt& s) {
  std::string w(take()->text);
  const vv_word& edit = *find_word(w, word_role::edit);
  const edit_form& form = edit.edit;
  std::string_view then = edit.then, or_then = edit.or_then;
  s.edit = form.kind;
  auto operand = [&](const std::string& context) { s.operands.push_back(parse_operand(context)); };
  auto word = [&](std::string_view kw, const std::string& context) { return expect(kw, context) != nullptr; };
  // `flag` in place of an operand, when `kw` follows it.
  auto flag_before = [&](std::string_view kw) {
    if (!(at("flag") && peek(1).is_word(kw))) return false;
    take();
    s.edit = with_flag_operand(s.edit);
    return true;
  };
  bool ok = true;
  if (form.list_first) {
    std::vector<pieces> list;
    if (!parse_make_list(w, then, list)) return false;
    ok = word(then, "after the list of '" + w + "'");
    if (ok) operand("after '" + std::string(then) + "'");
    s.operands.insert(s.operands.end(), std::make_move_iterator(list.begin()),
                      std::make_move_iterator(list.end()));
    if (!ok) return false;
    s.end = expect(";", "at the end of '" + w + "'");
    return s.end != nullptr;
  }
  // How messages name the form: 'replace ... with ... in ...'; a choice of
  // two words is left out ('splice ... in ...').
  std::string shape = "'" + w;
  if (!then.empty() && or_then.empty()) shape += " ... " + std::string(then);
  if (!form.last.empty()) shape += " ... " + std::string(form.last);
  shape += " ...'";

  if (form.flag_may_be != edit_form::first || !flag_before(then)) {
    // A missing operand: a connective is no operand, but after or before
    // would pass for a name.
    if (!then.empty() && !has_role(then, word_role::connective) &&
        (at(then) || (!or_then.empty() && at(or_then)))) {
      error(peek(), "expected a vertex after '" + w + "', found " + found(peek()));
      return false;
    }
    operand("after '" + w + "'");
  }
  if (!then.empty()) {
    std::string taken(then);
    if (!or_then.empty()) {
      if (!at(then) && !at(or_then)) {
        error(peek(), "expected '" + std::string(then) + "' or '" + std::string(or_then) + "' in '" + w +
                          "', found " + found(peek()));
        return false;
      }
      taken = std::string(take()->text);
      if (taken == or_then) s.edit = form.or_kind;
    } else {
      ok = word(then, "in " + shape);
    }
    if (ok && (form.flag_may_be != edit_form::second || !flag_before(form.last))) operand("after '" + taken + "'");
  }
  if (!form.last.empty()) {
    ok = ok && word(form.last, "in " + shape);
    if (ok) operand("after '" + std::string(form.last) + "'");
  }
  if (!ok) return false;
  s.end = expect(";", "at the end of '" + w + "'");
  return s.end != nullptr;
}

// make-list = "{" balanced {"," balanced} "}"   (each balanced up to "," or `then`)
bool parser::parse_make_list(const std::string& w, std::string_view then, std::vector<pieces>& list) {
  if (!at("{")) {
    error(peek(), "expected '{' to start the list of '" + w + "', found " + found(peek()));
    return false;
  }
  const token* open = take();
  while (!at("}") && !at_end()) {
    list.push_back(parse_balanced({",", then, ";"}, mode::expression));
    if (list.back().empty()) error(peek(), "expected a vertex in the list of '" + w + "'");
    if (!accept(",")) break;
  }
  if (!accept("}")) {
    error(at_end() ? *open : peek(), "expected '}' to end the list of '" + w + "', found " + found(peek()));
    return false;
  }
  return true;
}

// forall = "forall" name "in" operand statement
stmt_ptr parser::parse_forall() {
  auto s = make_stmt(stmt_kind::forall, take());
  if (!peek().is_identifier() || is_reserved_vv_word(peek().text)) {
    error(peek(), "expected the name of the loop vertex after 'forall'");
    recover();
    return s;
  }
  s->name = take();
  if (!expect("in", "after the loop vertex of 'forall'")) {
    recover();
    return s;
  }
  s->operands.push_back(parse_operand("after 'in'"));
  s->children.push_back(parse_statement());
  return s;
}

// vertex-declaration = "vertex" declarator {"," declarator} ";"
// declarator = name                      (creates a vertex)
//            | name "(" [balanced {"," balanced}] ")"    (with properties)
//            | name "{" [balanced {"," balanced}] "}"
//            | name "=" balanced                          (a reference)
//            | name balanced                             (starting at "[": an array of null handles)
// each balanced up to "," (or ";")
bool parser::parse_vertex_declaration(stmt& s) {
  take();  // vertex
  while (true) {
    if (!peek().is_identifier() || is_reserved_vv_word(peek().text)) {
      error(peek(), "expected the name of a vertex in the declaration");
      return false;
    }
    vertex_declarator d;
    d.name = take();
    if (at("(") || at("{")) {
      const token* open = take();
      std::string_view close = open->is("(") ? ")" : "}";
      d.how = vertex_declarator::create_with;
      while (!at(close) && !at_end()) {
        d.args.push_back(parse_balanced({","}, mode::expression));
        if (d.args.back().empty()) error(peek(), "expected an initial property value");
        if (!accept(",")) break;
      }
      if (!expect(close, "after the initial property values of '" + std::string(d.name->text) + "'"))
        return false;
      if (d.args.empty()) d.how = vertex_declarator::create;
    } else if (accept("=")) {
      d.how = vertex_declarator::reference;
      d.args.push_back(parse_balanced({",", ";"}, mode::expression));
      if (d.args[0].empty()) error(peek(), "expected an initial value after '='");
    } else if (at("[")) {
      d.how = vertex_declarator::plain;
      d.args.push_back(parse_balanced({",", ";"}, mode::expression));
    } else if (!at(",") && !at(";")) {
      error(peek(), "expected ';', ',', '(' or '=' after the vertex '" + std::string(d.name->text) + "'");
      return false;
    }
    s.declarators.push_back(std::move(d));
    if (!accept(",")) break;
  }
  s.end = expect(";", "at the end of the vertex declaration");
  return s.end != nullptr;
}

}  // namespace vvc
