#include "compile/compiler_messages.hpp"

#include <cctype>
#include <climits>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include <vv/io/files.hpp>

#include "app/files.hpp"
#include "compile/property_messages.hpp"
#include "compile/text_ends.hpp"
#include "source.hpp"

namespace vvi {

namespace {

using place = std::pair<std::string, long long>;  // file, line

// A line or column number as the compiler or a #line wrote it: nothing when
// it is not all digits or does not fit below `limit` (a #line of 3000000000
// is legal; g++ then prints it wrapped to a negative number).
std::optional<long long> number(const std::string& digits, long long limit) {
  if (digits.empty() || digits.size() > 18 || digits.find_first_not_of("0123456789") != std::string::npos)
    return std::nullopt;
  long long n = std::stoll(digits);
  if (n > limit) return std::nullopt;
  return n;
}

// The generated lines that stand for each .vvp line (from #line).
std::map<place, std::vector<std::string>> generated_lines(const std::string& cpp) {
  std::map<place, std::vector<std::string>> out;
  std::istringstream in(cpp);
  std::string file, l;
  long long line = 0;
  while (std::getline(in, l)) {
    // #line N "FILE"
    if (l.rfind("#line ", 0) == 0) {
      std::size_t space = l.find(' ', 6);
      std::optional<long long> n = number(l.substr(6, space == std::string::npos ? space : space - 6), LLONG_MAX);
      bool named = space != std::string::npos && l.size() >= space + 3 && l[space + 1] == '"' && l.back() == '"';
      if (n && named) {
        line = *n;
        file = l.substr(space + 2, l.size() - space - 3);
      } else {
        file.clear();  // a directive this does not understand: its lines stand for nothing known
      }
      continue;
    }
    if (!file.empty()) out[{file, line}].push_back(l);
    ++line;
  }
  return out;
}

bool is_word(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The token that starts at (or contains) 1-based column col.
std::string token_at(const std::string& text, int col) {
  if (col < 1 || static_cast<std::size_t>(col) > text.size()) return "";
  std::size_t i = static_cast<std::size_t>(col - 1);
  if (std::isspace(static_cast<unsigned char>(text[i]))) return "";
  if (!is_word(text[i])) return std::string(1, text[i]);
  std::size_t b = i, e = i;
  while (b > 0 && is_word(text[b - 1])) --b;
  while (e < text.size() && is_word(text[e])) ++e;
  return text.substr(b, e - b);
}

// Where `token` stands in text as a whole token, in order.
std::vector<std::size_t> occurrences(const std::string& text, const std::string& token) {
  std::vector<std::size_t> out;
  bool word = is_word(token[0]);
  for (std::size_t at = text.find(token); at != std::string::npos; at = text.find(token, at + 1)) {
    bool alone = !word || ((at == 0 || !is_word(text[at - 1])) &&
                           (at + token.size() >= text.size() || !is_word(text[at + token.size()])));
    if (alone) out.push_back(at);
  }
  return out;
}

// The .vvp column of the token the compiler pointed at, or 0 when it cannot
// be told (the token was written by the translator, or it is ambiguous).
int vvp_column(const std::string& vvp_line, const std::vector<std::string>& generated, int col) {
  std::set<std::size_t> found;
  for (const std::string& g : generated) {
    std::string tok = token_at(g, col);
    if (tok.empty()) continue;
    std::vector<std::size_t> in_vvp = occurrences(vvp_line, tok);
    std::vector<std::size_t> in_cpp = occurrences(g, tok);
    std::size_t index = 0;
    while (index < in_cpp.size() && in_cpp[index] + tok.size() <= static_cast<std::size_t>(col - 1)) ++index;
    // The k-th occurrence on the generated line is the k-th on the .vvp line
    // when both hold it equally often.
    if (in_vvp.size() == 1) found.insert(in_vvp[0]);
    else if (!in_vvp.empty() && in_vvp.size() == in_cpp.size() && index < in_vvp.size()) found.insert(in_vvp[index]);
  }
  return found.size() == 1 ? static_cast<int>(*found.begin()) + 1 : 0;
}

// The .vvp lines messages quote, read once per file. Only a regular file of
// a program's size is read: a #line may name anything.
class vvp_files {
 public:
  const std::string& line(const std::string& file, int n) {
    auto it = lines_.find(file);
    if (it == lines_.end()) {
      std::vector<std::string> v;
      std::error_code ec;
      if (std::filesystem::is_regular_file(file, ec) && std::filesystem::file_size(file, ec) <= vv::io::program_file_limit.bytes) {
        std::istringstream in(read_file(file).value_or(""));
        for (std::string l; std::getline(in, l);) v.push_back(l);
      }
      it = lines_.emplace(file, std::move(v)).first;
    }
    static const std::string none;
    return n >= 1 && static_cast<std::size_t>(n) <= it->second.size() ? it->second[static_cast<std::size_t>(n - 1)]
                                                                         : none;
  }

 private:
  std::map<std::string, std::vector<std::string>> lines_;
};

// "  12 | code" and "     |   ^~~~": the compiler's excerpt of a line.
bool is_excerpt(const std::string& l) {
  std::size_t i = l.find_first_not_of(' ');
  if (i == std::string::npos) return false;
  if (l[i] == '|') return i > 0;  // no line number
  i = l.find_first_not_of("0123456789", i);
  return i != std::string::npos && l.compare(i, 2, " |") == 0;
}

// The file named by a line that starts a message ("f:12:5: error: ...",
// "f: In function ...", "f: At global scope:"), or "". Its line and column
// need not be numbers this can use ("f:-1294967296:3: ..." after a #line
// beyond what g++ counts).
std::string message_file(const std::string& l) {
  if (l.empty() || l[0] == ' ' || l[0] == ':') return "";
  std::size_t colon = l.find(':');
  if (colon == std::string::npos || colon + 1 >= l.size()) return "";
  char next = l[colon + 1];
  bool numbered = std::isdigit(static_cast<unsigned char>(next)) || next == '-';
  if (numbered || l.compare(colon, 5, ": In ") == 0 || l.compare(colon, 5, ": At ") == 0) return l.substr(0, colon);
  return "";
}

// clang's closing count ("3 errors generated.", "1 warning generated."):
// not a message of the program's.
bool is_count(const std::string& l) {
  return !l.empty() && std::isdigit(static_cast<unsigned char>(l[0])) && ends_with(l, " generated.") &&
         (l.find(" error") != std::string::npos || l.find(" warning") != std::string::npos);
}

// "f:12:5: message", with a line and a column that fit an int.
struct location {
  std::string file;
  int line = 0, column = 0;
  std::string message;
};

std::optional<location> located(const std::string& l, const std::string& file) {
  std::size_t line_end = l.find(':', file.size() + 1);
  if (line_end == std::string::npos) return std::nullopt;
  std::size_t column_end = l.find(':', line_end + 1);
  if (column_end == std::string::npos || l.compare(column_end, 2, ": ") != 0) return std::nullopt;
  std::optional<long long> line = number(l.substr(file.size() + 1, line_end - file.size() - 1), INT_MAX);
  std::optional<long long> column = number(l.substr(line_end + 1, column_end - line_end - 1), INT_MAX);
  if (!line || !column || *line < 1) return std::nullopt;
  return location{file, static_cast<int>(*line), static_cast<int>(*column), l.substr(column_end + 2)};
}

}  // namespace

std::string plain_quotes(std::string text) {
  // g++ quotes with U+2018/U+2019 (and U+201C/U+201D) in a UTF-8 locale;
  // the viewer's font has no glyph for them.
  static const std::pair<const char*, char> typographic[] = {
      {"\xE2\x80\x98", '\''}, {"\xE2\x80\x99", '\''}, {"\xE2\x80\x9C", '"'}, {"\xE2\x80\x9D", '"'}};
  for (const auto& [from, to] : typographic)
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + 1))
      text.replace(at, 3, 1, to);
  return text;
}

std::string compiler_messages(const std::string& output, const message_sources& sources) {
  // A line that starts a message names its file first: "f:12:5: error: ..."
  // or "f: In function ...". The lines after it (source, caret, notes
  // without a place) belong to it.
  std::map<place, std::vector<std::string>> generated = generated_lines(sources.generated_cpp);
  vvp_files files;
  std::istringstream in(plain_quotes(output));
  std::string kept, line;
  bool keeping = false, about_vvp = false;
  // After a message about a .vvp line come the compiler's excerpts of the
  // generated C++ (g++'s "  12 | ...", clang's bare code, carets and
  // fix-its): the message's own excerpt of the .vvp line replaces them.
  bool in_excerpt = false;
  while (std::getline(in, line)) {
    if (is_count(line)) continue;
    std::string path = message_file(line);
    in_excerpt = in_excerpt && path.empty();
    if (!path.empty()) {
      keeping = path.rfind(sources.vvlib_dir, 0) != 0 && path.rfind("/usr/", 0) != 0;
      about_vvp = ends_with(path, ".vvp");
      in_excerpt = about_vvp && line.find(": In ") == std::string::npos && line.find(": At ") == std::string::npos;
      std::optional<location> at = keeping && about_vvp ? located(line, path) : std::nullopt;
      if (at) {
        const std::string& text = files.line(at->file, at->line);
        int col = vvp_column(text, generated[{at->file, at->line}], at->column);
        std::string message = property_message(at->message, sources.fields);
        if (message.empty()) message = at->message;
        kept += at->file + ":" + std::to_string(at->line) + (col ? ":" + std::to_string(col) : "") + ": " + message + "\n";
        kept += "  " + text + "\n";
        if (col) {
          std::string pad = "  ";
          for (int i = 0; i + 1 < col && static_cast<std::size_t>(i) < text.size(); ++i)
            pad += text[static_cast<std::size_t>(i)] == '\t' ? '\t' : ' ';
          kept += pad + "^\n";
        }
        continue;
      }
    } else if (line.rfind("In file included from", 0) == 0 || line.rfind("                 from", 0) == 0) {
      keeping = false;
      continue;
    }
    if (!keeping || (in_excerpt && path.empty())) continue;
    if (about_vvp && is_excerpt(line)) continue;  // the compiler's caret is in the wrong column
    kept += line + "\n";
  }
  return kept;
}

}  // namespace vvi
