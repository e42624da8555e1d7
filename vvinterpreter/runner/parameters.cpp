#include "runner/parameters.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "runner/session.hpp"

namespace vvi {

namespace {

bool is(const vv_param_entry& p, const char* type) { return std::strcmp(p.type, type) == 0; }

// The shortest decimal that reads back as the same value of the
// parameter's type (a float 0.1 is "0.1", not its double expansion);
// whole numbers are written without an exponent.
std::string shortest(double v, bool as_float = false) {
  char buf[40];
  if (std::fabs(v) < 1e15 && v == std::floor(v)) {
    std::snprintf(buf, sizeof buf, "%.0f", v);
    return buf;
  }
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    bool same = as_float ? std::strtof(buf, nullptr) == static_cast<float>(v) : std::strtod(buf, nullptr) == v;
    if (same) break;
  }
  return buf;
}

std::string number_text(double v, const vv_param_entry& p) { return shortest(v, is(p, "float")); }

// The whole text as a number of the parameter's type, or why not.
std::string parse_number(const vv_param_entry& p, const std::string& text, double& out) {
  std::string type_phrase = std::string(is(p, "int") || is(p, "unsigned") ? "an " : "a ") + p.type;
  std::string not_one = "parameter " + std::string(p.name) + " is " + type_phrase + ", and \"" + text + "\" is not one";
  const char* s = text.c_str();
  char* end = nullptr;
  errno = 0;
  if (is(p, "bool")) {
    if (text == "true" || text == "1") out = 1;
    else if (text == "false" || text == "0") out = 0;
    else return not_one + " (true, false, 1 or 0)";
    return "";
  }
  if (is(p, "int") || is(p, "unsigned")) {
    if (is(p, "unsigned") && text.find('-') != std::string::npos) return not_one;
    long long v = std::strtoll(s, &end, 10);
    if (end == s || *end || errno == ERANGE) return not_one;
    double lo = is(p, "int") ? double(std::numeric_limits<int>::min()) : 0.0;
    double hi = is(p, "int") ? double(std::numeric_limits<int>::max()) : double(std::numeric_limits<unsigned>::max());
    if (double(v) < lo || double(v) > hi) return not_one + " (out of the type's range)";
    out = double(v);
    return "";
  }
  double v = std::strtod(s, &end);
  if (end == s || *end || text.empty()) return not_one;
  if (!std::isfinite(v)) return not_one + " (a parameter is a finite number)";
  if (is(p, "float") && std::fabs(v) > double(std::numeric_limits<float>::max())) return not_one + " (out of the type's range)";
  out = v;
  return "";
}

}  // namespace

std::vector<const vv_param_entry*> parameters_of(const session& s) {
  const vv_plugin& m = s.model();
  std::vector<const vv_param_entry*> out;
  for (std::size_t i = 0; i < m.param_count; ++i) out.push_back(&m.params[i]);
  return out;
}

const vv_param_entry* find_parameter(const session& s, const std::string& name) {
  for (const vv_param_entry* p : parameters_of(s))
    if (name == p->name) return p;
  return nullptr;
}

double parameter_number(const vv_param_entry& p) {
  if (is(p, "bool")) return *static_cast<const bool*>(p.value) ? 1 : 0;
  if (is(p, "int")) return *static_cast<const int*>(p.value);
  if (is(p, "unsigned")) return *static_cast<const unsigned*>(p.value);
  if (is(p, "float")) return *static_cast<const float*>(p.value);
  return *static_cast<const double*>(p.value);
}

std::string parameter_text(const vv_param_entry& p) {
  if (is(p, "bool")) return parameter_number(p) != 0 ? "true" : "false";
  if (is(p, "int") || is(p, "unsigned")) return std::to_string(static_cast<long long>(parameter_number(p)));
  return number_text(parameter_number(p), p);
}

std::string parameter_line(const vv_param_entry& p) {
  std::string line = std::string(p.name) + " " + p.type + " " + parameter_text(p);
  if (p.has_range) line += " [" + shortest(p.lo) + ", " + shortest(p.hi) + "]";
  return line;
}

std::string set_parameter(const vv_param_entry& p, const std::string& text) {
  double v = 0;
  std::string why = parse_number(p, text, v);
  if (!why.empty()) return why;
  if (p.has_range && (v < p.lo || v > p.hi))
    return text + " is outside the range [" + shortest(p.lo) + ", " + shortest(p.hi) + "] of parameter " +
           p.name;
  if (is(p, "bool")) *static_cast<bool*>(p.value) = v != 0;
  else if (is(p, "int")) *static_cast<int*>(p.value) = static_cast<int>(v);
  else if (is(p, "unsigned")) *static_cast<unsigned*>(p.value) = static_cast<unsigned>(v);
  else if (is(p, "float")) *static_cast<float*>(p.value) = static_cast<float>(v);
  else *static_cast<double*>(p.value) = v;
  return "";
}

std::string apply_parameter_settings(const session& s, std::vector<parameter_setting>& settings,
                                     const std::string& model_file) {
  for (std::size_t i = 0; i < settings.size();) {
    parameter_setting& g = settings[i];
    const vv_param_entry* p = find_parameter(s, g.name);
    bool from_before = !g.type.empty();
    if (from_before && (!p || g.type != p->type)) {
      settings.erase(settings.begin() + long(i));  // the parameter is gone or changed: the file's value rules
      continue;
    }
    std::string assignment = "--set " + g.name + "=" + g.text;
    if (!p) {
      std::string known;
      for (const vv_param_entry* q : parameters_of(s)) known += (known.empty() ? "" : ", ") + std::string(q->name);
      return model_file + ": " + assignment + ": the model has no parameter " + g.name +
             (known.empty() ? " (it has none)" : " (it has " + known + ")");
    }
    std::string why = set_parameter(*p, g.text);
    if (!why.empty()) {
      if (from_before) {
        settings.erase(settings.begin() + long(i));
        continue;
      }
      return model_file + ":" + std::to_string(p->line) + ": " + assignment + ": " + why;
    }
    g.type = p->type;
    ++i;
  }
  return "";
}

}  // namespace vvi
