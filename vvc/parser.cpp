#include "parser.hpp"

namespace vvc {

const token& parser::peek(std::size_t k) const {
  std::size_t i = pos_ + k;
  return i < toks_.size() ? toks_[i] : toks_.back();  // the last token is eof
}

const token* parser::take() {
  const token* t = &toks_[pos_];
  if (pos_ + 1 < toks_.size()) ++pos_;
  return t;
}

bool parser::accept(std::string_view text) {
  if (!at(text)) return false;
  take();
  return true;
}

std::string parser::found(const token& t) {
  return t.kind == tok::eof ? "the end of the file" : "'" + std::string(t.text) + "'";
}

const token* parser::expect(std::string_view text, const std::string& context) {
  if (at(text)) return take();
  error(peek(), "expected '" + std::string(text) + "' " + context + ", found " + found(peek()));
  return nullptr;
}

bool parser::enter() {
  if (++nesting_ <= max_nesting) return true;
  if (nesting_ == max_nesting + 1)
    error(peek(), "nested too deeply (more than " + std::to_string(max_nesting) + " levels)");
  pos_ = toks_.size() - 1;  // give up on the rest: it cannot be translated
  gave_up_ = true;
  return false;
}

void parser::recover() {
  int nesting = 0;
  while (!at_end()) {
    const token& t = peek();
    if (t.is("(") || t.is("[") || t.is("{")) ++nesting;
    if (t.is(")") || t.is("]") || t.is("}")) {
      if (nesting == 0) return;  // the enclosing construct's closer
      --nesting;
    }
    take();
    if (nesting == 0 && (t.is(";") || t.is("}"))) return;
  }
}

}  // namespace vvc
