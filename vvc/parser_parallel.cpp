// `parallel forall v in M statement` (LANGUAGE.md section 6.1): a forall
// whose iterations may run at once. It becomes a call with the body as a
// lambda, so what would leave the loop cannot be written in it: `break`
// and `return` are errors (a `continue` ends the iteration, the emitter
// makes it a `return`). The loop must be over a mesh: an operand written
// as a vertex (`` `v ``, a query) is an error here; one that is a vertex
// by its type only is a C++ error at the same line (vv/parallel.hpp).
#include "parser.hpp"

namespace vvc {

// parallel-forall = "parallel" forall
stmt_ptr parser::parse_parallel_forall() {
  const token* word = take();  // parallel
  stmt_ptr s = parse_forall();
  if (s->kind != stmt_kind::forall || !s->name || s->operands.empty() || s->children.empty()) return s;
  s->kind = stmt_kind::parallel_forall;
  parallel_loops_ = true;
  s->tok = word;
  const pieces& over = s->operands[0];
  if (over.size() == 1 && (over[0].kind == piece_kind::old_state || over[0].kind == piece_kind::query))
    error(*over[0].tok, "only a loop over a mesh can be parallel: this is a vertex (drop 'parallel' to visit its neighbours)");
  check_parallel_body(*s->children[0], true, *word);
  return s;
}

// Statements directly in the body (not in a nested loop, switch or lambda)
// may not leave it.
void parser::check_parallel_body(const stmt& s, bool loop_level, const token& loop) {
  const std::string where = "the parallel forall of line " + std::to_string(loop.line);
  switch (s.kind) {
    case stmt_kind::simple:
      if (s.head.empty() || s.head[0].kind != piece_kind::token) return;
      if (s.head[0].tok->is_word("return"))
        error(*s.head[0].tok, "'return' cannot leave " + where +
                                  ": its iterations run at once (use 'continue' to end an iteration)");
      else if (loop_level && s.head[0].tok->is_word("break"))
        error(*s.head[0].tok, "'break' cannot leave " + where + ": its iterations run at once, in no order");
      else if (s.head[0].tok->is_word("goto"))
        error(*s.head[0].tok, "'goto' cannot leave " + where + ": its iterations run at once");
      return;
    case stmt_kind::while_:
    case stmt_kind::do_while:
    case stmt_kind::for_:
    case stmt_kind::forall:
    case stmt_kind::switch_:
      // break belongs to these; return still leaves the whole loop.
      for (const stmt_ptr& c : s.children) check_parallel_body(*c, false, loop);
      return;
    case stmt_kind::parallel_forall:
      return;  // checked on its own
    default:
      for (const stmt_ptr& c : s.children) check_parallel_body(*c, loop_level, loop);
      return;
  }
}

}  // namespace vvc
