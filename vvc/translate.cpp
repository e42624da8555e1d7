#include "translate.hpp"

#include <vv/io/files.hpp>

#include "emitter.hpp"
#include "lexer.hpp"
#include "parser.hpp"

namespace vvc {

const char* version() { return "0.1.0"; }

namespace {
void run(translation& t, const source_file& file, std::string source_dir) {
  std::vector<token> tokens = lex(file, t.sources, t.diag);
  program p = parser(tokens, t.diag).parse_program();
  if (t.diag.any()) return;
  for (const property_block& b : p.properties) {
    std::vector<std::string>& names =
        b.keyword->text == "edge" ? t.fields.edge : b.keyword->text == "vertex" ? t.fields.vertex : t.fields.mesh;
    for (const field& f : b.fields) names.emplace_back(f.name->text);
  }
  std::string name = file.path.substr(file.path.find_last_of('/') + 1);
  emit_options options{version(), std::move(source_dir), name, t.sources.text_hash()};
  t.cpp = emit(p, options);
  program_apart apart = emit_apart(p, options);
  t.header = std::move(apart.header);
  t.program = std::move(apart.program);
  t.declarations = emit_declarations(p, options);
  t.ok = true;
}
}  // namespace

translation translate_file(const std::string& path, std::string* unreadable) {
  translation t;
  const source_file* f = t.sources.load(path, unreadable);
  if (f) run(t, *f, vv::io::absolute_folder_of(path));
  return t;
}

translation translate_text(const std::string& name, std::string text) {
  translation t;
  run(t, *t.sources.add(name, std::move(text)), "");
  return t;
}

}  // namespace vvc
