#include "globals.hpp"

#include <cctype>
#include <string_view>

#include "keywords.hpp"

namespace vvc {

namespace {

using range = std::pair<std::size_t, std::size_t>;  // pieces [first, last)

bool is_word_piece(const piece& p) { return p.kind == piece_kind::token && p.tok->is_identifier(); }

// Declarations that define no variable, by their first word.
bool defines_no_variable(const piece& first) {
  if (!is_word_piece(first)) return !is_token(first, "::");
  std::string_view w = first.tok->text;
  return w == "typedef" || w == "using" || w == "template" || w == "namespace" || w == "extern" ||
         w == "static_assert" || w == "friend" || w == "struct" || w == "class" || w == "union" || w == "enum" ||
         w == "asm";
}

// A type's text: words apart, punctuation close ("std::map<int, vertex>").
std::string spell(const pieces& run, std::size_t from, std::size_t to) {
  std::string out;
  for (std::size_t i = from; i < to; ++i) {
    const piece& p = run[i];
    if (p.kind == piece_kind::group) {  // std::function<double(double)>, bounds [3]
      out += std::string(p.tok->text) + (p.parts.empty() ? "" : spell(p.parts[0], 0, p.parts[0].size())) +
             std::string(p.close ? p.close->text : "");
      continue;
    }
    if (p.kind != piece_kind::token) {
      out += "...";
      continue;
    }
    std::string_view t = p.tok->text;
    bool word = p.tok->is_identifier() || p.tok->kind == tok::number;
    if (word && !out.empty() && (std::isalnum(static_cast<unsigned char>(out.back())) || out.back() == '_' ||
                                 out.back() == '>' || out.back() == '*' || out.back() == '&'))
      out += ' ';
    out += t;
    if (t == ",") out += ' ';
  }
  return out;
}

// `static`, `inline` and the like are not part of the type.
bool is_storage_word(const piece& p) {
  if (!is_word_piece(p)) return false;
  std::string_view w = p.tok->text;
  return w == "static" || w == "inline" || w == "thread_local" || w == "mutable" || w == "register";
}

// The declarators of [s, e), split at commas outside template brackets and
// outside initialisers' groups (which are pieces of their own).
std::vector<range> split_at_commas(const pieces& run, std::size_t s, std::size_t e) {
  std::vector<range> out;
  int angle = 0;
  bool in_init = false;
  std::size_t d = s;
  for (std::size_t k = s; k < e; ++k) {
    const piece& q = run[k];
    if (is_token(q, "=")) in_init = true;
    if (!in_init && is_token(q, "<")) ++angle;
    else if (!in_init && is_token(q, ">")) --angle;
    else if (!in_init && is_token(q, ">>")) angle -= 2;
    else if (angle <= 0 && is_token(q, ",")) {
      // In an initialiser a comma outside groups still ends the declarator
      // (`int a = 1, b = 2;`); a template's commas are inside <> only
      // before the `=`.
      out.push_back({d, k});
      d = k + 1;
      in_init = false;
    }
  }
  out.push_back({d, e});
  return out;
}

// Whether a `(` group after a declarator's name holds parameters (a
// function's declaration) rather than a constructor's arguments: empty,
// or starting with a type word, or a type and a name side by side.
bool holds_parameters(const piece& group) {
  if (group.parts.empty() || group.parts[0].empty()) return true;
  const pieces& in = group.parts[0];
  for (const piece& p : in)
    if (p.kind == piece_kind::token && (p.tok->kind == tok::string || p.tok->kind == tok::number ||
                                        p.tok->kind == tok::character))
      return false;
  if (is_word_piece(in[0])) {
    std::string_view w = in[0].tok->text;
    for (std::string_view type : {"void", "bool", "char", "short", "int", "long", "float", "double", "unsigned",
                                  "signed", "const", "volatile", "auto", "vertex", "mesh", "struct", "class"})
      if (w == type) return true;
  }
  for (std::size_t i = 0; i + 1 < in.size(); ++i)
    if (is_word_piece(in[i]) && is_word_piece(in[i + 1])) return true;
  return false;
}

class finder {
 public:
  explicit finder(std::vector<global_variable>& out) : out_(out) {}

  // One declaration [s, e) (its `;` excluded) at namespace scope.
  void declaration(const pieces& run, std::size_t s, std::size_t e, const std::string& scope) {
    while (s < e && is_token(run[s], ";")) ++s;
    if (s >= e) return;
    if (is_word_piece(run[s]) && run[s].tok->is_word("namespace")) return namespace_body(run, s, e, scope);
    if (defines_no_variable(run[s])) return;
    if (run[e - 1].kind == piece_kind::body && !run[e - 1].lambda) return;  // a function's definition
    std::vector<range> declarators = split_at_commas(run, s, e);
    std::string specifiers;
    for (std::size_t i = 0; i < declarators.size(); ++i) {
      auto [ds, de] = declarators[i];
      std::size_t name = de;
      std::size_t stop = de;
      int angle = 0;  // inside template arguments: std::function<double(double)>
      for (std::size_t k = ds; k < de; ++k) {
        const piece& q = run[k];
        if (is_token(q, "<")) ++angle;
        else if (is_token(q, ">")) --angle;
        else if (is_token(q, ">>")) angle -= 2;
        if (angle > 0) continue;
        if (is_token(q, "=") || is_group(q, "(") || is_group(q, "{") || is_group(q, "[")) {
          stop = k;
          break;
        }
        if (is_word_piece(q) && !is_storage_word(q)) name = k;
      }
      if (name == de) return;  // no name: not a declaration we understand
      if (stop < de && is_group(run[stop], "(") && holds_parameters(run[stop])) return;  // a function
      if (stop < de && is_group(run[stop], "(") && stop + 1 < de && is_token(run[stop + 1], "->")) return;
      // The name may be qualified (a static member's definition: int A::n = 0;).
      std::size_t first = name;
      while (first >= ds + 2 && is_token(run[first - 1], "::") && is_word_piece(run[first - 2])) first -= 2;
      // The pointer and reference signs before it belong to this declarator.
      std::size_t own = first;
      while (own > ds && (is_token(run[own - 1], "*") || is_token(run[own - 1], "&") || is_token(run[own - 1], "&&") ||
                          (is_word_piece(run[own - 1]) && run[own - 1].tok->is_word("const") && own - 1 > ds &&
                           is_token(run[own - 2], "*"))))
        --own;
      if (i == 0) {
        std::size_t spec_from = ds;
        while (spec_from < own && is_storage_word(run[spec_from])) ++spec_from;
        specifiers = spell(run, spec_from, own);
      }
      global_variable g;
      g.name = scope + spell(run, first, name + 1);
      std::string sign = spell(run, own, first);
      std::string bounds;
      for (std::size_t k = stop; k < de && is_group(run[k], "["); ++k) bounds += spell(run, k, k + 1);
      g.type = specifiers + sign + bounds;
      g.line = run[name].tok->line;
      if (!specifiers.empty()) out_.push_back(g);
    }
  }

  // `static T x ...;` in a function body.
  void local_static(const pieces& head) {
    if (head.empty() || !is_word_piece(head[0]) || !head[0].tok->is_word("static")) return;
    for (const piece& p : head)
      if (is_word_piece(p) && (p.tok->is_word("const") || p.tok->is_word("constexpr"))) {
        // A constant never changes: nothing to save. (`T* const` and
        // `const T*` alike are read as constant here; a pointer cannot be
        // saved anyway.)
        return;
      }
    std::size_t before = out_.size();
    declaration(head, 0, head.size(), "");
    for (std::size_t i = before; i < out_.size(); ++i) out_[i].in_function = true;
  }

  void walk(const pieces& run) {
    for (const piece& p : run) walk(p);
  }

  void walk(const piece& p) {
    if (p.kind == piece_kind::body) {
      for (const stmt_ptr& s : p.body) walk(*s);
      return;
    }
    for (const pieces& part : p.parts) walk(part);
  }

  void walk(const stmt& s) {
    if (s.kind == stmt_kind::simple) local_static(s.head);
    walk(s.head);
    for (const pieces& h : s.heads) walk(h);
    for (const pieces& o : s.operands) walk(o);
    for (const vertex_declarator& d : s.declarators)
      for (const pieces& a : d.args) walk(a);
    for (const stmt_ptr& c : s.children) walk(*c);
  }

 private:
  // namespace N { declarations }: each declaration, as N::name.
  void namespace_body(const pieces& run, std::size_t s, std::size_t e, const std::string& scope) {
    std::size_t k = s + 1;
    std::string name;
    while (k < e && (is_word_piece(run[k]) || is_token(run[k], "::"))) name += std::string(run[k++].tok->text);
    if (k >= e || !is_group(run[k], "{") || run[k].parts.empty()) return;
    const std::string inner = name.empty() ? scope : scope + name + "::";
    const pieces& body = run[k].parts[0];
    std::size_t from = 0;
    for (std::size_t i = 0; i < body.size(); ++i) {
      bool ends = is_token(body[i], ";") || body[i].kind == piece_kind::body;
      // A nested namespace, or an extern "C" block, ends at its closing brace.
      if (is_group(body[i], "{") && from < i && is_word_piece(body[from]) &&
          (body[from].tok->is_word("namespace") || body[from].tok->is_word("extern")))
        ends = true;
      if (!ends) continue;
      declaration(body, from, body[i].kind == piece_kind::body || is_group(body[i], "{") ? i + 1 : i, inner);
      walk_range(body, from, i + 1);
      from = i + 1;
    }
  }

  void walk_range(const pieces& run, std::size_t s, std::size_t e) {
    for (std::size_t i = s; i < e; ++i) walk(run[i]);
  }

  std::vector<global_variable>& out_;
};

}  // namespace

std::vector<global_variable> find_globals(const program& p) {
  std::vector<global_variable> out;
  finder f(out);
  for (const top_item& it : p.items) {
    switch (it.kind) {
      case top_item::declaration: {
        std::size_t end = it.cxx.size();
        if (end && is_token(it.cxx[end - 1], ";")) --end;
        f.declaration(it.cxx, 0, end, "");
        // Functions defined here may hold static variables; a namespace's
        // were walked with its declarations.
        if (!(end && is_word_piece(it.cxx[0]) && it.cxx[0].tok->is_word("namespace"))) f.walk(it.cxx);
        break;
      }
      case top_item::parameter: {
        const parameter& d = p.parameters[it.parameter_index];
        out.push_back({std::string(d.name->text), std::string(d.type->text), d.name->line, false});
        break;
      }
      case top_item::block:
        f.walk(*it.block_body);
        break;
      case top_item::action:
        f.walk(*p.actions[it.action_index].body);
        break;
      case top_item::pick:
        f.walk(*p.pick->body);
        break;
      case top_item::property:
      case top_item::preproc: break;
    }
  }
  return out;
}

}  // namespace vvc
