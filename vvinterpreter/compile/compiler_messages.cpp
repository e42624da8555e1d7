#include "compile/compiler_messages.hpp"

#include <cctype>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "app/files.hpp"

namespace vvi {

namespace {

using place = std::pair<std::string, int>;  // file, line

// The generated lines that stand for each .vvp line (from #line).
std::map<place, std::vector<std::string>> generated_lines(const std::string& cpp) {
  static const std::regex directive(R"re(^#line (\d+) "(.*)"$)re");
  std::map<place, std::vector<std::string>> out;
  std::istringstream in(cpp);
  std::string file, l;
  int line = 0;
  while (std::getline(in, l)) {
    std::smatch m;
    if (std::regex_match(l, m, directive)) {
      line = std::stoi(m[1]);
      file = m[2];
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

class vvp_files {
 public:
  const std::string& line(const std::string& file, int n) {
    auto it = lines_.find(file);
    if (it == lines_.end()) {
      std::vector<std::string> v;
      std::istringstream in(read_file(file).value_or(""));
      for (std::string l; std::getline(in, l);) v.push_back(l);
      it = lines_.emplace(file, std::move(v)).first;
    }
    static const std::string none;
    return n >= 1 && static_cast<std::size_t>(n) <= it->second.size() ? it->second[static_cast<std::size_t>(n - 1)]
                                                                         : none;
  }

 private:
  std::map<std::string, std::vector<std::string>> lines_;
};

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// "  12 | code" and "     |   ^~~~": the compiler's excerpt of a line.
bool is_excerpt(const std::string& l) {
  static const std::regex excerpt(R"(^ *\d* \|)");
  return std::regex_search(l, excerpt);
}

}  // namespace

std::string compiler_messages(const std::string& output, const std::string& vvlib_dir,
                              const std::string& generated_cpp) {
  // A line that starts a message names its file first: "f:12:5: error: ..."
  // or "f: In function ...". The lines after it (source, caret, notes
  // without a place) belong to it.
  static const std::regex located(R"(^([^ :][^:]*):(\d+):(\d+): (.*)$)");
  std::map<place, std::vector<std::string>> generated = generated_lines(generated_cpp);
  vvp_files files;
  std::istringstream in(output);
  std::string kept, line;
  bool keeping = false, about_vvp = false;
  while (std::getline(in, line)) {
    std::smatch m;
    bool starts = std::regex_match(line, m, located);
    if (starts || (line.find(": In ") != std::string::npos && line[0] != ' ')) {
      std::string path = line.substr(0, line.find(':'));
      keeping = path.rfind(vvlib_dir, 0) != 0 && path.rfind("/usr/", 0) != 0;
      about_vvp = ends_with(path, ".vvp");
      if (keeping && starts && about_vvp) {
        std::string file = m[1];
        int n = std::stoi(m[2]);
        const std::string& text = files.line(file, n);
        int col = vvp_column(text, generated[{file, n}], std::stoi(m[3]));
        kept += file + ":" + std::to_string(n) + (col ? ":" + std::to_string(col) : "") + ": " + std::string(m[4]) + "\n";
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
    if (!keeping) continue;
    if (about_vvp && is_excerpt(line)) continue;  // the compiler's caret is in the wrong column
    kept += line + "\n";
  }
  return kept;
}

}  // namespace vvi
