#include "experiment/sweep_plan.hpp"

#include <cctype>
#include <cstdio>
#include <set>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace vvi {

namespace {

[[noreturn]] void refuse(const std::string& typed, const std::string& why) {
  throw std::invalid_argument("--sweep " + typed + ": " + why);
}

bool is_name(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  return true;
}

// The whole text as a finite number, or false.
bool number(const std::string& text, double& out) {
  if (text.empty()) return false;
  char* end = nullptr;
  out = std::strtod(text.c_str(), &end);
  return *end == '\0' && std::isfinite(out);
}

// A range's value as text, to 15 significant digits: a step typed in
// decimals gives the decimals (0:0.3:4 gives 0.1, not the
// 0.09999999999999999 that binary arithmetic makes of 0.3 / 3). The run is
// given this text, so the table and the model agree.
std::string value_text(double v) {
  if (v == 0) return "0";  // not "-0"
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.15g", v);
  return buf;
}

std::vector<std::string> split(const std::string& s, char by) {
  std::vector<std::string> parts;
  for (std::size_t from = 0;;) {
    std::size_t at = s.find(by, from);
    parts.push_back(s.substr(from, at == std::string::npos ? std::string::npos : at - from));
    if (at == std::string::npos) return parts;
    from = at + 1;
  }
}

std::vector<std::string> range_values(const std::string& typed, const std::vector<std::string>& part) {
  double lo = 0, hi = 0, count_d = 0;
  const char* need = "a range needs LO:HI:COUNT, three numbers, e.g. 0:1:5";
  if (!number(part[0], lo) || !number(part[1], hi) || !number(part[2], count_d)) refuse(typed, need);
  if (count_d != std::floor(count_d) || count_d < 0 || count_d > 1000000)
    refuse(typed, "COUNT must be a whole number of values from 1 to 1000000, not " + part[2]);
  unsigned count = static_cast<unsigned>(count_d);
  if (count == 0) refuse(typed, "COUNT is 0: the range has no values (COUNT must be 1 or more)");
  if (hi < lo) refuse(typed, "the range is empty: HI (" + part[1] + ") is below LO (" + part[0] + ")");
  if (count > 1 && hi == lo) refuse(typed, "LO and HI are equal, so its " + part[2] + " values would all be " + part[0]);
  std::vector<std::string> values;
  for (unsigned i = 0; i < count; ++i) {
    // The ends exactly; the others from LO in whole steps (no drift).
    double v = i + 1 == count && count > 1 ? hi : lo + (hi - lo) * i / (count > 1 ? count - 1 : 1);
    values.push_back(value_text(v));
  }
  return values;
}

}  // namespace

swept_parameter parse_sweep(const std::string& typed) {
  swept_parameter p;
  p.typed = typed;
  std::size_t eq = typed.find('=');
  const char* need = "it needs NAME=V1,V2,... or NAME=LO:HI:COUNT, e.g. --sweep rate=0.1,0.2 or --sweep rate=0:1:5";
  if (eq == std::string::npos) refuse(typed, need);
  p.name = typed.substr(0, eq);
  if (!is_name(p.name)) refuse(typed, "\"" + p.name + "\" is no parameter name; " + need);
  std::string rest = typed.substr(eq + 1);
  if (rest.empty()) refuse(typed, "no values: the sweep would have no runs");
  std::vector<std::string> colon = split(rest, ':');
  if (colon.size() == 3 && rest.find(',') == std::string::npos) {
    p.values = range_values(typed, colon);
  } else if (colon.size() == 1) {
    p.values = split(rest, ',');
    for (const std::string& v : p.values)
      if (v.empty()) refuse(typed, "an empty value (two commas, or one at an end)");
  } else {
    refuse(typed, need);
  }
  std::set<std::string> seen;
  for (const std::string& v : p.values)
    if (!seen.insert(v).second) refuse(typed, "the value " + v + " is listed twice");
  return p;
}

sweep_plan::sweep_plan(std::vector<swept_parameter> parameters, unsigned seeds, std::uint64_t fixed_seed)
    : parameters_(std::move(parameters)) {
  for (std::size_t i = 0; i < parameters_.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (parameters_[i].name == parameters_[j].name)
        throw std::invalid_argument("--sweep " + parameters_[i].typed + ": parameter " + parameters_[i].name +
                                    " is already swept (--sweep " + parameters_[j].typed + ")");
  if (seeds == 0) seeds_.push_back(fixed_seed);
  for (unsigned s = 1; s <= seeds; ++s) seeds_.push_back(s);
}

std::size_t sweep_plan::size() const {
  std::size_t n = seeds_.size();
  for (const swept_parameter& p : parameters_) n *= p.values.size();
  return n;
}

planned_run sweep_plan::run(unsigned number) const {
  planned_run r;
  r.number = number;
  std::size_t index = number - 1;
  r.seed = seeds_[index % seeds_.size()];
  index /= seeds_.size();
  r.values.resize(parameters_.size());
  for (std::size_t k = parameters_.size(); k-- > 0;) {  // the last parameter varies fastest
    r.values[k] = parameters_[k].values[index % parameters_[k].values.size()];
    index /= parameters_[k].values.size();
  }
  return r;
}

std::vector<unsigned> sweep_plan::shard(unsigned i, unsigned n) const {
  std::vector<unsigned> runs;
  for (std::size_t r = i; r <= size(); r += n) runs.push_back(static_cast<unsigned>(r));
  return runs;
}

std::string sweep_plan::folder(unsigned number) const {
  std::string digits = std::to_string(number);
  std::size_t width = std::max<std::size_t>(4, std::to_string(size()).size());
  return "run-" + std::string(width > digits.size() ? width - digits.size() : 0, '0') + digits;
}

std::string sweep_plan::describe(const planned_run& r) const {
  std::string text;
  for (std::size_t k = 0; k < parameters_.size(); ++k) text += parameters_[k].name + "=" + r.values[k] + " ";
  return text + "seed=" + std::to_string(r.seed);
}

}  // namespace vvi
