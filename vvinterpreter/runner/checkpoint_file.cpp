#include "runner/checkpoint_file.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "compile/hashing.hpp"

namespace vvi {

namespace {

constexpr const char* magic = "vv checkpoint";
constexpr int format_version = 1;

// "NAME VALUE" of a header line; false when the line is not of that name.
bool field(const std::string& line, const char* name, std::string& value) {
  std::size_t n = std::strlen(name);
  if (line.compare(0, n, name) != 0 || line.size() <= n || line[n] != ' ') return false;
  value = line.substr(n + 1);
  return true;
}

bool whole_number(const std::string& s, unsigned long long& out) {
  if (s.empty() || s.size() > 20 || s.find_first_not_of("0123456789") != std::string::npos) return false;
  errno = 0;
  out = std::strtoull(s.c_str(), nullptr, 10);
  return errno == 0;
}

bool hex_digits(const std::string& s) {
  return s.size() == 32 && s.find_first_not_of("0123456789abcdef") == std::string::npos;
}

}  // namespace

std::string checkpoint_text(const checkpoint& c) {
  std::string out = std::string(magic) + " " + std::to_string(format_version) + "\n";
  out += "program " + c.program + "\n";
  out += "program-hash " + c.program_hash + "\n";
  out += "step " + std::to_string(c.step) + "\n";
  out += "seed " + std::to_string(c.seed) + "\n";
  for (const auto& [name, value] : c.parameters) out += "parameter " + name + "=" + value + "\n";
  out += "state-bytes " + std::to_string(c.state.size()) + "\n";
  out += "state-checksum " + checksum(c.state) + "\n\n";
  return out + c.state;
}

std::string read_checkpoint(const std::string& path, checkpoint& out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return path + ": cannot read the checkpoint: " + std::strerror(errno);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) return path + ": cannot read the checkpoint: " + std::strerror(errno);
  const std::string cut = path + ": the checkpoint is truncated: ";
  const std::string damaged = path + ": the checkpoint is damaged: ";
  // The header: lines up to the first empty one.
  std::size_t at = 0;
  int line_number = 0;
  auto next_line = [&](std::string& line) {
    std::size_t end = bytes.find('\n', at);
    if (end == std::string::npos) return false;
    line = bytes.substr(at, end - at);
    at = end + 1;
    ++line_number;
    return true;
  };
  std::string line, value;
  if (bytes.empty()) return cut + "the file is empty";
  if (!next_line(line) || line.compare(0, std::strlen(magic), magic) != 0) {
    if (bytes.compare(0, std::strlen(magic), magic) == 0 || std::string(magic).compare(0, bytes.size(), bytes) == 0)
      return cut + "it ends in its header";
    return path + ": not a vv checkpoint (it does not begin with \"" + magic + "\")";
  }
  if (line != std::string(magic) + " " + std::to_string(format_version))
    return path + ": a checkpoint of another format (" + line + "); this vvinterpreter reads \"" + magic + " " +
           std::to_string(format_version) + "\"";
  checkpoint c;
  bool has[6] = {};
  unsigned long long state_bytes = 0, number = 0;
  std::string state_checksum;
  for (;;) {
    if (!next_line(line)) return cut + "it ends in its header";
    if (line.empty()) break;
    const std::string where = damaged + "header line " + std::to_string(line_number) + ": ";
    if (field(line, "program", value)) {
      c.program = value, has[0] = true;
    } else if (field(line, "program-hash", value)) {
      if (!hex_digits(value)) return where + "the program's hash is not 32 hex digits";
      c.program_hash = value, has[1] = true;
    } else if (field(line, "step", value)) {
      if (!whole_number(value, number) || number > 0xffffffffull) return where + "the step is not a count";
      c.step = static_cast<unsigned>(number), has[2] = true;
    } else if (field(line, "seed", value)) {
      if (!whole_number(value, number)) return where + "the seed is not a number";
      c.seed = number, has[3] = true;
    } else if (field(line, "parameter", value)) {
      std::size_t eq = value.find('=');
      if (eq == std::string::npos || eq == 0) return where + "a parameter is not NAME=VALUE";
      c.parameters.emplace_back(value.substr(0, eq), value.substr(eq + 1));
    } else if (field(line, "state-bytes", value)) {
      if (!whole_number(value, state_bytes)) return where + "the state's size is not a count";
      has[4] = true;
    } else if (field(line, "state-checksum", value)) {
      if (!hex_digits(value)) return where + "the checksum is not 32 hex digits";
      state_checksum = value, has[5] = true;
    } else {
      return where + "\"" + line.substr(0, 40) + "\" is no field of a checkpoint";
    }
  }
  const char* names[6] = {"program", "program-hash", "step", "seed", "state-bytes", "state-checksum"};
  for (int i = 0; i < 6; ++i)
    if (!has[i]) return damaged + "its header has no " + names[i] + " line";
  const std::size_t left = bytes.size() - at;
  if (left < state_bytes)
    return cut + "it holds " + std::to_string(left) + " of the " + std::to_string(state_bytes) +
           " bytes of its state";
  if (left > state_bytes) return damaged + std::to_string(left - state_bytes) + " bytes follow its state";
  c.state = bytes.substr(at);
  if (checksum(c.state) != state_checksum) return damaged + "its state does not match its checksum";
  out = std::move(c);
  return "";
}

std::string check_checkpoint_program(const std::string& path, const checkpoint& c, const std::string& program,
                                     const std::string& program_hash) {
  if (c.program != program)
    return path + ": a checkpoint of another program (" + c.program + "), not of " + program +
           ": it cannot be resumed by this one";
  if (c.program_hash != program_hash)
    return path + ": a checkpoint of " + c.program + " as it was before it was edited: the program has changed " +
           "since, and its state cannot be resumed by the new one (run it from its start)";
  return "";
}

}  // namespace vvi
