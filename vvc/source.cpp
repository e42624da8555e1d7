#include "source.hpp"

#include <cstdint>
#include <cstdio>

#include <vv/io/files.hpp>

namespace vvc {

namespace {

// CR LF (DOS) and a lone CR (old Mac) end a line as LF does, for GCC as for
// us: they become LF, so that every line count, #line directive and
// diagnostic agrees with the compiler's.
std::string with_lf_line_ends(std::string text) {
  if (text.find('\r') == std::string::npos) return text;
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\r') out += text[i];
    else if (i + 1 == text.size() || text[i + 1] != '\n') out += '\n';
  }
  return out;
}

}  // namespace

source_file::source_file(std::string p, std::string t) : path(std::move(p)), text(with_lf_line_ends(std::move(t))) {
  line_starts.push_back(0);
  for (std::size_t i = 0; i < text.size(); ++i)
    if (text[i] == '\n') line_starts.push_back(i + 1);
}

std::string_view source_file::line(int n) const {
  if (n < 1 || static_cast<std::size_t>(n) > line_starts.size()) return {};
  std::size_t begin = line_starts[static_cast<std::size_t>(n - 1)];
  std::size_t end = text.find('\n', begin);
  if (end == std::string::npos) end = text.size();
  return std::string_view(text).substr(begin, end - begin);
}

std::string source_file::folder() const { return vv::io::folder_of(path); }

const source_file* source_set::load(const std::string& path, std::string* why) {
  // Only a regular file of a sensible size is a program: a folder would read
  // as an empty program, /dev/zero would never end, a FIFO would block.
  std::optional<std::string> read = vv::io::read_file(path, why, vv::io::program_file_limit);
  if (!read) return nullptr;
  std::string text = std::move(*read);
  // A UTF-8 byte-order mark, as some editors write: not part of the program.
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);
  return add(path, std::move(text));
}

std::vector<std::string> source_set::paths() const {
  std::vector<std::string> out;
  for (const auto& f : files_) out.push_back(f->path);
  return out;
}

std::string source_set::text_hash() const {
  // Two FNV-1a streams, with a separator after each file.
  std::uint64_t a = 0xcbf29ce484222325ULL, b = 0x84222325cbf29ce4ULL;
  for (const auto& f : files_) {
    for (unsigned char c : f->text) {
      a = (a ^ c) * 0x100000001b3ULL;
      b = (b ^ c) * 0x100000001b3ULL + 0x9e3779b97f4a7c15ULL;
    }
    a = (a ^ 0xffu) * 0x100000001b3ULL;
    b = (b ^ 0xfeu) * 0x100000001b3ULL;
  }
  char out[33];
  std::snprintf(out, sizeof out, "%016llx%016llx", static_cast<unsigned long long>(a),
                static_cast<unsigned long long>(b));
  return out;
}

const source_file* source_set::add(std::string path, std::string text) {
  files_.push_back(std::make_unique<source_file>(std::move(path), std::move(text)));
  return files_.back().get();
}

}  // namespace vvc
