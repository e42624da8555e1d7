#include "compile/property_messages.hpp"

#include <optional>

#include "app/joined_names.hpp"
#include "compile/text_ends.hpp"

namespace vvi {

namespace {

// The text between `open` (found from `from`) and the next `close`; "" when
// either is missing.
std::string between(const std::string& s, const std::string& open, const std::string& close, std::size_t from = 0) {
  std::size_t b = s.find(open, from);
  if (b == std::string::npos) return "";
  b += open.size();
  std::size_t e = s.find(close, b);
  return e == std::string::npos ? "" : s.substr(b, e - b);
}

// The type a "'T' {aka 'U'}" description stands for, without qualifiers:
// U when given (g++ spells it out), else T; "using A = B" is B.
std::string described_type(const std::string& description) {
  std::string type = between(description, "{aka '", "'}");
  if (type.empty()) {
    std::size_t b = description.find('\''), e = description.rfind('\'');
    if (b == std::string::npos || e <= b) return "";
    type = description.substr(b + 1, e - b - 1);
  }
  if (starts_with(type, "using ") && type.find(" = ") != std::string::npos) type = type.substr(type.find(" = ") + 3);
  for (bool stripped = true; stripped;) {
    stripped = false;
    for (const char* word : {"const ", "volatile ", "struct ", "class "})
      if (starts_with(type, word)) {
        type = type.substr(std::string(word).size());
        stripped = true;
      }
  }
  return type;
}

struct owner {
  const char* what = nullptr;   // "the vertex"
  const char* block = nullptr;  // the block that declares its properties
  bool has_functions = false;   // a mesh has member functions besides its properties
  const std::vector<std::string>* fields = nullptr;
};

// Which of the generated property types (or the mesh class) `type` is.
owner owner_of(const std::string& type, const property_fields& f) {
  if (type == "vv_vertex_props" || ends_with(type, "::vertex_props")) return {"the vertex", "vertex", false, &f.vertex};
  if (type == "vv_edge_props" || ends_with(type, "::edge_props"))
    return {"the half-edge record", "edge", false, &f.edge};
  if (type == "vv_mesh_props" || ends_with(type, "::mesh_props")) return {"the mesh", "mesh", false, &f.mesh};
  if (type == "vv::mesh<vv_traits>") return {"the mesh", "mesh", true, &f.mesh};
  return {};
}

}  // namespace

namespace {

// What a "no member" message says: the type's description, the member, and
// the compiler's suggestion ("" if none).
struct missing_member {
  std::string severity, type, name, suggestion;
};

// g++: "'T' {aka 'U'} has no member named 'x'; did you mean 'y'?"
std::optional<missing_member> gxx_words(const std::string& message, std::size_t severity_end) {
  static const std::string marker = " has no member named '";
  std::size_t at = message.find(marker);
  if (at == std::string::npos || at < severity_end) return std::nullopt;
  std::size_t name_begin = at + marker.size();
  std::size_t name_end = message.find('\'', name_begin);
  if (name_end == std::string::npos) return std::nullopt;
  return missing_member{message.substr(0, severity_end),
                        described_type(message.substr(severity_end + 2, at - severity_end - 2)),
                        message.substr(name_begin, name_end - name_begin),
                        between(message, "did you mean '", "'", name_end)};
}

// clang: "no member named 'x' in 'T'; did you mean 'y'?"
std::optional<missing_member> clang_words(const std::string& message, std::size_t severity_end) {
  static const std::string marker = ": no member named '";
  if (message.compare(severity_end, marker.size(), marker) != 0) return std::nullopt;
  std::size_t name_begin = severity_end + marker.size();
  std::size_t name_end = message.find('\'', name_begin);
  static const std::string in = "' in '";
  if (name_end == std::string::npos || message.compare(name_end, in.size(), in) != 0) return std::nullopt;
  std::size_t type_begin = name_end + in.size() - 1;  // its opening quote
  std::size_t type_end = message.find('\'', type_begin + 1);
  if (type_end == std::string::npos) return std::nullopt;
  return missing_member{message.substr(0, severity_end),
                        described_type(message.substr(type_begin, type_end - type_begin + 1)),
                        message.substr(name_begin, name_end - name_begin),
                        between(message, "did you mean '", "'", type_end)};
}

}  // namespace

std::string property_message(const std::string& message, const property_fields& fields) {
  std::size_t severity_end = message.find(": ");
  if (severity_end == std::string::npos) return "";
  std::optional<missing_member> m = gxx_words(message, severity_end);
  if (!m) m = clang_words(message, severity_end);
  if (!m) return "";
  owner o = owner_of(m->type, fields);
  if (!o.what) return "";
  std::string out = m->severity + ": " + o.what + " has no property " +
                    (o.has_functions ? "or member function '" : "'") + m->name + "'";
  if (!m->suggestion.empty()) out += " (did you mean '" + m->suggestion + "'?)";
  if (o.fields->empty()) return out + "; it has none (a " + o.block + " block declares them)";
  return out + "; its properties are: " + joined_names(*o.fields);
}

}  // namespace vvi
