// vv expressions: queries, the old state, property access, paths and
// half-edge records, and the operands they take.
#include <iterator>

#include <string>

#include "parser.hpp"
#include "keywords.hpp"

namespace vvc {

bool parser::starts_operand(const token& t) const {
  switch (t.kind) {
    case tok::identifier:
      return !expression_follows(t.text) || t.text == "sizeof" || t.text == "new";
    case tok::number:
    case tok::string:
    case tok::character:
    case tok::backtick:
    case tok::at:
      return true;
    case tok::punct:
      return t.text == "(" || t.text == "::" || is_prefix_operator(t);
    default:
      return false;
  }
}

// vv-expression = old-state | path | query
// (next/prev only before "(" balanced ")" "to", any/flagged only before
// "in", is only before an operand and "in")
bool parser::parse_vv_expression(pieces& out) {
  const token& t = peek();
  if (t.kind == tok::backtick) {
    out.push_back(parse_old_state());
    return true;
  }
  if (t.kind == tok::at) {
    out.push_back(parse_path());
    return true;
  }
  if (!t.is_identifier()) return false;
  std::string_view w = t.text;
  if (!has_role(w, word_role::query)) return false;
  bool query = is_reserved_vv_word(w);  // nextto, prevto, valence, labelof
  if ((w == "next" || w == "prev") && peek(1).is("("))
    query = looks_ahead([&] {
      take();
      parse_group({}, mode::expression);
      return at("to");
    });
  if ((w == "any" || w == "flagged") && peek(1).is_word("in")) query = true;
  if (w == "is" && starts_operand(peek(1)))
    query = looks_ahead([&] {
      take();
      parse_operand("after 'is'");
      return at("in");
    });
  if (!query) return false;
  out.push_back(parse_query());
  return true;
}

// query = ("nextto" | "prevto") ("flag" | operand) "in" operand
//       | ("next" | "prev") "(" balanced ")" "to" operand "in" operand
//       | ("any" | "flagged") "in" operand
//       | ("valence" | "labelof") operand
//       | "is" operand "in" operand
piece parser::parse_query() {
  piece p;
  p.kind = piece_kind::query;
  nesting_guard guard(*this);  // queries nest inside their operands
  if (!guard.ok()) {
    p.tok = &peek();
    return p;
  }
  p.tok = take();
  std::string w(p.tok->text);
  std::string after_kw = "after '" + w + "'";
  auto operand_in_target = [&](const std::string& what) {
    p.parts.push_back(parse_operand(after_kw));
    expect("in", "after " + what + " of '" + w + "'");
    p.parts.push_back(parse_operand("after 'in'"));
  };
  if (w == "nextto" || w == "prevto") {
    if (at("flag") && peek(1).is_word("in")) {
      take();
      take();
      p.query = w == "nextto" ? query_kind::next_to_flag : query_kind::prev_to_flag;
      p.parts.push_back(parse_operand("after 'in'"));
    } else {
      p.query = w == "nextto" ? query_kind::next_to : query_kind::prev_to;
      operand_in_target("the operand");
    }
  } else if (w == "next" || w == "prev") {
    p.query = w == "next" ? query_kind::next_i_to : query_kind::prev_i_to;
    take();  // (
    pieces count = parse_balanced({}, mode::expression);
    if (count.empty()) error(peek(), "expected the number of steps in '" + w + "(...)to'");
    expect(")", "after the number of steps");
    expect("to", "after '" + w + "(...)'");
    p.parts.push_back(std::move(count));
    operand_in_target("the operand");
  } else if (w == "any" || w == "flagged") {
    p.query = w == "any" ? query_kind::any_in : query_kind::flagged_in;
    take();  // in
    p.parts.push_back(parse_operand("after 'in'"));
  } else if (w == "valence" || w == "labelof") {
    p.query = w == "valence" ? query_kind::valence : query_kind::label_of;
    p.parts.push_back(parse_operand(after_kw));
  } else {  // is
    p.query = query_kind::is_in;
    operand_in_target("the operand");
  }
  return p;
}

// operand = prefix-op operand | query | (old-state | path) postfix*
//         | "(" balanced ")" postfix* | ["::"] name postfix*
//         | (number | character) postfix* | string {string}
// (qualified names and template arguments are postfixes: a::b<int>(x))
pieces parser::parse_operand(const std::string& context) {
  pieces out;
  nesting_guard guard(*this);
  if (!guard.ok()) return out;
  const token& t = peek();
  if (is_prefix_operator(t)) {
    out.push_back(token_piece(take()));
    pieces rest = parse_operand(context);
    out.insert(out.end(), std::make_move_iterator(rest.begin()), std::make_move_iterator(rest.end()));
    return out;
  }
  if (parse_vv_expression(out)) {
    if (out.back().kind != piece_kind::query) parse_postfix(out, true);
    return out;
  }
  if (t.is("(")) {
    out.push_back(parse_group(out, mode::expression));
    parse_postfix(out, true);
    return out;
  }
  if (t.is("::") || is_plain_name(t)) {
    if (t.is("::")) out.push_back(token_piece(take()));
    if (!peek().is_identifier()) {
      error(peek(), "expected a name after '::'");
      return out;
    }
    out.push_back(token_piece(take()));
    parse_postfix(out, true);
    return out;
  }
  if (t.kind == tok::number || t.kind == tok::character) {
    out.push_back(token_piece(take()));
    parse_postfix(out, true);
    return out;
  }
  if (t.kind == tok::string) {
    while (peek().kind == tok::string) out.push_back(token_piece(take()));
    return out;
  }
  error(t, "expected a vertex " + context + ", found " + found(t));
  return out;
}

// postfix = "(" balanced ")" | "[" balanced "]" | ("." | "->" | "::") ["template"] ["~"] name
//         | "$" name (when allow_property) | "++" | "--" | template-arguments (after a name)
void parser::parse_postfix(pieces& out, bool allow_property) {
  while (!at_end()) {
    const token& t = peek();
    if (t.is("(") || t.is("[")) {
      out.push_back(parse_group(out, mode::expression));
    } else if (t.is(".") || t.is("->") || t.is("::")) {
      out.push_back(token_piece(take()));
      if (peek().is_word("template")) out.push_back(token_piece(take()));
      if (peek().is("~")) out.push_back(token_piece(take()));
      if (!peek().is_identifier()) {
        error(peek(), "expected a member name after '" + std::string(t.text) + "'");
        return;
      }
      out.push_back(token_piece(take()));
    } else if (t.kind == tok::dollar && allow_property) {
      if (!parse_property(out)) return;
    } else if (t.is("++") || t.is("--")) {
      out.push_back(token_piece(take()));
    } else if (t.is("<") && out.back().kind == piece_kind::token && out.back().tok->is_identifier()) {
      if (!parse_template_arguments(out)) return;
    } else {
      return;
    }
  }
}

// property = "$" name
bool parser::parse_property(pieces& out) {
  take();  // $
  if (!peek().is_identifier()) {
    error(peek(), "expected a property name after '$', found " + found(peek()));
    return false;
  }
  piece p;
  p.kind = piece_kind::property;
  p.tok = take();
  out.push_back(std::move(p));
  return true;
}

// template-arguments = "<" ... ">" when "(" "::" or "{" follows the ">":
// f<int>(x). Angle brackets are no groups, so this counts them over tokens.
bool parser::parse_template_arguments(pieces& out) {
  std::size_t k = pos_;
  int angle = 0, paren = 0;
  for (; k < toks_.size(); ++k) {
    const token& u = toks_[k];
    if (u.is("(") || u.is("[")) ++paren;
    else if (u.is(")") || u.is("]")) --paren;
    else if (paren == 0 && u.is("<")) ++angle;
    else if (paren == 0 && u.is(">")) --angle;
    else if (paren == 0 && u.is(">>")) angle -= 2;
    if (paren < 0 || u.is(";") || u.is("{") || u.is("}") || u.kind == tok::eof) return false;
    if (angle <= 0) break;
  }
  if (angle != 0 || k + 1 >= toks_.size() ||
      !(toks_[k + 1].is("(") || toks_[k + 1].is("::") || toks_[k + 1].is("{")))
    return false;
  while (pos_ <= k) {
    if (peek().is("(") || peek().is("[")) out.push_back(parse_group(out, mode::expression));
    else out.push_back(token_piece(take()));
  }
  return true;
}

// old-state = "`" ( "`" old-state | path | "(" balanced ")" postfix* | ["::"] name postfix* )
// with postfix not taking "$": `v$pos is (`v)$pos.
piece parser::parse_old_state() {
  nesting_guard guard(*this);
  piece p;
  p.kind = piece_kind::old_state;
  p.tok = take();
  if (peek().kind == tok::at) {
    piece path = parse_path();
    path.old = true;
    path.tok = p.tok;
    return path;
  }
  pieces operand;
  const token& t = peek();
  if (!guard.ok()) {
    p.parts.push_back(std::move(operand));
    return p;
  }
  if (t.kind == tok::backtick) {
    operand.push_back(parse_old_state());
  } else if (t.is("(")) {
    operand.push_back(parse_group(operand, mode::expression));
    parse_postfix(operand, false);
  } else if (is_plain_name(t) || t.is("::")) {
    if (t.is("::")) operand.push_back(token_piece(take()));
    if (peek().is_identifier()) operand.push_back(token_piece(take()));
    parse_postfix(operand, false);
  } else {
    error(t, "expected a vertex after '" + std::string(p.tok->text) + "', found " + found(t));
  }
  p.parts.push_back(std::move(operand));
  return p;
}

// path = "@" ["&"] "(" balanced "," balanced ")" { "next" | "prev" | "swap" | "," } "@"
piece parser::parse_path() {
  piece p;
  p.kind = piece_kind::path;
  nesting_guard guard(*this);  // paths nest inside their operands
  if (!guard.ok()) {
    p.tok = &peek();
    return p;
  }
  p.tok = take();
  p.assign = accept("&");
  if (!at("(")) {
    error(*p.tok, "stray '@' in program (a path starts with '@(' or '@&(')");
    return p;
  }
  take();
  p.parts.push_back(parse_balanced({","}, mode::expression));
  expect(",", "between the two vertices of a path");
  p.parts.push_back(parse_balanced({","}, mode::expression));
  expect(")", "after the two vertices of a path");
  if (p.assign)
    for (const pieces& v : p.parts)
      if (!v.empty() && (v.size() != 1 || v[0].kind != piece_kind::token || !v[0].tok->is_identifier()))
        error(v[0].tok ? *v[0].tok : *p.tok,
              "the vertices of '@&(a, b)' must be variables: the path assigns its final pair to them");
  while (true) {
    const token& t = peek();
    if (t.kind == tok::at) {
      p.close = take();
      break;
    }
    if (t.is(",")) {
      take();
      continue;
    }
    if (t.is_word("next") || t.is_word("prev") || t.is_word("swap")) {
      p.ops.push_back(take());
      continue;
    }
    if (t.kind == tok::eof || t.is(";") || t.is("}")) {
      error(*p.tok, "unterminated path: no closing '@'");
      break;
    }
    error(t, "unknown path operation '" + std::string(t.text) + "' (expected next, prev or swap)");
    take();
  }
  return p;
}

namespace {

bool is_prefix_operator_piece(const piece& p) { return p.kind == piece_kind::token && is_prefix_operator(*p.tok); }

// Pieces [b, e) form one operand: prefix operators, a primary, postfixes.
bool is_operand_shape(const pieces& run, std::size_t b, std::size_t e) {
  std::size_t i = b;
  while (i < e && is_prefix_operator_piece(run[i])) ++i;
  if (i == e) return false;
  const piece& first = run[i];
  if (first.kind == piece_kind::token) {
    const token& t = *first.tok;
    if (t.is("::") && i + 1 < e && run[i + 1].kind == piece_kind::token && run[i + 1].tok->is_identifier()) ++i;
    else if (!(t.kind == tok::number || t.kind == tok::string || t.kind == tok::character || is_plain_name(t)))
      return false;
  } else if (first.kind == piece_kind::group) {
    if (!first.tok->is("(")) return false;
  } else if (first.kind == piece_kind::property || first.kind == piece_kind::body ||
             first.kind == piece_kind::class_body) {
    return false;
  }
  for (++i; i < e; ++i) {
    const piece& q = run[i];
    if (q.kind == piece_kind::property) continue;
    if (q.kind == piece_kind::group && (q.tok->is("(") || q.tok->is("["))) continue;
    if (q.kind != piece_kind::token) return false;
    const token& t = *q.tok;
    if (t.is("++") || t.is("--")) continue;
    if ((t.is(".") || t.is("->") || t.is("::")) && i + 1 < e && run[i + 1].kind == piece_kind::token &&
        run[i + 1].tok->is_identifier()) {
      ++i;
      continue;
    }
    return false;
  }
  return true;
}

}  // namespace

// edge-access = "(" operand ("^" | "|") operand ")"
void parser::as_edge_access(piece& g) {
  const pieces& in = g.parts[0];
  std::size_t op = in.size();
  for (std::size_t i = 0; i < in.size(); ++i)
    if (is_token(in[i], "^") || is_token(in[i], "|")) {
      if (op != in.size()) return;  // two operators: plain C++
      op = i;
    }
  if (op == in.size() || !is_operand_shape(in, 0, op) || !is_operand_shape(in, op + 1, in.size())) return;
  piece e;
  e.kind = piece_kind::edge_access;
  e.tok = in[op].tok;
  e.close = g.close;
  pieces x, y;
  for (std::size_t i = 0; i < op; ++i) x.push_back(std::move(g.parts[0][i]));
  for (std::size_t i = op + 1; i < in.size(); ++i) y.push_back(std::move(g.parts[0][i]));
  e.parts.push_back(std::move(x));
  e.parts.push_back(std::move(y));
  g = std::move(e);
}

}  // namespace vvc
