// What the parser decides, seen through the C++ it produces: operand
// extents and precedence, vv-or-C++ decisions, pass-through, and that
// several independent errors are all reported. (Whether the translations
// behave as LANGUAGE.md says is checked by the programs in programs/.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <string>

#include "spelling.hpp"
#include "squeezed.hpp"
#include "translate.hpp"

namespace {

// The C++ of `code` placed in a function body.
std::string in_function(const std::string& code) {
  vvc::translation t = vvc::translate_text("t.vvp", "void f() {\n" + code + "\n}\n");
  std::string errors;
  for (const auto& d : t.diag.list()) errors += vvc::format(d);
  EXPECT_TRUE(t.ok) << errors;
  return squeeze(t.cpp);
}

void expect_translation(const std::string& vv, const std::string& cxx) {
  std::string out = in_function(vv);
  EXPECT_NE(out.find(squeeze(cxx)), std::string::npos) << vv << "\n  became\n" << out;
}

// A failed translation (its diagnostics point into its own sources).
vvc::translation failed(const std::string& program) {
  vvc::translation t = vvc::translate_text("t.vvp", program);
  EXPECT_FALSE(t.ok);
  EXPECT_TRUE(t.cpp.empty());
  return t;
}

}  // namespace

TEST(Translation, QueryOperandsAreUnaryExpressions) {
  expect_translation("x = a + nextto b in c$x;", "x = a + vv::next_to(b, c.props().x);");
  expect_translation("n = valence `v + 1;", "n = vv::valence(vv::old(v)) + 1;");
  expect_translation("p = (nextto u in `v)$pos * 0.125;",
                     "p = (vv::next_to(u, vv::old(v))).props().pos * 0.125;");
  expect_translation("y = nextto _nextto(a) in f(a, b, prevto b in c);",
                     "y = vv::next_to(_nextto(a), f(a, b, vv::prev_to(b, c)));");
  expect_translation("y = nextto (nextto _nextto(a) in f(a, b, prevto b in c)) in a;",
                     "y = vv::next_to((vv::next_to(_nextto(a), f(a, b, vv::prev_to(b, c)))), a);");
  expect_translation("z = nextto nextto a in b in c;", "z = vv::next_to(vv::next_to(a, b), c);");
}

TEST(Translation, TheOldStateTakesAPostfixExpressionAndBindsBeforeDollar) {
  expect_translation("p = `v$pos;", "p = vv::old(v).props().pos;");
  expect_translation("x = `q[8]$x;", "x = vv::old(q[8]).props().x;");
  expect_translation("x = `f(a)$x;", "x = vv::old(f(a)).props().x;");
  expect_translation("x = f(a)$x;", "x = f(a).props().x;");
  expect_translation("x = `s.v->w$x;", "x = vv::old(s.v->w).props().x;");
  expect_translation("x = \xE2\x80\x98v$x;", "x = vv::old(v).props().x;");
}

TEST(Translation, IndexedNextAndPrevAreVvOnlyBeforeTo) {
  expect_translation("w = next(2)to u in `v;", "w = vv::next_to(u, vv::old(v), (2));");
  expect_translation("w = prev(i + 1)to u in v;", "w = vv::prev_to(u, v, (i + 1));");
  expect_translation("auto it = std::next(i); auto j = next(i);", "auto it = std::next(i); auto j = next(i);");
}

TEST(Translation, ContextWordsStayIdentifiersElsewhere) {
  expect_translation("int any = 1, is = 2, in = 3, to = 4; any = is + in * to;",
                     "int any = 1, is = 2, in = 3, to = 4; any = is + in * to;");
  expect_translation("bool b = is x in M;", "bool b = vv::is_in(x, M);");
  expect_translation("b = is nextto a in v in w;", "b = vv::is_in(vv::next_to(a, v), w);");
  expect_translation("b = is @(a, b) next @ in c;", "b = vv::is_in(vv::path(a, b).next().second(), c);");
  expect_translation("b = is prev(2)to a in `v in c;", "b = vv::is_in(vv::prev_to(a, vv::old(v), (2)), c);");
  expect_translation("v = any in w; f = flagged in w;", "v = vv::any_in(w); f = vv::flagged_in(w);");
  expect_translation("int nexttoX = 1, vertexCount = 2; bool in_range;",
                     "int nexttoX = 1, vertexCount = 2; bool in_range;");
}

TEST(Translation, EdgeAccessOnlyInParenthesesThatAreNoCall) {
  expect_translation("(a^b).mark = 3;", "(vv::edge_hat(a, b)).mark = 3;");
  expect_translation("k = (i|j) + (i^j);", "k = (vv::edge_bar(i, j)) + (vv::edge_hat(i, j));");
  expect_translation("c = ((`v)|u).crease;", "c = (vv::edge_bar((vv::old(v)), u)).crease;");
  expect_translation("g(a^b); h = i | j; k = (i | j | l);", "g(a^b); h = i | j; k = (i | j | l);");
}

TEST(Translation, Paths) {
  expect_translation("w = @(a, b) swap next @;", "w = vv::path(a, b).swap().next().second();");
  expect_translation("w = `@(a, b) next, prev @;", "w = vv::old_path(a, b).next().prev().second();");
  expect_translation("@&(a, b) swap next @;", "vv::path_into(a, b).swap().next().store();");
  expect_translation("`@&(a, b) swap next @;", "vv::old_path_into(a, b).swap().next().store();");
}

TEST(Translation, EditsAndTheirCxxLookalikes) {
  expect_translation("make {a, b, c} nb_of v;", "vv::make_nb(v, {a, b, c});");
  expect_translation("erase x from v;", "vv::erase_from(x, v);");
  expect_translation("erase flag from v;", "vv::erase_flag(v);");
  expect_translation("replace a with x in `v;", "vv::replace_in(a, x, vv::old(v));");
  expect_translation("splice x before flag in v;", "vv::splice_before_flag(x, v);");
  expect_translation("add (x) to M; remove x from M;", "vv::add_to((x), M); vv::remove_from(x, M);");
  expect_translation("splice (x) after a in v;", "vv::splice_after((x), a, v);");
  expect_translation("synchronize M; clear M;", "vv::synchronise(M); vv::clear(M);");
  // Calls of C++ functions that share an edit's name stay calls.
  expect_translation("erase(it); remove(\"file\"); add(1, 2); merge = 3;",
                     "erase(it); remove(\"file\"); add(1, 2); merge = 3;");
}

TEST(Translation, VertexDeclarations) {
  expect_translation("vertex a, b(p, 2.0), c = a, d = 0;",
                     "vertex a = vv_new_vertex(); vertex b = vv_new_vertex_with(p, 2.0); "
                     "vertex c = a; vertex d = 0;");
  expect_translation("vertex& r = a; vertex* q = &a;", "vertex& r = a; vertex* q = &a;");
}

TEST(Translation, ForallOverAnyOperand) {
  expect_translation("forall x in nextto a in b { f(x); }",
                     "for ([[maybe_unused]] auto&& x : vv::each(vv::next_to(a, b))) { f(x); }");
  expect_translation("forall x in `v n++;", "for ([[maybe_unused]] auto&& x : vv::each(vv::old(v))) n++;");
}

TEST(Translation, CommentsAndStringsAreNotTranslated) {
  expect_translation("s = \"nextto a in b\"; // make {a} nb_of b;", "s = \"nextto a in b\";");
  std::string out = in_function("s = \"nextto a in b\"; // make {a} nb_of b;");
  EXPECT_EQ(out.find("make_nb"), std::string::npos);
}

TEST(Translation, VvInsideLambdasTernariesAndTemplateArguments) {
  expect_translation("auto g = [&](vertex v) { add v to M; return nextto v in w; };",
                     "auto g = [&](vertex v) { vv::add_to(v, M); return vv::next_to(v, w); };");
  expect_translation("u = c ? nextto a in b : prevto a in b;", "u = c ? vv::next_to(a, b) : vv::prev_to(a, b);");
  expect_translation("std::vector<decltype(nextto a in b)> vs;", "std::vector<decltype(vv::next_to(a, b))> vs;");
}

TEST(Translation, ExecutionBlocksOnlyAtTopLevelBeforeBrace) {
  vvc::translation t = vvc::translate_text("t.vvp", "int step = 0;\nvoid f() { step++; }\nstep {\n f();\n}\n");
  ASSERT_TRUE(t.ok);
  std::string out = squeeze(t.cpp);
  EXPECT_NE(out.find("intstep=0;"), std::string::npos);
  EXPECT_NE(out.find("staticvoidvv_block_step(){f();}"), std::string::npos);
  EXPECT_NE(out.find("returnvv_model.run(vv_block_step);"), std::string::npos);
}

TEST(Translation, LineDirectivesFollowTheSource) {
  vvc::translation t = vvc::translate_text("dir/m.vvp", "int a;\n\n\n\n\n\n\n\n\n\n\n\nint b;\n");
  ASSERT_TRUE(t.ok);
  EXPECT_NE(t.cpp.find("#line 1 \"dir/m.vvp\"\nint a;"), std::string::npos) << t.cpp;
  EXPECT_NE(t.cpp.find("#line 13 \"dir/m.vvp\"\nint b;"), std::string::npos) << t.cpp;
}

// A string continued over two lines, or a raw string, is one token of
// several lines: the lines after it keep their numbers.
TEST(Translation, LinesAfterATokenOfSeveralLinesKeepTheirNumbers) {
  vvc::translation t =
      vvc::translate_text("m.vvp", "const char* s = \"a\\\nb\";\nconst char* r = R\"(c\nd)\";\nint x;\n");
  ASSERT_TRUE(t.ok);
  std::size_t at = t.cpp.find("int x;");
  ASSERT_NE(at, std::string::npos) << t.cpp;
  std::size_t directive = t.cpp.rfind("#line 1 \"m.vvp\"\n", at);
  ASSERT_NE(directive, std::string::npos) << t.cpp;
  EXPECT_EQ(std::count(t.cpp.begin() + static_cast<long>(directive), t.cpp.begin() + static_cast<long>(at), '\n'), 5)
      << t.cpp;  // "int x;" on line 5: the directive's own newline and four more
}

TEST(Translation, GlobalMeshesAreListedForTheHost) {
  vvc::translation t = vvc::translate_text("t.vvp", "mesh S, T;\nstatic mesh U;\nmesh f();\n");
  ASSERT_TRUE(t.ok);
  EXPECT_NE(t.cpp.find("{\"S\","), std::string::npos);
  EXPECT_NE(t.cpp.find("{\"T\","), std::string::npos);
  EXPECT_NE(t.cpp.find("{\"U\","), std::string::npos);
  EXPECT_EQ(t.cpp.find("{\"f\","), std::string::npos);
  EXPECT_NE(t.cpp.find("vv_d.mesh_count = 3;"), std::string::npos) << t.cpp;  // the descriptor's mesh count
}

TEST(Diagnostics, IndependentErrorsAreAllReported) {
  vvc::translation t =
      failed("void f() {\n  x = nextto a b;\n}\nvoid g() {\n  erase x v;\n}\nstart {\n  y = valence ;\n}\n");
  const auto& errors = t.diag.list();
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_EQ(errors[0].line, 2);
  EXPECT_EQ(errors[1].line, 5);
  EXPECT_EQ(errors[2].line, 8);
}

TEST(Diagnostics, FormatHasFileLineColumnSourceLineAndCaret) {
  vvc::translation t = failed("void f() {\n\tx = nextto a b;\n}\n");
  const auto& errors = t.diag.list();
  ASSERT_FALSE(errors.empty());
  EXPECT_EQ(vvc::format(errors[0]),
            "t.vvp:2:15: error: expected 'in' after the operand of 'nextto', found 'b'\n"
            "  \tx = nextto a b;\n"
            "  \t             ^\n");
}

// A long line is cut around the caret: 200 characters at most, "..." at
// each cut, the caret under the same character, no UTF-8 character split.
TEST(Diagnostics, ALongLineIsCutAroundTheCaret) {
  std::string before, after;
  for (int i = 0; i < 1000; ++i) before += "\xC3\xA9", after += "\xC3\xA9";  // é
  vvc::translation t = failed("void f() {\n\tx = g(\"" + before + "\") + nextto a b+ g(\"" + after + "\");\n}\n");
  ASSERT_FALSE(t.diag.list().empty());
  std::string text = vvc::format(t.diag.list()[0]);
  std::size_t l1 = text.find('\n'), l2 = text.find('\n', l1 + 1);
  std::string shown = text.substr(l1 + 3, l2 - l1 - 3), caret = text.substr(l2 + 3);
  ASSERT_EQ(shown.compare(0, 3, "..."), 0) << shown;
  ASSERT_EQ(shown.compare(shown.size() - 3, 3, "..."), 0) << shown;
  auto characters = [](const std::string& s) {
    return std::count_if(s.begin(), s.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; });
  };
  EXPECT_EQ(characters(shown), 206);  // 200 and the two marks
  EXPECT_EQ(caret.find_first_not_of(' '), caret.size() - 2) << caret;  // spaces, then "^\n"
  // The caret's column in the shown line is the 'b' the message names.
  std::size_t column = caret.size() - 2, byte = 0;
  for (std::size_t c = 0; byte < shown.size(); ++byte) {
    if ((static_cast<unsigned char>(shown[byte]) & 0xC0) == 0x80) continue;
    if (c++ == column) break;
  }
  EXPECT_EQ(shown.substr(byte, 2), "b+") << shown << "\n" << caret;
  // A short line is shown whole.
  vvc::translation s = failed("void f() {\n  x = nextto a b;\n}\n");
  EXPECT_EQ(vvc::format(s.diag.list()[0]),
            "t.vvp:2:16: error: expected 'in' after the operand of 'nextto', found 'b'\n"
            "    x = nextto a b;\n"
            "                 ^\n");
}

TEST(Diagnostics, EmptyDeclaratorInAPropertyBlockIsReported) {
  // Found by the fuzzer: the empty declarator has no token of its own.
  vvc::translation t = failed("vertex {\n  int a, ;\n};\n");
  ASSERT_FALSE(t.diag.list().empty());
  EXPECT_EQ(t.diag.list()[0].message, "expected a property name in this declaration");
  EXPECT_EQ(t.diag.list()[0].line, 2);
}

// Issue 9, item 6: 10,000 nested paths or queries overflowed the stack:
// their parsing did not go through the nesting guard. Item 11: 10,000
// balanced parentheses gave 24 false "unterminated '('" errors before the
// real one. Each is now exactly one error: "nested too deeply".
TEST(Nesting, DeepPathsQueriesAndParenthesesAreOneClearError) {
  const int n = 10000;
  auto repeat = [](const std::string& s, int k) {
    std::string out;
    for (int i = 0; i < k; ++i) out += s;
    return out;
  };
  const std::string programs[] = {
      "void f(vertex a, vertex b) { vertex c = " + repeat("@(", n) + "a, b" + repeat(") next @", n) + "; }\n",
      "void f(vertex a, vertex b) { vertex c = " + repeat("nextto (", n) + "a" + repeat(") in b", n) + "; }\n",
      "void f(vertex a, vertex b) { vertex c = " + repeat("next(", n) + "1" + repeat(")to a in b", n) + "; }\n",
      "int x = " + repeat("(", n) + "1" + repeat(")", n) + ";\n",
  };
  for (const std::string& program : programs) {
    vvc::translation t = failed(program);
    ASSERT_EQ(t.diag.list().size(), 1u) << program.substr(0, 60);
    EXPECT_NE(vvc::format(t.diag.list()[0]).find("error: nested too deeply (more than 256 levels)"),
              std::string::npos)
        << vvc::format(t.diag.list()[0]);
  }
}

TEST(Spelling, EditDistanceCountsASwapOfNeighboursAsOneEdit) {
  EXPECT_EQ(vvc::edit_distance("nexto", "nextto", 2), 1u);
  EXPECT_EQ(vvc::edit_distance("prevot", "prevto", 2), 1u);  // Levenshtein would say 2
  EXPECT_EQ(vvc::edit_distance("valance", "valence", 2), 1u);
  EXPECT_EQ(vvc::edit_distance("synchronis", "synchronise", 2), 1u);
  EXPECT_EQ(vvc::edit_distance("rplce", "replace", 2), 2u);
  EXPECT_EQ(vvc::edit_distance("ab", "ba", 2), 1u);
  EXPECT_EQ(vvc::edit_distance("", "ab", 2), 2u);
  EXPECT_EQ(vvc::edit_distance("abc", "xyz", 2), 3u);  // beyond the limit: limit + 1
  EXPECT_EQ(vvc::edit_distance("a", "abcdef", 2), 3u);
}

// Each misspelling is reported once, at the name, with the word meant.
TEST(Spelling, AMisspeltVvWordIsNamedWithTheWordMeant) {
  const std::string head = "vertex { double c; };\nmesh M;\n";
  struct {
    std::string code;
    int line, col;
    std::string message;
  } cases[] = {
      {"vertex f(vertex v, vertex u) { return nexto u in v; }", 3, 39, "unknown word 'nexto'; did you mean 'nextto'?"},
      {"vertex f(vertex v, vertex u) { return Nextto u in v; }", 3, 39, "unknown word 'Nextto'; did you mean 'nextto'?"},
      {"vertex f(vertex v, vertex u) { return nxt(2) to u in v; }", 3, 39, "unknown word 'nxt'; did you mean 'next'?"},
      {"vertex f(vertex v) { return ani in v; }", 3, 29, "unknown word 'ani'; did you mean 'any'?"},
      {"vertex f(vertex v) { return flaged in v; }", 3, 29, "unknown word 'flaged'; did you mean 'flagged'?"},
      {"bool f(vertex v, vertex u) { return iss u in v; }", 3, 37, "unknown word 'iss'; did you mean 'is'?"},
      {"unsigned f(vertex v) { return lableof v; }", 3, 31, "unknown word 'lableof'; did you mean 'labelof'?"},
      {"unsigned f(vertex v) { unsigned n = 0; n += valance `v; return n; }", 3, 45,
       "unknown word 'valance'; did you mean 'valence'?"},
      {"void f(vertex v, vertex a, vertex b) { mak {a, b} nb_of v; }", 3, 40, "unknown word 'mak'; did you mean 'make'?"},
      {"void f(vertex v, vertex a, vertex b) { splce a after b in v; }", 3, 40,
       "unknown word 'splce'; did you mean 'splice'?"},
      {"void f(vertex v, vertex a, vertex b) { splice a befor b in v; }", 3, 49,
       "expected 'after' or 'before' in 'splice', found 'befor'"},
      {"void f(vertex v, vertex a) { flg a in v; }", 3, 30, "unknown word 'flg'; did you mean 'flag'?"},
      {"void f(vertex a) { ad a to M; }", 3, 20, "unknown word 'ad'; did you mean 'add'?"},
      {"void f(vertex a) { remov a from M; }", 3, 20, "unknown word 'remov'; did you mean 'remove'?"},
      {"void f(mesh& N) { merg M with N; }", 3, 19, "unknown word 'merg'; did you mean 'merge'?"},
      {"void f() { clera M; }", 3, 12, "unknown word 'clera'; did you mean 'clear'?"},
      {"void f() { synchronse M; }", 3, 12, "unknown word 'synchronse'; did you mean 'synchronise'?"},
      {"step { foral v in M { v$c = 1; } }", 3, 8, "unknown word 'foral'; did you mean 'forall'?"},
      {"stpe { forall v in M v$c = 1; }", 3, 1, "unknown word 'stpe'; did you mean 'step'?"},
      {"rendr { }", 3, 1, "unknown word 'rendr'; did you mean 'render'?"},
      {"strat { }", 3, 1, "unknown word 'strat'; did you mean 'start'?"},
  };
  for (const auto& c : cases) {
    vvc::translation t = failed(head + c.code + "\n");
    ASSERT_EQ(t.diag.count(), 1u) << c.code << "\n" << (t.diag.any() ? vvc::format(t.diag.list()[0]) : "");
    const vvc::diagnostic& d = t.diag.list()[0];
    EXPECT_EQ(d.message, c.message) << c.code;
    EXPECT_EQ(d.line, c.line) << c.code;
    EXPECT_EQ(d.col, c.col) << c.code;
  }
}

// A name a letter or two from a vv word, where C++ may use a name: never
// taken for a misspelling (near_vv_words.vvp compiles and runs such names).
TEST(Spelling, NamesThatCxxMayUseAreNeverTaken) {
  const char* programs[] = {
      "struct Flag { int x; };\nvoid f() { Flag in; in.x = 1; Flag to, from; to = from; }\n",
      "int f() { int valance = 3; int y = valance; return y + valance * 2 - valance; }\n",
      "double valance(int); int f(int v) { int n = valance(v); return n + valance (v); }\n",
      "void eras(int); void f(int x) { eras(x); eras (x); }\n",
      "struct eras {}; void f() { eras x; (void)x; }\n",
      "int nexto = 1; int f() { nexto = nexto + 1; return -nexto * nexto; }\n",
      "struct S { int nexto(int); }; int f(S s) { return s.nexto(2); }\n",
      "template <class valance, valance v> struct S {};\nvoid g(valance v);\n",
      "int stpe = 3;\nint strat{4};\n",
      "void f() { const char* s = \"nexto u in v\"; (void)s; } // nexto u in v\n",
      "struct lableof {}; lableof f(lableof a) { return a; }\n",
      "struct Node { int x; }; void f() { Node * from = nullptr; Node& to = *from; (void)to; }\n",
      "enum Flag { from, to }; Flag f() { Flag x = from; return x; }\n",
      "struct Nexto { Nexto(int); }; void f(int u) { auto p = new Nexto(u); (void)p; }\n",
      // `in` ends a parameter's value: iss(1) is a call there
      "double iss(double);\nparam double x = iss(1) in [0, 3];\n",
      // `clera M;` declares M, when clera may be a type: of a header of the
      // program's own, or the program's (M declared nowhere as a mesh)
      "#include \"own.hpp\"\nmesh M;\nvoid f() { clera M; }\n",
      "void f() { clera M; }\n",
      "struct clera {}; mesh M;\nvoid f() { clera M; }\n",
  };
  for (const char* p : programs) {
    vvc::translation t = vvc::translate_text("t.vvp", p);
    EXPECT_TRUE(t.ok) << p << "\n" << (t.diag.any() ? vvc::format(t.diag.list()[0]) : "");
  }
}
