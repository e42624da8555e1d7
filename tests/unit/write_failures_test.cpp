// Writing files when something goes wrong (issue 9, items 18, 20, 21, 23):
// a disk that fills up mid-write, a target that is a symbolic link or a
// folder, a mesh without positions. The previous file is never replaced by
// a broken one, no temporary is left, and the message says why.
#include <vv/vv.hpp>
#include <vv/io/mesh_io.hpp>

#include <util/point.hpp>

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "positions_graph.hpp"
#include "test_files.hpp"

namespace {

namespace fs = std::filesystem;
using test_files::scratch_dir;
using test_files::slurp;
using Pt = util::Point<double>;

using G = positions_graph::graph;

struct NoPos {
  int mark = 0;
  template <class F>
  void vv_fields(F&& f) {
    f("mark", mark);
  }
};

// The names in a folder, sorted: a temporary left behind shows here.
std::vector<std::string> names_in(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

std::string fresh_dir(const std::string& name) {
  std::string d = scratch_dir() + name + "/";
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// A fan of n triangles around a centre (enough data to fill some KB).
std::vector<std::array<double, 3>> fan_points(std::size_t n) {
  std::vector<std::array<double, 3>> p = {{0, 0, 0}};
  for (std::size_t i = 0; i < n; ++i) p.push_back({std::cos(i * 0.1) * 1.2345678901234567, std::sin(i * 0.1), 0.5});
  return p;
}
std::vector<std::vector<std::size_t>> fan_faces(std::size_t n) {
  std::vector<std::vector<std::size_t>> f;
  for (std::size_t i = 1; i < n; ++i) f.push_back({0, i, i + 1});
  return f;
}

// Item 20: a PLY export to a nearly full disk exited 0 and replaced the
// good file with a truncated one. A file-size limit makes every write past
// 12 KB fail, as a full disk does; the export runs in a child process so
// the limit stays there.
TEST(WriteFailures, AFullDiskKeepsThePreviousFileAndSaysWhy) {
  for (const char* ext : {".ply", ".obj", ".off", ".stl", ".vvm"}) {
    SCOPED_TRACE(ext);
    std::string d = fresh_dir(std::string("full_disk") + ext);
    std::string path = d + "mesh" + ext;
    std::ofstream(path) << "the previous, good file\n";
    pid_t pid = fork();
    if (pid == 0) {
      signal(SIGXFSZ, SIG_IGN);  // the write fails with EFBIG instead
      rlimit limit{12 * 1024, 12 * 1024};
      setrlimit(RLIMIT_FSIZE, &limit);
      try {
        if (std::string(ext) == ".vvm") {
          G::context ctx;
          G::mesh m(ctx);
          for (int i = 0; i < 2000; ++i) {
            auto v = ctx.new_vertex();
            v->pos = Pt(i * 1.2345678901234567, 1.0 / (i + 3), 0.25);
            m.add(v);
          }
          vv::write_vvm(m, path);
        } else {
          vv::write_polygon_file(path, fan_points(2000), fan_faces(2000));
        }
      } catch (const vv::error& e) {
        std::string what = e.what();
        bool said = what == path + ": cannot write file: File too large";
        _exit(said ? 0 : 3);
      }
      _exit(2);  // written: the limit did not bite
    }
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 0) << "2: no error; 3: an error that does not say why";
    EXPECT_EQ(slurp(path), "the previous, good file\n");
    EXPECT_EQ(names_in(d), std::vector<std::string>{"mesh" + std::string(ext)});
  }
}

// Item 21: an export to a symbolic link replaced the link with a file.
TEST(WriteFailures, WritingThroughASymbolicLinkKeepsTheLink) {
  std::string d = fresh_dir("through_link");
  fs::create_directories(d + "real");
  std::ofstream(d + "real/mesh.obj") << "old\n";
  fs::create_symlink("real/mesh.obj", d + "mesh.obj");
  vv::write_polygon_file(d + "mesh.obj", fan_points(3), fan_faces(3));
  EXPECT_TRUE(fs::is_symlink(d + "mesh.obj"));
  EXPECT_NE(slurp(d + "real/mesh.obj"), "old\n");
  EXPECT_NE(slurp(d + "real/mesh.obj").find("f "), std::string::npos);
  EXPECT_EQ(names_in(d), (std::vector<std::string>{"mesh.obj", "real"}));
  EXPECT_EQ(names_in(d + "real"), std::vector<std::string>{"mesh.obj"});
  // .vvm files the same way.
  std::ofstream(d + "real/mesh.vvm") << "old\n";
  fs::create_symlink("real/mesh.vvm", d + "mesh.vvm");
  G::context ctx;
  G::mesh m(ctx);
  m.add(ctx.new_vertex());
  vv::write_vvm(m, d + "mesh.vvm");
  EXPECT_TRUE(fs::is_symlink(d + "mesh.vvm"));
  EXPECT_EQ(slurp(d + "real/mesh.vvm").rfind("<mesh>", 0), 0u);
}

// Item 23: a polygon export error said only "cannot write file".
TEST(WriteFailures, WritingOverAFolderSaysSo) {
  std::string d = fresh_dir("over_folder");
  fs::create_directories(d + "mesh.obj");
  try {
    vv::write_polygon_file(d + "mesh.obj", fan_points(3), fan_faces(3));
    ADD_FAILURE() << "wrote over a folder";
  } catch (const vv::error& e) {
    EXPECT_EQ(std::string(e.what()), d + "mesh.obj: cannot write file: it is a folder");
  }
  EXPECT_TRUE(fs::is_directory(d + "mesh.obj"));
  EXPECT_EQ(names_in(d), std::vector<std::string>{"mesh.obj"});
}

TEST(WriteFailures, AMissingFolderSaysSo) {
  std::string d = fresh_dir("missing_folder");
  try {
    vv::write_polygon_file(d + "no/such/mesh.off", fan_points(3), fan_faces(3));
    ADD_FAILURE() << "wrote into a missing folder";
  } catch (const vv::error& e) {
    EXPECT_EQ(std::string(e.what()), d + "no/such/mesh.off: cannot write file: No such file or directory");
  }
}

// Item 18: write_mesh wrote all-zero positions for a mesh without `pos`.
TEST(WriteFailures, APolygonFileOfAMeshWithoutPositionsIsRefused) {
  std::string d = fresh_dir("no_pos");
  vv::graph<NoPos>::context ctx;
  vv::graph<NoPos>::mesh m(ctx);
  auto a = ctx.new_vertex(), b = ctx.new_vertex(), c = ctx.new_vertex();
  vv::make_nb(a, {b, c});
  vv::make_nb(b, {c, a});
  vv::make_nb(c, {a, b});
  m.add(a), m.add(b), m.add(c);
  try {
    vv::write_mesh(m, d + "m.obj");
    ADD_FAILURE() << "a mesh without positions was written as OBJ";
  } catch (const vv::error& e) {
    EXPECT_EQ(std::string(e.what()),
              d + "m.obj: the vertices have no 'pos' property, so a obj file cannot hold them (.vvm can)");
  }
  EXPECT_FALSE(fs::exists(d + "m.obj"));
  EXPECT_NO_THROW(vv::write_mesh(m, d + "m.vvm"));
}

}  // namespace
