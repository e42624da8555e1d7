// The .vvm file format (LANGUAGE.md section 7): an XML <mesh> whose <v>
// elements are the vertices in order (attributes: properties and the
// neighbour list `nb`) and whose <e> elements set half-edge records.
//
// Reading validates the whole file before touching the mesh: on any
// problem it throws vv::error "file:line: problem" and the mesh is as it
// was. Writing gives the sub-graph induced by the mesh (neighbours outside
// it are left out), is deterministic, and replaces the file atomically.
#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include <pugixml.hpp>

#include "../edges.hpp"
#include "../edits.hpp"
#include "../fields.hpp"
#include "../mesh.hpp"
#include "../faces.hpp"
#include "files.hpp"

namespace vv {

namespace detail {

// Sets the field called `name` of props from text. Returns false when the
// struct has no such field; throws through fail() when the text is bad.
template <class P, class Fail>
bool set_field(P& props, const char* name, const char* text, Fail&& fail) {
  bool found = false;
  for_each_field(props, [&](const char* field, auto& value) {
    if (found || std::strcmp(field, name) != 0) return;
    found = true;
    if (!text_to_value(std::string(text), value))
      fail(std::string("cannot read \"") + text + "\" as the value of " + name);
  });
  return found;
}

// What a read let through that a learner would want to hear of: attributes
// no field takes, fields the file never gives. Each has a key, so that it is
// said once however often the file is read.
struct vvm_notes {
  std::vector<std::pair<std::string, std::string>> said;  // key, message
  std::set<std::string> keys;
  // The file's one name in keys (links and ".." resolved), so that a file
  // read under two spellings still warns once.
  std::string file;
  void add(std::string key, std::string message) {
    if (keys.insert(key).second) said.emplace_back(std::move(key), std::move(message));
  }
};

inline std::string kind_of(const char* element) {
  return std::strcmp(element, "v") == 0 ? "vertex" : std::strcmp(element, "e") == 0 ? "edge records" : "mesh";
}

// Sets the fields of props from the attributes of node (but those in skip);
// counts, per field, the nodes that gave it.
template <class P>
void set_fields_from(P& props, const pugi::xml_node& node, const io::text_file& file,
                     const char* skip[], const std::string& who, const char* element,
                     std::map<std::string, std::size_t>& given, vvm_notes& notes) {
  for (pugi::xml_attribute a : node.attributes()) {
    bool skipped = false;
    for (const char** s = skip; *s; ++s) skipped = skipped || std::strcmp(*s, a.name()) == 0;
    if (skipped) continue;
    bool known = set_field(props, a.name(), a.value(), [&](const std::string& problem) {
      file.fail(node.offset_debug(), who + ": " + problem);
    });
    if (known) {
      ++given[a.name()];
      continue;
    }
    notes.add(notes.file + "|unknown|" + element + "|" + a.name(),
              file.name() + ":" + std::to_string(file.line_at(node.offset_debug())) +
                  ": warning: the attribute " + a.name() + " of <" + element +
                  "> matches no field of the program's " + kind_of(element) + " and is ignored");
  }
}

// A field of P that fewer than `of` elements gave keeps its default there
// (said unless the program computes the field itself).
template <class P>
void note_missing_fields(const io::text_file& file, const char* what, const char* plural,
                         const std::map<std::string, std::size_t>& given, std::size_t of,
                         vvm_notes& notes) {
  if (of == 0) return;
  P probe{};
  for_each_field(probe, [&](const char* field, const auto&) {
    auto it = given.find(field);
    std::size_t n = it == given.end() ? 0 : it->second;
    if (n == of || is_computed_field<P>(field)) return;
    std::string head = file.name() + ": warning: the " + what + " field " + field;
    std::string tail = n == 0 ? (of == 1 ? " is not in the file and keeps its default value"
                                         : " is in no " + std::string(what) + " of the file and keeps its default value")
                              : " is missing from " + std::to_string(of - n) + " of the " + std::to_string(of) +
                                    " " + plural + ", which keep its default value";
    notes.add(notes.file + "|missing|" + what + "|" + field, head + tail);
  });
}

// What pugixml lets through but XML (or the format) forbids: text outside
// the document element, a second top-level element, an attribute given
// twice, text inside <mesh>, anything inside a <v> or <e>.
inline void check_structure(const pugi::xml_document& doc, const io::text_file& file) {
  // pugixml drops text before and after the document element; look at the
  // raw text (a UTF-8 byte order mark may lead).
  const std::string& text = file.text();
  std::size_t lead = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  std::size_t first = text.find_first_not_of(" \t\r\n", lead);
  if (first != std::string::npos && text[first] != '<')
    file.fail(std::ptrdiff_t(first), "malformed XML: text before the <mesh> element");
  std::size_t last_tag_end = text.rfind('>');
  std::size_t trailing = text.find_first_not_of(" \t\r\n", last_tag_end + 1);
  if (last_tag_end != std::string::npos && trailing != std::string::npos)
    file.fail(std::ptrdiff_t(trailing), "malformed XML: text after the <mesh> element");
  bool seen_root = false;
  for (pugi::xml_node n : doc.children()) {
    if (n.type() != pugi::node_element) continue;
    if (seen_root)
      file.fail(n.offset_debug(),
                std::string("malformed XML: a second top-level element <") + n.name() + ">");
    seen_root = true;
  }
  auto check_attributes = [&](const pugi::xml_node& e) {
    for (pugi::xml_attribute a = e.first_attribute(); a; a = a.next_attribute())
      for (pugi::xml_attribute b = a.next_attribute(); b; b = b.next_attribute())
        if (std::strcmp(a.name(), b.name()) == 0)
          file.fail(e.offset_debug(),
                    std::string("malformed XML: attribute ") + a.name() + " is given twice");
  };
  pugi::xml_node root = doc.document_element();
  check_attributes(root);
  for (pugi::xml_node n : root.children()) {
    if (n.type() == pugi::node_pcdata || n.type() == pugi::node_cdata)
      file.fail(n.offset_debug(), "text inside <mesh> (expected only <v> and <e> elements)");
    if (n.type() != pugi::node_element) continue;
    check_attributes(n);
    for (pugi::xml_node inner : n.children())
      if (inner.type() == pugi::node_element || inner.type() == pugi::node_pcdata ||
          inner.type() == pugi::node_cdata)
        file.fail(inner.offset_debug(), std::string("unexpected content inside <") + n.name() + ">");
  }
}

// The text of each field, in order, as the file holds it.
template <class P>
std::vector<std::string> field_texts(const P& props) {
  std::vector<std::string> out;
  for_each_field(props, [&](const char*, const auto& value) { out.push_back(value_to_text(value)); });
  return out;
}

// Parses an unsigned vertex index of the file; fails on anything else.
inline std::uint32_t parse_index(const std::string& token, std::size_t count,
                                 const std::function<void(const std::string&)>& fail) {
  if (token.empty() || token.find_first_not_of("0123456789") != std::string::npos)
    fail("\"" + token + "\" is not a vertex index");
  if (token.size() > 10 || std::stoull(token) >= count)
    fail("vertex index " + token + " is out of range (the file has " + std::to_string(count) +
         " vertices)");
  return static_cast<std::uint32_t>(std::stoul(token));
}

// Says the notes of a read, each once in the context's life, naming the
// line that read the file.
template <class Tr>
void say_notes(context<Tr>& ctx, const vvm_notes& notes, const where& w) {
  std::string from = w.file ? std::string(" (read at ") + w.file + ":" + std::to_string(w.line) + ")" : "";
  for (const auto& [key, message] : notes.said) ctx.warn_once(key, message + from);
}

}  // namespace detail

namespace detail {

// Validate: the text is well-formed XML whose one top-level element is
// <mesh>. doc keeps what the returned root points into.
inline pugi::xml_node vvm_root(pugi::xml_document& doc, const io::text_file& file) {
  if (file.text().find_first_not_of(" \t\r\n") == std::string::npos)
    file.fail(0, "empty file (expected a <mesh> element)");
  pugi::xml_parse_result parsed = doc.load_buffer(file.text().data(), file.text().size(),
                                                  pugi::parse_default, pugi::encoding_utf8);
  if (!parsed) file.fail(parsed.offset, std::string("malformed XML: ") + parsed.description());
  check_structure(doc, file);
  pugi::xml_node root = doc.document_element();
  if (!root) file.fail(0, "no root element (expected <mesh>)");
  if (std::strcmp(root.name(), "mesh") != 0)
    file.fail(root.offset_debug(), std::string("the root element is <") + root.name() +
                                       ">, expected <mesh>");
  return root;
}

// The <v> and <e> children of <mesh>, each in file order; anything else fails.
struct vvm_elements {
  std::vector<pugi::xml_node> vertices, records;
};
inline vvm_elements vvm_children(const pugi::xml_node& root, const io::text_file& file) {
  vvm_elements out;
  for (pugi::xml_node n : root.children()) {
    if (n.type() != pugi::node_element) continue;
    if (std::strcmp(n.name(), "v") == 0) out.vertices.push_back(n);
    else if (std::strcmp(n.name(), "e") == 0) out.records.push_back(n);
    else
      file.fail(n.offset_debug(), std::string("unexpected element <") + n.name() +
                                      "> (expected <v> or <e>)");
  }
  return out;
}

// Everything a .vvm file says, checked, before any vertex exists.
template <class Tr>
struct vvm_contents {
  struct record {
    std::uint32_t first, second;
    bool symmetric;
    typename Tr::edge_props value;
  };
  typename Tr::mesh_props mesh_props{};
  std::vector<typename Tr::vertex_props> props;       // per vertex, in file order
  std::vector<std::vector<std::uint32_t>> nbs;        // neighbour indices, per vertex
  std::vector<record> records;
};

// Vertices: the properties and neighbour list of each <v>.
template <class Tr>
void read_vvm_vertices(vvm_contents<Tr>& c, const std::vector<pugi::xml_node>& vs,
                       const io::text_file& file, std::map<std::string, std::size_t>& given,
                       vvm_notes& notes) {
  const std::size_t count = vs.size();
  c.props.assign(count, typename Tr::vertex_props());
  c.nbs.assign(count, {});
  static const char* v_skip[] = {"nb", nullptr};
  for (std::size_t i = 0; i < count; ++i) {
    std::string who = "vertex " + std::to_string(i);
    auto fail = [&](const std::string& problem) { file.fail(vs[i].offset_debug(), who + ": " + problem); };
    set_fields_from(c.props[i], vs[i], file, v_skip, who, "v", given, notes);
    pugi::xml_attribute nb = vs[i].attribute("nb");
    if (!nb) fail("no nb attribute (write nb=\"\" for a vertex without neighbours)");
    std::istringstream tokens(nb.value());
    std::string token;
    while (tokens >> token) {
      std::uint32_t j = parse_index(token, count, fail);
      if (j == i) fail("lists itself as a neighbour");
      for (std::uint32_t k : c.nbs[i])
        if (k == j) fail("lists vertex " + token + " twice as a neighbour");
      c.nbs[i].push_back(j);
    }
  }
}

// Records: each <e> names an existing half-edge (both ways when symmetric).
template <class Tr>
void read_vvm_records(vvm_contents<Tr>& c, const std::vector<pugi::xml_node>& es,
                      const io::text_file& file, std::map<std::string, std::size_t>& given,
                      vvm_notes& notes) {
  using record = typename vvm_contents<Tr>::record;
  const std::size_t count = c.nbs.size();
  static const char* e_skip[] = {"symmetric", "first", "second", nullptr};
  auto adjacent = [&](std::uint32_t a, std::uint32_t b) {
    for (std::uint32_t k : c.nbs[a])
      if (k == b) return true;
    return false;
  };
  for (pugi::xml_node e : es) {
    auto fail = [&](const std::string& problem) { file.fail(e.offset_debug(), "edge: " + problem); };
    auto index_attr = [&](const char* name) {
      pugi::xml_attribute a = e.attribute(name);
      if (!a) fail(std::string("no ") + name + " attribute");
      return parse_index(a.value(), count, fail);
    };
    record r{index_attr("first"), index_attr("second"), false, typename Tr::edge_props{}};
    if (pugi::xml_attribute s = e.attribute("symmetric")) {
      if (!text_to_value(std::string(s.value()), r.symmetric))
        fail(std::string("symmetric must be 0 or 1, not \"") + s.value() + "\"");
    }
    if (!adjacent(r.first, r.second))
      fail("vertex " + std::to_string(r.second) + " is not a neighbour of vertex " +
           std::to_string(r.first));
    if (r.symmetric && !adjacent(r.second, r.first))
      fail("symmetric, but vertex " + std::to_string(r.first) + " is not a neighbour of vertex " +
           std::to_string(r.second));
    set_fields_from(r.value, e, file, e_skip, "edge", "e", given, notes);
    c.records.push_back(std::move(r));
  }
}

// Build: create the vertices in file order and swap the new contents into m.
// The edits are noted at w, the line that read the file.
template <class Tr>
void build_vvm_mesh(mesh<Tr>& m, const vvm_contents<Tr>& c, const where& w) {
  context<Tr>& ctx = *m.ctx();
  const std::size_t count = c.props.size();
  mesh<Tr> fresh(ctx);
  static_cast<typename Tr::mesh_props&>(fresh) = c.mesh_props;
  std::vector<vertex<Tr>> created;
  created.reserve(count);
  for (std::size_t i = 0; i < count; ++i) created.push_back(ctx.new_vertex(c.props[i]));
  std::vector<vertex<Tr>> list;
  for (std::size_t i = 0; i < count; ++i) {
    list.clear();
    for (std::uint32_t j : c.nbs[i]) list.push_back(created[j]);
    make_nb_from(created[i], list, w);
    fresh.add(created[i], w);
  }
  for (const auto& r : c.records) {
    edge(created[r.first], created[r.second], w) = r.value;
    if (r.symmetric) edge(created[r.second], created[r.first], w) = r.value;
  }
  m = std::move(fresh);
}

}  // namespace detail

//! Replaces the contents and properties of m with the .vvm text (name is
//! used in error messages). New vertices are created in file order.
//! What the file let through without a word is added to notes when given.
//! The whole file is validated, read and checked before the mesh changes.
//! w is where the edits are noted (vvinterpreter --check names that line):
//! the caller's line by default.
template <class Tr>
void parse_vvm(mesh<Tr>& m, const io::text_file& file, detail::vvm_notes* notes = nullptr,
               where w = where::here()) {
  detail::vvm_notes ignored;
  detail::vvm_notes& said = notes ? *notes : ignored;
  if (!m.ctx())
    throw error(file.name(), 0,
                "the mesh has no context to create vertices in (construct it with mesh(context))");
  std::error_code ec;
  std::filesystem::path one_name = std::filesystem::weakly_canonical(file.name(), ec);
  said.file = ec ? file.name() : one_name.string();
  pugi::xml_document doc;
  pugi::xml_node root = detail::vvm_root(doc, file);

  detail::vvm_contents<Tr> contents;
  static const char* no_skip[] = {nullptr};
  std::map<std::string, std::size_t> mesh_given, vertex_given, edge_given;
  detail::set_fields_from(contents.mesh_props, root, file, no_skip, "mesh", "mesh", mesh_given, said);
  detail::vvm_elements elements = detail::vvm_children(root, file);
  detail::read_vvm_vertices(contents, elements.vertices, file, vertex_given, said);
  detail::read_vvm_records(contents, elements.records, file, edge_given, said);

  detail::note_missing_fields<typename Tr::mesh_props>(file, "mesh", "meshes", mesh_given, 1, said);
  detail::note_missing_fields<typename Tr::vertex_props>(file, "vertex", "vertices", vertex_given,
                                                         contents.props.size(), said);
  detail::build_vvm_mesh(m, contents, w);
}

//! Reads a .vvm file into m (see parse_vvm). A path that is no regular
//! file, or a file over io::mesh_file_limit, is refused unread.
template <class Tr>
void read_vvm(mesh<Tr>& m, const std::string& path, detail::vvm_notes* notes = nullptr,
              where w = where::here()) {
  parse_vvm(m, io::read_text_file(path, io::mesh_file_limit), notes, w);
}

//! The .vvm text of a mesh.
template <class Tr>
std::string vvm_text(const mesh<Tr>& m) {
  using EP = typename Tr::edge_props;
  using MP = typename Tr::mesh_props;
  pugi::xml_document doc;
  pugi::xml_node root = doc.append_child("mesh");
  auto put_fields = [](pugi::xml_node node, const auto& props) {
    for_each_field(props, [&](const char* name, const auto& value) {
      node.append_attribute(name) = value_to_text(value).c_str();
    });
  };
  put_fields(root, static_cast<const MP&>(m));

  context<Tr>* ctx = m.ctx();
  std::vector<std::uint32_t> pos = member_positions(m);
  constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> members;
  for (std::uint32_t id : m.slots())
    if (id) members.push_back(id);

  for (std::uint32_t id : members) {
    pugi::xml_node v = root.append_child("v");
    put_fields(v, ctx->props(id));
    std::string nb;
    for (const auto& e : ctx->nb(id)) {
      std::uint32_t u = detail::entry_id(e);
      if (pos[u] == none) continue;
      if (!nb.empty()) nb += ' ';
      nb += std::to_string(pos[u]);
    }
    v.append_attribute("nb") = nb.c_str();
  }

  using entry_traits = typename context<Tr>::entry_traits;
  // Records are compared by what the file would hold for them, so a record
  // type needs no == of its own, and fields not written do not count.
  const std::vector<std::string> blank = detail::field_texts(EP{});
  for (std::uint32_t a : members) {
    for (auto& e : ctx->nb(a)) {
      std::uint32_t b = detail::entry_id(e);
      if (pos[b] == none) continue;
      const EP& rec = entry_traits::rec(e, ctx->empty_record());
      std::vector<std::string> texts = detail::field_texts(rec);
      if (texts == blank) continue;
      // A pair with equal records both ways is written once, as symmetric.
      std::int32_t back = detail::find(ctx->nb(b), a);
      bool same_back = back >= 0 &&
          detail::field_texts(entry_traits::rec(ctx->nb(b)[static_cast<std::uint32_t>(back)],
                                                ctx->empty_record())) == texts;
      if (same_back && pos[b] < pos[a]) continue;
      pugi::xml_node x = root.append_child("e");
      x.append_attribute("symmetric") = same_back ? "1" : "0";
      x.append_attribute("first") = pos[a];
      x.append_attribute("second") = pos[b];
      put_fields(x, rec);
    }
  }
  std::ostringstream os;
  doc.save(os, "  ", pugi::format_indent | pugi::format_no_declaration, pugi::encoding_utf8);
  return os.str();
}

//! Writes m to a .vvm file, atomically.
template <class Tr>
void write_vvm(const mesh<Tr>& m, const std::string& path) {
  io::write_text_file(path, vvm_text(m));
}

template <class Tr>
void mesh<Tr>::readXMLFile(const std::string& path, where w) {
  detail::vvm_notes notes;
  at_caller(w, "readXMLFile",
            [&] { read_vvm(*this, io::resolve(ctx_ ? ctx_->base_dir : std::string(), path), &notes, w); });
  detail::say_notes(*ctx_, notes, w);
}

template <class Tr>
void mesh<Tr>::writeXMLFile(const std::string& path, where w) const {
  at_caller(w, "writeXMLFile", [&] { write_vvm(*this, io::resolve(ctx_ ? ctx_->base_dir : std::string(), path)); });
}

}  // namespace vv
