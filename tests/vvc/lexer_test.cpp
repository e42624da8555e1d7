// The lexer: every C++ token form, vv's three marks, positions, and the
// lexical errors.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lexer.hpp"

namespace {

struct lexed {
  vvc::source_set sources;
  vvc::diagnostics diag;
  std::vector<vvc::token> tokens;
};

lexed lex(const std::string& text) {
  lexed l;
  const vvc::source_file* f = l.sources.add("t.vvp", text);
  l.tokens = vvc::lex(*f, l.sources, l.diag);
  return l;
}

std::vector<std::string> texts(const std::string& text) {
  std::vector<std::string> out;
  for (const auto& t : lex(text).tokens)
    if (t.kind != vvc::tok::eof) out.emplace_back(t.text);
  return out;
}

using strings = std::vector<std::string>;

}  // namespace

TEST(Lexer, NumbersInEveryForm) {
  EXPECT_EQ(texts("0x1F 0b1010 1'000'000 3.5f .5 1e+5 1.5e-3L 0x1p-3 42u 7ull"),
            (strings{"0x1F", "0b1010", "1'000'000", "3.5f", ".5", "1e+5", "1.5e-3L", "0x1p-3", "42u", "7ull"}));
  auto l = lex("1e+5");
  EXPECT_EQ(l.tokens[0].kind, vvc::tok::number);
}

TEST(Lexer, StringsCharactersAndRawStrings) {
  EXPECT_EQ(texts(R"(s = "a \"q\" b"; c = '\''; u8"x"; L'y'; R"d(raw "x" ))d"; "x"s)"),
            (strings{"s", "=", R"("a \"q\" b")", ";", "c", "=", R"('\'')", ";", "u8\"x\"", ";", "L'y'", ";",
                     R"(R"d(raw "x" ))d")", ";", "\"x\"s"}));
}

TEST(Lexer, RawStringsMaySpanLinesAndKeepTheLineCount) {
  auto l = lex("a R\"(one\ntwo)\" b");
  ASSERT_EQ(l.tokens.size(), 4u);
  EXPECT_EQ(l.tokens[2].text, "b");
  EXPECT_EQ(l.tokens[2].line, 2);
}

TEST(Lexer, CommentsAreDroppedAndKeywordsInThemToo) {
  EXPECT_EQ(texts("a // nextto b in c\n/* make {a} nb_of b; */ b"), (strings{"a", "b"}));
}

TEST(Lexer, PreprocessorLinesStayWholeWithContinuations) {
  auto l = lex("#define TWICE(x) \\\n  ((x) + (x))\nint a;");
  ASSERT_GE(l.tokens.size(), 2u);
  EXPECT_EQ(l.tokens[0].kind, vvc::tok::preproc);
  EXPECT_EQ(l.tokens[0].text, "#define TWICE(x) \\\n  ((x) + (x))");
  EXPECT_EQ(l.tokens[1].text, "int");
  EXPECT_EQ(l.tokens[1].line, 3);
}

TEST(Lexer, HashInsideALineIsNoDirective) {
  auto l = lex("a # b");
  EXPECT_EQ(l.tokens[1].kind, vvc::tok::punct);
  EXPECT_EQ(l.tokens[1].text, "#");
}

TEST(Lexer, VvMarks) {
  auto l = lex("`v \xE2\x80\x98w x$pos @(a, b) next @");
  EXPECT_EQ(l.tokens[0].kind, vvc::tok::backtick);
  EXPECT_EQ(l.tokens[2].kind, vvc::tok::backtick);  // U+2018 too
  EXPECT_EQ(l.tokens[2].text, "\xE2\x80\x98");
  EXPECT_EQ(l.tokens[5].kind, vvc::tok::dollar);
  EXPECT_EQ(l.tokens[7].kind, vvc::tok::at);
}

TEST(Lexer, AnApostropheIsNeverTheOldStateMark) {
  auto l = lex("'c'");
  EXPECT_EQ(l.tokens[0].kind, vvc::tok::character);
  EXPECT_FALSE(l.diag.any());
}

TEST(Lexer, VvWordsOnlyAsWholeTokens) {
  EXPECT_EQ(texts("nexttoX vertexCount in_range mesh_count"),
            (strings{"nexttoX", "vertexCount", "in_range", "mesh_count"}));
}

TEST(Lexer, LongestPunctuators) {
  EXPECT_EQ(texts("a<<=b->*c...d::e>>=f<=>g"),
            (strings{"a", "<<=", "b", "->*", "c", "...", "d", "::", "e", ">>=", "f", "<=>", "g"}));
}

TEST(Lexer, LinesColumnsAndSpacing) {
  auto l = lex("a\n  bb c");
  EXPECT_EQ(l.tokens[1].line, 2);
  EXPECT_EQ(l.tokens[1].col, 3);
  EXPECT_TRUE(l.tokens[1].line_start);
  EXPECT_EQ(l.tokens[2].col, 6);
  EXPECT_TRUE(l.tokens[2].space_before);
}

TEST(Lexer, Errors) {
  struct {
    const char* text;
    int line, col;
    const char* message;
  } cases[] = {
      {"x = \"abc\ny;", 1, 5, "unterminated string literal"},
      {"c = 'a\n", 1, 5, "unterminated character literal"},
      {"a /* b\n c", 1, 3, "unterminated comment: '/*' has no '*/'"},
      {"s = R\"x(abc\n", 1, 5, "unterminated raw string literal"},
      {"a \\ b", 1, 3, "stray '\\' in program"},
      {"a \x01 b", 1, 3, "stray byte 1 in program"},
  };
  for (const auto& c : cases) {
    auto l = lex(c.text);
    ASSERT_TRUE(l.diag.any()) << c.text;
    EXPECT_EQ(l.diag.list()[0].line, c.line) << c.text;
    EXPECT_EQ(l.diag.list()[0].col, c.col) << c.text;
    EXPECT_EQ(l.diag.list()[0].message, c.message) << c.text;
  }
}

// Old Mac files end lines in a lone CR, DOS files in CR LF: each is a line
// end, as for GCC, also inside comments, continuations and raw strings.
TEST(Lexer, CrCrLfAndLfAllEndLines) {
  const std::string lf =
      "a\n/* two\nlines */ b\n#define M \\\n  1\nc // a comment \\\ncontinued\nd R\"(x\ny)\" e\n\nf \"g\\\nh\" i";
  for (std::string end : {"\r", "\r\n"}) {
    std::string text;
    for (char c : lf) text += c == '\n' ? end : std::string(1, c);
    auto expected = lex(lf);
    auto got = lex(text);
    ASSERT_FALSE(got.diag.any()) << vvc::format(got.diag.list()[0]);
    ASSERT_EQ(got.tokens.size(), expected.tokens.size());
    for (std::size_t i = 0; i < got.tokens.size(); ++i) {
      EXPECT_EQ(got.tokens[i].line, expected.tokens[i].line) << "token " << i << " " << got.tokens[i].text;
      EXPECT_EQ(got.tokens[i].col, expected.tokens[i].col) << "token " << i;
      EXPECT_EQ(got.tokens[i].text, expected.tokens[i].text) << "token " << i;
    }
  }
  auto l = lex("a\rb\r\nc\n\rd");
  ASSERT_EQ(l.tokens.size(), 5u);
  EXPECT_EQ(l.tokens[1].line, 2);
  EXPECT_EQ(l.tokens[2].line, 3);
  EXPECT_EQ(l.tokens[3].line, 5);
}
