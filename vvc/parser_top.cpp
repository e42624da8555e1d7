// The top level: property blocks, execution blocks, actions and the pick
// block, parameters, C++ declarations.
#include <cctype>

#include <model/viewer_keys.hpp>

#include "parser.hpp"
#include "keywords.hpp"

namespace vvc {

// program = { preprocessor-line | property-block | execution-block | action | pick
//           | parameter | declaration }
program parser::parse_program() {
  program p;
  while (!at_end() && !diag_.saturated()) {
    const token& t = peek();
    if (t.kind == tok::preproc) {
      top_item item;
      item.kind = top_item::preproc;
      item.tok = take();
      p.items.push_back(std::move(item));
    } else if (property_block_index(t.text) >= 0 && t.is_identifier() && peek(1).is("{")) {
      parse_property_block(p);
    } else if (t.is_identifier() && has_role(t.text, word_role::execution_block) && peek(1).is("{")) {
      parse_execution_block(p);
    } else if (starts_action()) {
      parse_action(p);
    } else if (starts_pick()) {
      parse_pick(p);
    } else if (starts_parameter()) {
      parse_parameter(p);
    } else if (t.is(")") || t.is("]") || t.is("}")) {
      error(t, "unmatched '" + std::string(t.text) + "'");
      take();
    } else if (misspelt_block_word_at_top_level()) {
      // `stpe { ... }`: reported, and read as the block it was meant to be
    } else {
      parse_top_declaration(p);
    }
  }
  p.last_property_item = p.items.size();
  for (std::size_t i = 0; i < p.items.size(); ++i)
    if (p.items[i].kind == top_item::property) p.last_property_item = i;
  for (const property_block& b : p.properties) {
    int k = property_block_index(b.keyword->text);
    (k == 0 ? p.edge : k == 1 ? p.vertex : p.mesh) = &b;
  }
  return p;
}

// property-block = ("edge" | "vertex" | "mesh") "{" declarations "}" [";"]
// in this order, each at most once, before any other use of its word.
void parser::parse_property_block(program& p) {
  property_block b;
  b.keyword = take();
  int k = property_block_index(b.keyword->text);
  for (const property_block& other : p.properties) {
    int j = property_block_index(other.keyword->text);
    if (j == k)
      error(*b.keyword, "a second " + std::string(property_block_word(k)) + " block (the first is at line " +
                            std::to_string(other.keyword->line) + ")");
    else if (j > k)
      error(*b.keyword, "the " + std::string(property_block_word(k)) + " block must come before the " +
                            std::string(property_block_word(j)) + " block (property blocks go edge, vertex, mesh)");
  }
  // All blocks come before any other use of any of the three words: the
  // model's types are complete only after the last block.
  const token* used = first_use_[k];
  for (const token* u : first_use_)
    if (u && !used) used = u;
  if (used)
    error(*b.keyword, "the " + std::string(property_block_word(k)) +
                          " block must come before any other use of '" + std::string(used->text) +
                          "' (used at line " + std::to_string(used->line) + ")");
  b.open = take();
  b.members = parse_balanced({}, mode::declaration);
  if (at("}")) {
    b.close = take();
  } else {
    error(*b.open, "unterminated " + std::string(property_block_word(k)) + " block: this '{' has no matching '}'");
    return;
  }
  accept(";");
  analyse_fields(b);
  top_item item;
  item.kind = top_item::property;
  item.tok = b.keyword;
  item.property_index = p.properties.size();
  p.properties.push_back(std::move(b));
  p.items.push_back(std::move(item));
}

// execution-block = block-name compound, each name at most once.
void parser::parse_execution_block(program& p) {
  top_item item;
  item.kind = top_item::block;
  item.block_name = take();
  item.tok = item.block_name;
  std::string name(item.block_name->text);
  for (const top_item& other : p.items)
    if (other.kind == top_item::block && other.block_name->text == name)
      error(*item.block_name, "the execution block '" + name + "' is given twice (first at line " +
                                  std::to_string(other.block_name->line) + ")");
  item.block_body = parse_compound();
  p.items.push_back(std::move(item));
}

// `param` is a word of ours only before a parameter's type and name, so a
// C++ program may still call a variable `param`.
bool parser::starts_parameter() const {
  if (!(peek().is_identifier() && has_role(peek().text, word_role::parameter)) || !peek(2).is_identifier()) return false;
  for (std::string_view type : {"bool", "int", "unsigned", "float", "double"})
    if (peek(1).is_word(type)) return true;
  return false;
}

// parameter = "param" type name "=" balanced ["in" "[" balanced "," balanced "]"] ";"
void parser::parse_parameter(program& p) {
  parameter d;
  d.keyword = take();
  d.type = take();
  d.name = take();
  for (const parameter& other : p.parameters)
    if (other.name->text == d.name->text)
      error(*d.name, "a second parameter " + std::string(d.name->text) + " (the first is at line " +
                         std::to_string(other.name->line) + ")");
  std::string of = " of parameter " + std::string(d.name->text);
  expect("=", "after the name" + of + " (a parameter needs a value: param " + std::string(d.type->text) + " " +
                  std::string(d.name->text) + " = VALUE;)");
  d.value = parse_balanced({";", "in"}, mode::expression);
  if (d.value.empty()) error(peek(), "expected the value" + of);
  if (accept("in")) {
    expect("[", "after 'in' (a range is written in [LO, HI])");
    d.lo = parse_balanced({","}, mode::expression);
    expect(",", "between the ends of the range" + of);
    d.hi = parse_balanced({}, mode::expression);
    expect("]", "after the range" + of);
    if (d.lo.empty() || d.hi.empty()) error(*d.name, "the range" + of + " needs both ends: in [LO, HI]");
    if (d.type->is_word("bool")) error(*d.name, "a bool parameter has no range");
  }
  expect(";", "after the parameter " + std::string(d.name->text));
  top_item item;
  item.kind = top_item::parameter;
  item.tok = d.keyword;
  item.parameter_index = p.parameters.size();
  p.parameters.push_back(std::move(d));
  p.items.push_back(std::move(item));
}

namespace {

// An action's name is shown on a button, typed after `action` in a script
// and written into a session's event log, one line each: plain printable
// text, no escapes, no spaces at its ends. "" when the literal is one.
std::string action_name_problem(std::string_view literal) {
  if (literal.size() < 2 || literal.front() != '"' || literal.back() != '"')
    return "an action's name is a plain string literal (no prefix, not raw): action \"NAME\" { ... }";
  std::string_view name = literal.substr(1, literal.size() - 2);
  if (name.empty()) return "an action's name must not be empty";
  for (char c : name) {
    if (c == '\\') return "an action's name is plain text, without escapes";
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return "an action's name is one line of printable text";
  }
  if (name.front() == ' ' || name.back() == ' ') return "an action's name must not begin or end with a space";
  return "";
}

// 'g' -> 'g', 'G' -> 'g', '7' -> '7'; 0 for anything else.
char action_key_char(std::string_view literal) {
  if (literal.size() != 3 || literal.front() != '\'' || literal.back() != '\'') return 0;
  const unsigned char c = static_cast<unsigned char>(literal[1]);
  if (c >= 0x80 || !std::isalnum(c)) return 0;
  return static_cast<char>(std::tolower(c));
}

}  // namespace

// `action` is a word of ours only at the top level and before a string.
bool parser::starts_action() const {
  return peek().is_identifier() && has_role(peek().text, word_role::action) && peek(1).kind == tok::string;
}

// action = "action" string ["key" character] compound
// Names are unique; a key belongs to one action and is none of the viewer's.
void parser::parse_action(program& p) {
  action_block a;
  a.keyword = take();
  a.name = take();
  const std::string name(a.name->text);
  if (std::string why = action_name_problem(a.name->text); !why.empty()) error(*a.name, why);
  for (const action_block& other : p.actions)
    if (other.name->text == a.name->text)
      error(*a.name, "a second action " + name + " (the first is at line " + std::to_string(other.name->line) + ")");
  if (peek().is_identifier() && has_role(peek().text, word_role::action_key)) {
    take();
    if (peek().kind != tok::character) {
      error(peek(), "expected the key as a character after 'key', as in key 'g', found " + found(peek()));
    } else {
      a.key = take();
      a.key_char = action_key_char(a.key->text);
      const std::string key(a.key->text);
      if (!a.key_char) {
        error(*a.key, "the key of action " + name + " must be one letter or digit, as in key 'g'; found " + key);
      } else if (const vv::model::viewer_key* v = vv::model::find_viewer_key(a.key_char)) {
        error(*a.key, "the key " + key + " of action " + name + " is the viewer's key for " + v->does +
                          "; choose another");
      } else {
        for (const action_block& other : p.actions)
          if (other.key_char == a.key_char)
            error(*a.key, "the key " + key + " of action " + name + " is already the key of action " +
                              std::string(other.name->text) + " (line " + std::to_string(other.key->line) + ")");
      }
    }
  }
  if (!at("{")) {
    error(peek(), "expected '{' to begin the block of action " + name + ", found " + found(peek()));
    recover();
    return;
  }
  a.body = parse_compound();
  top_item item;
  item.kind = top_item::action;
  item.tok = a.keyword;
  item.action_index = p.actions.size();
  p.actions.push_back(std::move(a));
  p.items.push_back(std::move(item));
}

// `pick` is a word of ours only at the top level and before '('.
bool parser::starts_pick() const {
  return peek().is_identifier() && has_role(peek().text, word_role::pick) && peek(1).is("(");
}

// pick = "pick" "(" "vertex" name ")" compound, at most once.
void parser::parse_pick(program& p) {
  auto b = std::make_unique<pick_block>();
  b->keyword = take();
  if (p.pick)
    error(*b->keyword, "a second pick block (the first is at line " + std::to_string(p.pick->keyword->line) + ")");
  take();  // (
  if (!peek().is_word("vertex") || !peek(1).is_identifier() || !peek(2).is(")")) {
    error(peek(), "expected 'vertex NAME' in the pick block's parentheses, as in pick (vertex v) { ... }, found " +
                      found(peek()));
    // Skip to the parameter list's end, then read the block if it is there.
    while (!at_end() && !at(")") && !at("{")) take();
    accept(")");
    if (at("{")) parse_compound();
    return;
  }
  b->vertex = take();
  // Like a global declaration, it uses the word: the vertex block must come first.
  if (!first_use_[1]) first_use_[1] = b->vertex;
  b->name = take();
  take();  // )
  if (!at("{")) {
    error(peek(), "expected '{' to begin the pick block, found " + found(peek()));
    recover();
    return;
  }
  b->body = parse_compound();
  if (p.pick) return;  // reported above
  p.pick = std::move(b);
  top_item item;
  item.kind = top_item::pick;
  item.tok = p.pick->keyword;
  p.items.push_back(std::move(item));
}

// declaration = balanced ";" | balanced ending in a function or namespace body
void parser::parse_top_declaration(program& p) {
  std::size_t start = pos_;
  const token& first = peek();
  if (first.is_word("vertex") && peek(1).is_identifier() &&
      (peek(2).is(";") || peek(2).is(",") || peek(2).is("{")))
    error(peek(1), "vertex '" + std::string(peek(1).text) +
                       "' would be created at global scope, where no model exists yet; write "
                       "'vertex " + std::string(peek(1).text) +
                       " = 0;' here and create the vertex in an execution block");
  top_item item;
  item.tok = &first;
  item.cxx = parse_balanced({";"}, mode::declaration, true);
  bool ends_with_body = !item.cxx.empty() && (item.cxx.back().kind == piece_kind::body ||
                                              (item.cxx.back().kind == piece_kind::group &&
                                               item.cxx.back().tok->is("{")));
  if (at(";")) item.cxx.push_back(token_piece(take()));
  else if (!ends_with_body && !at_end() && !diag_.saturated())
    error(peek(), "expected ';' after the declaration");
  else if (!ends_with_body && at_end() && !item.cxx.empty())
    error(peek(), "expected ';' at the end of the file");
  if (pos_ == start) take();  // always make progress

  // Global meshes: `[static] mesh A, B = ..., C;` (not `mesh f(...)`).
  const pieces& run = item.cxx;
  std::size_t i = 0;
  if (i < run.size() && is_token(run[i], "static")) ++i;
  if (i < run.size() && is_token(run[i], "mesh")) {
    for (++i; i < run.size(); ++i) {
      if (run[i].kind != piece_kind::token || !run[i].tok->is_identifier()) break;
      const token* name = run[i].tok;
      std::size_t j = i + 1;
      if (j < run.size() && run[j].kind == piece_kind::group && run[j].tok->is("(")) break;  // a function
      p.global_meshes.push_back(name);
      while (j < run.size() && !is_token(run[j], ",") && !is_token(run[j], ";")) ++j;
      if (j >= run.size() || is_token(run[j], ";")) break;
      i = j;  // the comma; the loop steps to the next name
    }
  }
  for (std::size_t k = start; k < pos_; ++k) {
    int w = toks_[k].is_identifier() ? property_block_index(toks_[k].text) : -1;
    if (w >= 0 && !first_use_[w]) first_use_[w] = &toks_[k];
  }
  p.items.push_back(std::move(item));
}

namespace {

using declarator_range = std::pair<std::size_t, std::size_t>;  // pieces [first, last)

// Member declarations that declare no data member: statics, types,
// aliases, friends, templates, functions by their specifiers.
bool declares_no_data(const piece& head) {
  if (head.kind != piece_kind::token || !head.tok->is_identifier()) return false;
  std::string_view w = head.tok->text;
  return w == "static" || w == "typedef" || w == "using" || w == "friend" || w == "template" || w == "enum" ||
         w == "struct" || w == "class" || w == "union" || w == "virtual" || w == "explicit" || w == "operator" ||
         w == "constexpr" || w == "inline";
}

// The declarators of the member declaration [s, e), split at commas outside
// template brackets; none when a `(` outside them before any `=` makes it a
// function declaration.
std::vector<declarator_range> split_declarators(const pieces& m, std::size_t s, std::size_t e) {
  std::vector<declarator_range> declarators;
  int angle = 0;
  bool seen_init = false;
  std::size_t d = s;
  for (std::size_t k = s; k < e; ++k) {
    const piece& q = m[k];
    if (is_token(q, "<")) ++angle;
    else if (is_token(q, ">")) --angle;
    else if (is_token(q, ">>")) angle -= 2;
    else if (is_token(q, "=")) seen_init = true;
    else if (angle <= 0 && !seen_init && q.kind == piece_kind::group && q.tok->is("(")) return {};
    else if (angle <= 0 && is_token(q, ",")) {
      declarators.push_back({d, k});
      d = k + 1;
      seen_init = false;
    }
  }
  declarators.push_back({d, e});
  return declarators;
}

// `computed` before a data member's type says that the program computes the
// field itself, so a file need not give it (no warning when it does not).
// It is a word of ours only there, and only before a type and a name: in
// `computed c;`, `computed c = x;`, `computed* p;` or `computed<T> t;` it
// names a type, and a variable may still be called `computed`.
bool is_computed_qualifier(const pieces& m, std::size_t s, std::size_t e) {
  if (s + 2 >= e || m[s].kind != piece_kind::token || !m[s].tok->is_word("computed")) return false;
  const piece& type = m[s + 1];
  if (type.kind != piece_kind::token || !type.tok->is_identifier()) return false;
  const piece& after = m[s + 2];
  return !(is_token(after, "=") || is_token(after, ",") || is_token(after, ":") || after.kind == piece_kind::group);
}

// A declarator without an initialiser or a bit-field width gets `{}` after
// its last piece (after any array bounds from `stop` on).
void value_initialise_unless_initialised(property_block& b, std::size_t stop, std::size_t de) {
  const pieces& m = b.members;
  std::size_t k = stop;
  while (k < de && m[k].kind == piece_kind::group && m[k].tok->is("[")) ++k;
  bool has_init = k < de && (is_token(m[k], "=") || is_token(m[k], ":") ||
                             (m[k].kind == piece_kind::group && m[k].tok->is("{")));
  if (has_init) return;
  const piece& last = m[k - 1];
  b.value_init_after.push_back(last.kind == piece_kind::group ? last.close : last.tok);
}

}  // namespace

// A data member of a property block: a declaration that is no function,
// type, alias or static. Its declarators name the fields; those without an
// initialiser get `{}` so every property starts value-initialised. A
// leading `computed` marks its fields computed and is not emitted.
void parser::analyse_fields(property_block& b) {
  const pieces& m = b.members;
  std::vector<std::size_t> qualifiers;  // the `computed` pieces, dropped at the end
  std::size_t begin = 0;
  for (std::size_t i = 0; i <= m.size(); ++i) {
    bool ends = i == m.size() || is_token(m[i], ";") || m[i].kind == piece_kind::body;
    if (!ends) continue;
    std::size_t s = begin, e = i;
    begin = i + 1;
    while (s + 1 < e && m[s].kind == piece_kind::token &&
           (m[s].tok->is_word("public") || m[s].tok->is_word("private") || m[s].tok->is_word("protected")) &&
           is_token(m[s + 1], ":"))
      s += 2;
    if (s >= e || (i < m.size() && m[i].kind == piece_kind::body) || declares_no_data(m[s])) continue;
    const bool computed = is_computed_qualifier(m, s, e);
    if (computed) qualifiers.push_back(s++);
    bool type_has_handle = false;  // read from the first declarator: the type is written there
    std::vector<declarator_range> declarators = split_declarators(m, s, e);
    const std::size_t first_field = b.fields.size();
    for (std::size_t di = 0; di < declarators.size(); ++di)
      add_field(b, declarators[di].first, declarators[di].second, di == 0, type_has_handle);
    for (std::size_t f = first_field; f < b.fields.size(); ++f) b.fields[f].computed = computed;
  }
  // Fields and value-initialisations point at tokens, not at pieces: they
  // stay right when the qualifiers go.
  for (auto q = qualifiers.rbegin(); q != qualifiers.rend(); ++q)
    b.members.erase(b.members.begin() + static_cast<std::ptrdiff_t>(*q));
}

// One declarator [ds, de) of a data member: its name becomes a field
// (handles and pointers are not written to .vvm files), then its
// value-initialisation.
void parser::add_field(property_block& b, std::size_t ds, std::size_t de, bool first, bool& type_has_handle) {
  const pieces& m = b.members;
  std::size_t name = de, stop = de;
  for (std::size_t k = ds; k < de; ++k) {
    const piece& q = m[k];
    if (is_token(q, "=") || is_token(q, ":") || (q.kind == piece_kind::group && q.tok->is("{")) ||
        (q.kind == piece_kind::group && q.tok->is("["))) {
      stop = k;
      break;
    }
    if (q.kind == piece_kind::token && q.tok->is_identifier()) name = k;
  }
  if (name == de) {
    // An empty declarator (`int a, ;`) has no token of its own.
    const token& where = ds < de ? *m[ds].tok : ds > 0 ? *m[ds - 1].tok : *b.open;
    error(where, "expected a property name in this declaration");
    return;
  }
  bool pointer = false;
  for (std::size_t k = ds; k < name; ++k) {
    if (is_token(m[k], "*") || is_token(m[k], "&")) pointer = true;
    if (first && (is_token(m[k], "vertex") || is_token(m[k], "mesh"))) type_has_handle = true;
  }
  const token* name_tok = m[name].tok;
  if (name_tok->text == "nb") error(*name_tok, "the property name 'nb' is reserved (it holds the neighbourhood in .vvm files)");
  b.fields.push_back({name_tok, !pointer && !type_has_handle});
  value_initialise_unless_initialised(b, stop, de);
}

}  // namespace vvc
