// VTK files for ParaView: a mesh as VTK XML PolyData (.vtp) and a series of
// them as a ParaView collection (.pvd). The format code is compiled once,
// into vv_formats (vvlib/formats/vtk_files.cpp); the mesh side, which walks
// a model's properties, is vv/io/vtp.hpp.
//
// A .vtp file is written in VTK's "raw appended" binary form: an XML header
// naming every array, then the arrays' bytes, little-endian, each after a
// 64-bit byte count. Binary keeps every value exactly as the model holds it
// (nan, infinities and -0 included, which VTK's ASCII reader does not take),
// and the bytes depend only on the values: the same mesh gives the same file
// on any machine.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "polygon_files.hpp"

namespace vv {

//! The number types of VTK's XML arrays.
enum class vtk_number { int8, uint8, int16, uint16, int32, uint32, int64, uint64, float32, float64 };

//! Bytes per value of a VTK number type.
VV_FORMATS_API std::size_t vtk_number_size(vtk_number type);

//! One array of point data: `components` values per point (1 or 3), each
//! of `type`, in the machine's byte order (the writer makes them
//! little-endian).
struct vtp_point_array {
  std::string name;
  vtk_number type = vtk_number::float64;
  unsigned components = 1;
  std::string bytes;
};

//! What a .vtp file holds: points, cells as lists of indices into them
//! (vertices, polylines, polygons) and the point data.
struct vtp_polydata {
  std::vector<std::array<double, 3>> points;
  std::vector<std::size_t> verts;  //!< points drawn alone (on no line or polygon)
  std::vector<std::vector<std::size_t>> lines;
  std::vector<std::vector<std::size_t>> polys;
  std::vector<vtp_point_array> point_data;
};

//! The bytes of a .vtp file; vv::error naming `path` when an index is past
//! the points or an array's size does not match them.
VV_FORMATS_API std::string vtp_bytes(const vtp_polydata& data, const std::string& path);

//! Writes a .vtp file atomically: on failure nothing is written and the
//! previous file is untouched.
VV_FORMATS_API void write_vtp_file(const std::string& path, const vtp_polydata& data);

//! One file of a series: the step it shows and its path relative to the
//! folder of the .pvd that lists it.
struct pvd_entry {
  std::uint64_t step = 0;
  std::string file;
};

//! The text of a ParaView collection listing the entries in order, each
//! step as the time ParaView shows.
VV_FORMATS_API std::string pvd_text(const std::vector<pvd_entry>& entries);

//! The entries of a .pvd file vv wrote (to go on with a series);
//! vv::error naming the file when it cannot be read or is no collection.
VV_FORMATS_API std::vector<pvd_entry> read_pvd(const std::string& path);

//! The collection beside a series of files named by a pattern with
//! "{step}" in it: the pattern without "{step}" (and the '-', '_' or '.'
//! just before it) and with the extension .pvd ("out/mesh-{step}.vtp" gives
//! "out/mesh.pvd", "{step}.vtp" gives "series.pvd").
VV_FORMATS_API std::string pvd_path_for(const std::string& pattern);

//! A series that grows as a run goes: each add() lists one more file and
//! rewrites the whole .pvd atomically, so that a run killed at any time
//! leaves the last complete collection, which ParaView opens.
class VV_FORMATS_API pvd_series {
 public:
  //! A new series at pvd_path (nothing is written until the first add).
  explicit pvd_series(std::string pvd_path);
  //! Goes on with the series in an existing .pvd file (see read_pvd).
  static pvd_series resume(const std::string& pvd_path);

  //! Lists `file` (a path as the caller wrote it, relative to the working
  //! folder or absolute) at `step`, replacing what was listed at that step,
  //! and writes the .pvd. Steps are listed in increasing order. On failure
  //! (vv::error naming the .pvd) the file and the series are as they were.
  void add(std::uint64_t step, const std::string& file);

  const std::string& path() const { return path_; }
  const std::vector<pvd_entry>& entries() const { return entries_; }

 private:
  std::string path_;
  std::vector<pvd_entry> entries_;
};

}  // namespace vv
