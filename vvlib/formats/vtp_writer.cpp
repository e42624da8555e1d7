// VTK XML PolyData (.vtp) in the raw appended binary form (see
// vv/io/vtk_files.hpp for why): the XML part names each array and where its
// bytes start in the appended block; each array there is a 64-bit byte
// count followed by its values, all little-endian.
#include <vv/io/vtk_files.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "xml_text.hpp"

namespace vv {

namespace {

constexpr bool little_endian_machine = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;

const char* vtk_name(vtk_number type) {
  switch (type) {
    case vtk_number::int8: return "Int8";
    case vtk_number::uint8: return "UInt8";
    case vtk_number::int16: return "Int16";
    case vtk_number::uint16: return "UInt16";
    case vtk_number::int32: return "Int32";
    case vtk_number::uint32: return "UInt32";
    case vtk_number::int64: return "Int64";
    case vtk_number::uint64: return "UInt64";
    case vtk_number::float32: return "Float32";
    case vtk_number::float64: return "Float64";
  }
  return "Float64";
}

// Appends values of `size` bytes each, in the machine's order, as
// little-endian.
void append_little_endian(std::string& out, const char* values, std::size_t count, std::size_t size) {
  if constexpr (little_endian_machine) {
    out.append(values, count * size);
  } else {
    for (std::size_t i = 0; i < count; ++i)
      for (std::size_t b = size; b-- > 0;) out += values[i * size + b];
  }
}

void append_u64(std::string& out, std::uint64_t v) {
  for (int b = 0; b < 8; ++b) out += static_cast<char>((v >> (8 * b)) & 0xff);
}

// The XML header and the appended block, built side by side.
class vtp_builder {
 public:
  // An array whose bytes (machine order) go into the appended block.
  void array(const std::string& indent, const std::string& name, vtk_number type, unsigned components,
             const char* values, std::size_t count) {
    std::size_t size = vtk_number_size(type);
    xml += indent + "<DataArray type=\"" + vtk_name(type) + "\" Name=\"" + formats_detail::xml_attribute_text(name) +
           "\" NumberOfComponents=\"" + std::to_string(components) + "\" format=\"appended\" offset=\"" +
           std::to_string(appended.size()) + "\"/>\n";
    append_u64(appended, static_cast<std::uint64_t>(count) * size);
    append_little_endian(appended, values, count, size);
  }

  // A kind of cell (Verts, Lines, Polys) as connectivity and the end
  // offset of each cell; nothing when there are none. Int32 while every
  // number fits (half the bytes; VTK widens them as it reads), else Int64.
  void cells(const char* element, const std::vector<std::vector<std::size_t>>& lists, std::size_t points) {
    if (lists.empty()) return;
    std::size_t total = 0;
    for (const auto& list : lists) total += list.size();
    xml += std::string("      <") + element + ">\n";
    if (std::max(points, total) <= std::size_t(INT32_MAX))
      cell_arrays<std::int32_t>(lists, vtk_number::int32);
    else
      cell_arrays<std::int64_t>(lists, vtk_number::int64);
    xml += std::string("      </") + element + ">\n";
  }

  template <class Index>
  void cell_arrays(const std::vector<std::vector<std::size_t>>& lists, vtk_number type) {
    std::vector<Index> connectivity, offsets;
    for (const auto& list : lists) {
      for (std::size_t i : list) connectivity.push_back(static_cast<Index>(i));
      offsets.push_back(static_cast<Index>(connectivity.size()));
    }
    array("        ", "connectivity", type, 1, reinterpret_cast<const char*>(connectivity.data()), connectivity.size());
    array("        ", "offsets", type, 1, reinterpret_cast<const char*>(offsets.data()), offsets.size());
  }

  std::string xml, appended;
};

void check_indices(const std::vector<std::vector<std::size_t>>& lists, std::size_t points, const char* what,
                   const std::string& path) {
  for (const auto& list : lists)
    for (std::size_t i : list)
      if (i >= points)
        throw error(path, 0, std::string("a ") + what + " names point " + std::to_string(i) + " of " +
                                 std::to_string(points));
}

}  // namespace

std::size_t vtk_number_size(vtk_number type) {
  switch (type) {
    case vtk_number::int8: case vtk_number::uint8: return 1;
    case vtk_number::int16: case vtk_number::uint16: return 2;
    case vtk_number::int32: case vtk_number::uint32: case vtk_number::float32: return 4;
    case vtk_number::int64: case vtk_number::uint64: case vtk_number::float64: return 8;
  }
  return 8;
}

std::string vtp_bytes(const vtp_polydata& data, const std::string& path) {
  const std::size_t n = data.points.size();
  std::vector<std::vector<std::size_t>> verts;
  for (std::size_t i : data.verts) verts.push_back({i});
  check_indices(verts, n, "vertex cell", path);
  check_indices(data.lines, n, "line", path);
  check_indices(data.polys, n, "polygon", path);
  for (const vtp_point_array& a : data.point_data)
    if (a.bytes.size() != n * a.components * vtk_number_size(a.type))
      throw error(path, 0, "point data " + a.name + " has " + std::to_string(a.bytes.size()) + " bytes, not " +
                               std::to_string(n * a.components * vtk_number_size(a.type)) + " for " +
                               std::to_string(n) + " points");

  vtp_builder b;
  b.xml = "<?xml version=\"1.0\"?>\n"
          "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
          "  <PolyData>\n"
          "    <Piece NumberOfPoints=\"" + std::to_string(n) + "\" NumberOfVerts=\"" +
          std::to_string(verts.size()) + "\" NumberOfLines=\"" + std::to_string(data.lines.size()) +
          "\" NumberOfStrips=\"0\" NumberOfPolys=\"" + std::to_string(data.polys.size()) + "\">\n";
  if (!data.point_data.empty()) {
    b.xml += "      <PointData>\n";
    for (const vtp_point_array& a : data.point_data)
      b.array("        ", a.name, a.type, a.components, a.bytes.data(), n * a.components);
    b.xml += "      </PointData>\n";
  }
  b.xml += "      <Points>\n";
  static_assert(sizeof(std::array<double, 3>) == 3 * sizeof(double), "points are packed");
  b.array("        ", "Points", vtk_number::float64, 3, reinterpret_cast<const char*>(data.points.data()), 3 * n);
  b.xml += "      </Points>\n";
  b.cells("Verts", verts, n);
  b.cells("Lines", data.lines, n);
  b.cells("Polys", data.polys, n);
  b.xml += "    </Piece>\n"
           "  </PolyData>\n"
           "  <AppendedData encoding=\"raw\">\n"
           "   _";
  return b.xml + b.appended + "\n  </AppendedData>\n</VTKFile>\n";
}

void write_vtp_file(const std::string& path, const vtp_polydata& data) {
  io::write_file_atomically(path, vtp_bytes(data, path));
}

}  // namespace vv
