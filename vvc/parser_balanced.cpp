// Balanced token sequences and the groups in them.
#include "parser.hpp"
#include "keywords.hpp"

namespace vvc {

namespace {

bool is_opener(const token& t) { return t.kind == tok::punct && (t.text == "(" || t.text == "[" || t.text == "{"); }
bool is_closer(const token& t) { return t.kind == tok::punct && (t.text == ")" || t.text == "]" || t.text == "}"); }

std::string_view closer_of(std::string_view open) { return open == "(" ? ")" : open == "[" ? "]" : "}"; }

// Tokens that may stand between a parameter list and a body:
// `) const noexcept -> T& {`.
bool is_specifier_token(const piece& p) {
  if (p.kind != piece_kind::token) return false;
  const token& t = *p.tok;
  if (t.kind == tok::identifier)
    return !expression_follows(t.text) || t.text == "noexcept";
  return t.kind == tok::punct &&
         (t.text == "&" || t.text == "&&" || t.text == "*" || t.text == "->" || t.text == "::" ||
          t.text == "<" || t.text == ">" || t.text == ",");
}

bool is_assignment(const token& t) {
  if (t.kind != tok::punct) return false;
  for (std::string_view op : {"=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=", ">>=", "++", "--"})
    if (t.text == op) return true;
  return false;
}

// The old state the operand ending `out` writes to, as in `p, `p$pos or
// `p$pos[0], or null: the operand's end is walked back over properties,
// subscripts and member names.
const piece* written_old_state(const pieces& out) {
  std::size_t i = out.size();
  while (i > 0) {
    const piece& p = out[i - 1];
    bool postfix = p.kind == piece_kind::property || is_group(p, "[") ||
                   (p.kind == piece_kind::token && (p.tok->is(".") || p.tok->is_identifier()) && i >= 2 &&
                    (p.tok->is(".") || is_token(out[i - 2], ".")));
    if (!postfix) break;
    --i;
  }
  if (i == 0 || out[i - 1].kind != piece_kind::old_state) return nullptr;
  return &out[i - 1];
}

// "p" for `p, "this vertex" for an operand that is more than a name.
std::string old_state_subject(const piece& old) {
  if (old.parts.size() == 1 && old.parts[0].size() == 1 && old.parts[0][0].kind == piece_kind::token &&
      old.parts[0][0].tok->is_identifier())
    return std::string(old.parts[0][0].tok->text);
  return "this vertex";
}

}  // namespace

// Writing to the old state would change a copy that the next synchronise
// discards (and is a const error in the generated C++): say so here.
void parser::refuse_writing_the_old_state(const pieces& out, const token& op) {
  if (!is_assignment(op)) return;
  const piece* old = written_old_state(out);
  if (!old && (op.is("++") || op.is("--")) && peek(1).kind == tok::backtick) {
    error(peek(1), "the old state of a vertex is read-only: it is what the vertex was at 'synchronise'");
    return;
  }
  if (old)
    error(*old->tok, "the old state of " + old_state_subject(*old) +
                         " is read-only: it is what the vertex was at 'synchronise'");
}

// balanced = { group | vv-expression | "$" name | token } up to a stop token (or
// a closer) at this depth; neither is consumed. With declaration_ends, it
// ends just after a function or namespace body.
pieces parser::parse_balanced(std::initializer_list<std::string_view> stops, mode m,
                         bool declaration_ends) {
  pieces out;
  while (!at_end() && !diag_.saturated()) {
    const token& t = peek();
    if (is_closer(t)) break;
    bool stop = false;
    for (std::string_view s : stops) stop = stop || t.is(s);
    if (stop) break;
    if (is_opener(t)) {
      out.push_back(parse_group(out, m));
      const piece& g = out.back();
      bool ends = (g.kind == piece_kind::body && !g.lambda) ||
                  (g.kind == piece_kind::group && g.tok->is("{") && opens_scope_body(out, out.size() - 1) == 2);
      if (declaration_ends && ends) break;
      continue;
    }
    if (parse_vv_expression(out)) continue;
    if (t.kind == tok::dollar) {
      if (!ends_operand(out)) error(t, "'$' must follow a vertex, as in v$pos");
      parse_property(out);
      continue;
    }
    refuse_writing_the_old_state(out, t);
    if (t.is_identifier()) misspelt_word_in_expression(stops);
    piece p;
    p.tok = take();
    out.push_back(std::move(p));
  }
  return out;
}

// group = "(" balanced ")" | "[" balanced "]" | "{" balanced "}"
//       | "{" statements "}"   (a function or lambda body)
//       | "{" declarations "}" (a class or namespace body)
// A `(` that is no call may hold an edge access (X ^ Y) or (X | Y).
piece parser::parse_group(const pieces& before, mode m) {
  nesting_guard guard(*this);
  if (!guard.ok()) {
    piece none;
    none.tok = &peek();
    return none;
  }
  const token& open_tok = peek();
  const bool maybe_edge = open_tok.text == "(" && !ends_operand(before);
  piece p;
  p.kind = piece_kind::group;
  p.tok = take();
  mode inner = mode::expression;
  if (open_tok.text == "{") {
    bool lambda = starts_lambda_body(before);
    if (lambda || (m == mode::declaration && starts_function_body(before))) {
      p.kind = piece_kind::body;
      p.lambda = lambda;
      body_statements(p.body);
    } else if (int scope = opens_scope_body(before, before.size())) {
      p.kind = scope == 1 ? piece_kind::class_body : piece_kind::group;
      inner = mode::declaration;
    }
  }
  if (p.kind != piece_kind::body) p.parts.push_back(parse_balanced({}, inner));
  std::string_view want = closer_of(p.tok->text);
  if (peek().is(want)) {
    p.close = take();
    if (maybe_edge) as_edge_access(p);
  } else if (at_end()) {
    error(*p.tok, p.kind == piece_kind::body || p.kind == piece_kind::class_body
                      ? std::string("unterminated block: this '{' has no matching '}'")
                      : std::string("unterminated '") + std::string(p.tok->text) + "': no matching '" +
                            std::string(want) + "'");
  } else {
    error(peek(), "expected '" + std::string(want) + "' to close the '" +
                      std::string(p.tok->text) + "' at line " + std::to_string(p.tok->line) +
                      ", found '" + std::string(peek().text) + "'");
  }
  return p;
}

// A lambda's body follows its capture list `[...]` (which is no subscript:
// nothing that ends an operand precedes it) and maybe its parameters and
// specifiers: `[&](vertex v) mutable -> bool {`.
bool parser::starts_lambda_body(const pieces& before) const {
  std::size_t i = before.size();
  while (i > 0 && is_specifier_token(before[i - 1])) --i;
  if (i > 0 && is_group(before[i - 1], "(")) --i;
  if (i == 0 || !is_group(before[i - 1], "[")) return false;
  return !ends_operand(before, i - 1);
}

// A function body follows a parameter list (and specifiers), or a
// constructor's member initialisers: `X(int a) : b(a), c{a} {`.
bool parser::starts_function_body(const pieces& before) const {
  std::size_t i = before.size();
  while (i > 0 && is_specifier_token(before[i - 1])) --i;
  if (i > 0 && before[i - 1].kind == piece_kind::token && before[i - 1].tok->is_word("noexcept")) --i;
  if (i == 0) return false;
  if (is_group(before[i - 1], "(")) return i >= 2;  // a name (or operator) before the parameters
  if (is_group(before[i - 1], "{")) {
    bool saw_parameters = false;
    for (std::size_t k = 0; k + 1 < i; ++k) {
      if (is_group(before[k], "(")) saw_parameters = true;
      if (saw_parameters && is_token(before[k], ":")) return true;
    }
  }
  return false;
}

// 1: `struct|class|union Name [final] [: bases] {`; 2: `namespace [N] {` or
// `extern "C" {`; 0: anything else (an enum, an initialiser).
int parser::opens_scope_body(const pieces& before, std::size_t n) const {
  for (std::size_t i = n; i > 0; --i) {
    const piece& p = before[i - 1];
    if (p.kind != piece_kind::token) continue;
    const token& t = *p.tok;
    if (t.is_word("namespace")) return 2;
    if (t.is_word("extern") && i < n && before[i].kind == piece_kind::token &&
        before[i].tok->kind == tok::string && i + 1 == n)
      return 2;
    if (t.is_word("struct") || t.is_word("class") || t.is_word("union")) {
      // Name, qualifiers, final, then nothing or a base list: a class head.
      std::size_t k = i;
      while (k < n && before[k].kind == piece_kind::token &&
             (before[k].tok->is_identifier() || before[k].tok->is("::")))
        ++k;
      if (k == n) return 1;
      if (!is_token(before[k], ":")) return 0;  // `class T>` in a template, `struct X x =`
      for (std::size_t j = k; j < n; ++j)
        if (is_token(before[j], "=") || is_token(before[j], ";")) return 0;
      return 1;
    }
    if (t.is("=") || t.is(";")) return 0;
  }
  return 0;
}

}  // namespace vvc
