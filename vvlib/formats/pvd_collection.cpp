// ParaView collections (.pvd): an XML list of DataSet elements, each a
// file and the time ParaView shows it at (here the step). A growing series
// is rewritten whole and atomically at every step, so the file on disk is
// always a complete collection.
#include <vv/io/vtk_files.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <optional>
#include <system_error>

#include <pugixml.hpp>

#include "xml_text.hpp"

namespace vv {

namespace {

// `file` as the .pvd at pvd_path names it: relative to the .pvd's folder
// (both taken from the working folder when relative), or absolute when
// there is no relative way (the working folder is gone).
std::string relative_to_collection(const std::string& pvd_path, const std::string& file) {
  namespace fs = std::filesystem;
  std::error_code ec1, ec2;
  fs::path base = fs::absolute(fs::path(pvd_path), ec1).parent_path().lexically_normal();
  fs::path target = fs::absolute(fs::path(file), ec2).lexically_normal();
  if (ec1 || ec2) return file;
  fs::path rel = target.lexically_relative(base);
  return rel.empty() ? target.generic_string() : rel.generic_string();
}

bool is_separator(char c) { return c == '-' || c == '_' || c == '.'; }

}  // namespace

std::string pvd_text(const std::vector<pvd_entry>& entries) {
  std::string out =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const pvd_entry& e : entries)
    out += "    <DataSet timestep=\"" + std::to_string(e.step) + "\" group=\"\" part=\"0\" file=\"" +
           formats_detail::xml_attribute_text(e.file) + "\"/>\n";
  return out + "  </Collection>\n</VTKFile>\n";
}

std::vector<pvd_entry> read_pvd(const std::string& path) {
  std::string why;
  std::optional<std::string> bytes = io::read_file(path, &why, io::any_file_limit);
  if (!bytes) throw error(path, 0, "cannot open file: " + why);
  pugi::xml_document doc;
  pugi::xml_parse_result parsed = doc.load_buffer(bytes->data(), bytes->size());
  if (!parsed) throw error(path, 0, std::string("not a ParaView collection: ") + parsed.description());
  pugi::xml_node root = doc.child("VTKFile");
  if (!root || std::strcmp(root.attribute("type").value(), "Collection") != 0 || !root.child("Collection"))
    throw error(path, 0, "not a ParaView collection (no <VTKFile type=\"Collection\"><Collection>)");
  std::vector<pvd_entry> entries;
  for (pugi::xml_node d : root.child("Collection").children("DataSet")) {
    const char* step = d.attribute("timestep").value();
    const char* file = d.attribute("file").value();
    char* end = nullptr;
    unsigned long long value = std::strtoull(step, &end, 10);
    if (!*step || *end || *step == '-' || !*file)
      throw error(path, 0, std::string("a DataSet without a whole-number timestep and a file (timestep \"") + step +
                               "\", file \"" + file + "\")");
    entries.push_back({value, file});
  }
  return entries;
}

std::string pvd_path_for(const std::string& pattern) {
  const std::string mark = "{step}";
  std::size_t slash = pattern.rfind('/');
  std::string folder = slash == std::string::npos ? "" : pattern.substr(0, slash + 1);
  std::string name = slash == std::string::npos ? pattern : pattern.substr(slash + 1);
  // A step in a folder's name: the collection goes above the first such folder.
  if (std::size_t at = folder.find(mark); at != std::string::npos) {
    std::size_t cut = folder.rfind('/', at);
    folder = cut == std::string::npos ? "" : folder.substr(0, cut + 1);
  }
  for (std::size_t at; (at = name.find(mark)) != std::string::npos;) {
    std::size_t from = at > 0 && is_separator(name[at - 1]) ? at - 1 : at;
    name.erase(from, at + mark.size() - from);
  }
  std::size_t dot = name.rfind('.');
  std::string stem = dot == std::string::npos ? name : name.substr(0, dot);
  while (!stem.empty() && is_separator(stem.front())) stem.erase(0, 1);
  while (!stem.empty() && is_separator(stem.back())) stem.pop_back();
  return folder + (stem.empty() ? "series" : stem) + ".pvd";
}

pvd_series::pvd_series(std::string pvd_path) : path_(std::move(pvd_path)) {}

pvd_series pvd_series::resume(const std::string& pvd_path) {
  pvd_series s(pvd_path);
  s.entries_ = read_pvd(pvd_path);
  std::stable_sort(s.entries_.begin(), s.entries_.end(),
                   [](const pvd_entry& a, const pvd_entry& b) { return a.step < b.step; });
  return s;
}

void pvd_series::add(std::uint64_t step, const std::string& file) {
  std::vector<pvd_entry> next = entries_;
  pvd_entry entry{step, relative_to_collection(path_, file)};
  auto at = std::lower_bound(next.begin(), next.end(), step,
                             [](const pvd_entry& e, std::uint64_t s) { return e.step < s; });
  if (at != next.end() && at->step == step)
    *at = entry;
  else
    next.insert(at, entry);
  io::write_file_atomically(path_, pvd_text(next));
  entries_ = std::move(next);
}

}  // namespace vv
