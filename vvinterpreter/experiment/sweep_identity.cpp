#include "experiment/sweep_identity.hpp"

#include <algorithm>
#include <cstdlib>
#include <sstream>

#include <vv/io/files.hpp>

#include "compile/hashing.hpp"

namespace vvi {

namespace {

const char* const first_line = "vv sweep 1";

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

}  // namespace

std::string sweep_identity::text() const {
  std::string out = std::string(first_line) + "\nprogram " + program + "\nplots " + plots + "\n";
  for (const swept_parameter& p : parameters) {
    out += "parameter " + p.name + " ";
    for (std::size_t i = 0; i < p.values.size(); ++i) out += (i ? "," : "") + p.values[i];
    out += "\n";
  }
  out += seeds ? "seeds " + std::to_string(seeds) + "\n" : "seed " + std::to_string(seed) + "\n";
  for (const std::string& o : options) out += "option " + o + "\n";
  return out;
}

std::optional<sweep_identity> parse_identity(const std::string& text, std::string& why) {
  std::vector<std::string> lines = lines_of(text);
  if (lines.empty() || lines[0] != first_line) {
    why = "it does not start with \"" + std::string(first_line) + "\"";
    return std::nullopt;
  }
  sweep_identity id;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const std::string& l = lines[i];
    std::size_t space = l.find(' ');
    std::string key = l.substr(0, space), value = space == std::string::npos ? "" : l.substr(space + 1);
    if (key == "program") id.program = value;
    else if (key == "plots") id.plots = value;
    else if (key == "option") id.options.push_back(value);
    else if (key == "seeds") id.seeds = static_cast<unsigned>(std::strtoul(value.c_str(), nullptr, 10));
    else if (key == "seed") id.seed = std::strtoull(value.c_str(), nullptr, 10);
    else if (key == "parameter") {
      std::size_t sp = value.find(' ');
      if (sp == std::string::npos) {
        why = "line " + std::to_string(i + 1) + " names a parameter without values";
        return std::nullopt;
      }
      try {
        id.parameters.push_back(parse_sweep(value.substr(0, sp) + "=" + value.substr(sp + 1)));
      } catch (const std::exception& e) {
        why = "line " + std::to_string(i + 1) + ": " + e.what();
        return std::nullopt;
      }
    } else {
      why = "line " + std::to_string(i + 1) + " is not understood: \"" + l + "\"";
      return std::nullopt;
    }
  }
  if (id.program.empty() || id.plots.empty() || (id.seeds == 0 && text.find("\nseed ") == std::string::npos)) {
    why = "it lacks the program, plots or seeds line";
    return std::nullopt;
  }
  return id;
}

std::string program_hash(const std::vector<std::string>& source_files) {
  std::vector<std::string> hashes;
  for (const std::string& f : source_files) hashes.push_back(content_hash().add(vv::io::read_file(f).value_or("")).hex());
  std::sort(hashes.begin(), hashes.end());
  hashes.erase(std::unique(hashes.begin(), hashes.end()), hashes.end());  // one file by two spellings
  content_hash all;
  for (const std::string& h : hashes) all.add(h);
  return all.hex();
}

std::string first_difference(const std::string& there, const std::string& here) {
  std::vector<std::string> a = lines_of(there), b = lines_of(here);
  for (std::size_t i = 0; i < std::max(a.size(), b.size()); ++i) {
    std::string x = i < a.size() ? a[i] : "", y = i < b.size() ? b[i] : "";
    if (x == y) continue;
    auto shown = [](const std::string& s) { return s.empty() ? std::string("nothing") : "\"" + s + "\""; };
    return shown(x) + " there, " + shown(y) + " here";
  }
  return "";
}

}  // namespace vvi
