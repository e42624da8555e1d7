// The default job: Loop-subdivide a model with vvlib and save the result.
//
//   vv_loop_demo [INPUT] [STEPS] [OUTDIR]
//
// Defaults: models/pyramid.vvm, 3 steps, ./out. Writes OUTDIR/NAME-loopK.obj
// and .vvm and prints what it wrote; exits non-zero with a one-line reason
// on any error.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>

#include <vv/io/mesh_io.hpp>

#include "loop_subdivision.hpp"

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  std::string input = argc > 1 ? argv[1] : std::string(VV_MODELS_DIR) + "/pyramid.vvm";
  int steps = argc > 2 ? std::atoi(argv[2]) : 3;
  fs::path outdir = argc > 3 ? argv[3] : "out";
  if (argc > 4 || steps < 0) {
    std::fprintf(stderr, "usage: vv_loop_demo [INPUT] [STEPS >= 0] [OUTDIR]\n");
    return 2;
  }
  try {
    loop_example::graph::context ctx;
    loop_example::graph::mesh S(ctx);
    vv::read_mesh(S, input);
    std::printf("read %s: %zu vertices, %zu edges, %zu faces\n", input.c_str(), S.size(),
                vv::edge_count(S), vv::face_orbits(S).size());
    for (int i = 1; i <= steps; ++i) {
      loop_example::subdivide(S);
      std::printf("Loop step %d: %zu vertices, %zu edges, %zu faces\n", i, S.size(),
                  vv::edge_count(S), vv::face_orbits(S).size());
    }
    fs::create_directories(outdir);
    std::string stem = fs::path(input).stem().string() + "-loop" + std::to_string(steps);
    for (const char* ext : {".obj", ".vvm"}) {
      fs::path out = outdir / (stem + ext);
      vv::write_mesh(S, out.string());
      std::printf("wrote %s\n", out.string().c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vv_loop_demo: %s\n", e.what());
    return 1;
  }
  return 0;
}
