// What the parser decides, seen through the C++ it produces: operand
// extents and precedence, vv-or-C++ decisions, pass-through, and that
// several independent errors are all reported. (Whether the translations
// behave as LANGUAGE.md says is checked by the programs in programs/.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <string>

#include "translate.hpp"

namespace {

std::string squeeze(std::string s) {
  s.erase(std::remove_if(s.begin(), s.end(), [](unsigned char c) { return std::isspace(c); }), s.end());
  return s;
}

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
                     "for (vertex x : vv::each(vv::next_to(a, b))) { f(x); }");
  expect_translation("forall x in `v n++;", "for (vertex x : vv::each(vv::old(v))) n++;");
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
  EXPECT_NE(out.find("returnvv::plugin::guarded(vv_exchange,vv_block_step);"), std::string::npos);
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
  EXPECT_NE(t.cpp.find("vv_mesh_table, 3,"), std::string::npos) << t.cpp;  // the descriptor's mesh count
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
