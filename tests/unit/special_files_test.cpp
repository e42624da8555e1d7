// The mesh readers (.vvm and the polygon formats, through read_mesh, the
// mesh members and read_vvm) refuse what is no regular file and what is
// over the size limit of mesh files, unread, naming the file and what it
// is; a FIFO is refused without blocking. The mesh is left as it was.
#include <vv/vv.hpp>
#include <vv/io/mesh_io.hpp>

#include <util/point.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "positions_graph.hpp"
#include "special_files.hpp"
#include "test_files.hpp"

#ifndef VV_SOURCE_DIR
#error "compile with -DVV_SOURCE_DIR='\"/path/to/source\"'"
#endif

namespace {

using G = positions_graph::graph;

const char* const mesh_extensions[] = {".vvm", ".obj", ".off", ".ply", ".stl"};

// The message of reading path into a mesh that holds the pyramid, checking
// that the pyramid is still there afterwards.
template <class Read>
std::string refusal(const std::string& path, Read&& read) {
  G::context ctx;
  G::mesh M(ctx);
  vv::read_vvm(M, VV_SOURCE_DIR "/models/pyramid.vvm");
  std::string message = special_files::error_reading_fifo(path, [&] { read(M, path); });
  EXPECT_EQ(M.size(), 6u) << path;
  return message;
}

std::string read_mesh_refusal(const std::string& path) {
  return refusal(path, [](G::mesh& M, const std::string& p) { vv::read_mesh(M, p); });
}

TEST(MeshReaders, RefuseAFifoWithoutBlocking) {
  for (const char* ext : mesh_extensions) {
    const std::string path = special_files::fifo(std::string("pipe") + ext);
    EXPECT_EQ(read_mesh_refusal(path), path + ": cannot open file: it is a FIFO (named pipe), not a regular file");
  }
}

TEST(MeshReaders, RefuseALinkToDevZero) {
  for (const char* ext : mesh_extensions) {
    const std::string path = special_files::link_to_dev_zero(std::string("zero") + ext);
    EXPECT_EQ(read_mesh_refusal(path),
              path + ": cannot open file: it is a symbolic link to /dev/zero, a character device, not a regular file");
  }
}

// A folder was "empty file" as .vvm, and "not a readable ... file" as the
// others.
TEST(MeshReaders, RefuseAFolderSayingSo) {
  for (const char* ext : mesh_extensions) {
    const std::string path = special_files::folder(std::string("folder") + ext);
    EXPECT_EQ(read_mesh_refusal(path), path + ": cannot open file: it is a folder, not a file");
  }
}

TEST(MeshReaders, RefuseAFileOverTheLimitUnread) {
  EXPECT_EQ(vv::io::mesh_file_limit.bytes, std::uint64_t(1) << 30);
  for (const char* ext : mesh_extensions) {
    const std::string path = special_files::sparse_file(std::string("huge") + ext, vv::io::mesh_file_limit.bytes + 1);
    EXPECT_EQ(read_mesh_refusal(path),
              path + ": cannot open file: it is 1 GiB (1073741825 bytes), over the 1 GiB limit of mesh files");
  }
}

// What a program sees: the member functions, with the line that called them.
TEST(MeshReaders, TheMembersNameTheCallersLineAndTheFile) {
  const std::string fifo = special_files::fifo("member_pipe.vvm");
  const vv::where at{"model.vvp", 12};
  EXPECT_EQ(refusal(fifo, [&](G::mesh& M, const std::string& p) { M.readXMLFile(p, at); }),
            "model.vvp:12: readXMLFile: " + fifo + ": cannot open file: it is a FIFO (named pipe), not a regular file");
  const std::string zero = special_files::link_to_dev_zero("member_zero.stl");
  EXPECT_EQ(refusal(zero, [&](G::mesh& M, const std::string& p) { M.readFile(p, at); }),
            "model.vvp:12: readFile: " + zero +
                ": cannot open file: it is a symbolic link to /dev/zero, a character device, not a regular file");
}

}  // namespace
