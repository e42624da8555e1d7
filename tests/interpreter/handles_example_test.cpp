// examples/handles.vvp run as users run it (vvinterpreter --batch): the
// counts and genus it prints after each step, the solid torus its first
// step makes (checked with vvlib on the export), and its parameters.
#include <vv/vv.hpp>

#include <util/point.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "run_interpreter.hpp"
#include "test_files.hpp"

namespace {

const std::string handles_vvp = VV_SOURCE_DIR "/examples/handles.vvp";

test_run::result batch(std::vector<std::string> args) {
  std::vector<std::string> all = {"--batch", "--quiet"};
  all.insert(all.end(), args.begin(), args.end());
  all.push_back(handles_vvp);
  return test_run::run(test_run::interpreter(all), 300);
}

std::string report(const test_run::result& r) { return "stdout:\n" + r.out + "stderr:\n" + r.err; }

// What the example prints for 4 steps: the cube, the torus of step 1 and
// three corner cuttings (V = 2E, E = 4E, F = F + E + V).
const std::string four_steps =
    "start: V 8, E 12, F 6, genus 0\n"
    "step 1: V 16, E 32, F 16, genus 1\n"
    "step 2: V 64, E 128, F 64, genus 1\n"
    "step 3: V 256, E 512, F 256, genus 1\n"
    "step 4: V 1024, E 2048, F 1024, genus 1\n";

struct props {
  util::Point<double> pos;
  template <class F>
  void vv_fields(F&& f) {
    f("pos", pos);
  }
};
using graph = vv::graph<props>;

}  // namespace

TEST(HandlesExample, PrintsGenusOneAfterEveryStep) {
  test_run::result r = batch({"--steps", "4"});
  ASSERT_EQ(r.status, 0) << report(r);
  EXPECT_EQ(r.out, four_steps);
}

TEST(HandlesExample, TensionMovesVerticesButKeepsCountsAndGenus) {
  const std::string dir = test_files::scratch_dir();
  test_run::result plain = batch({"--steps", "2", "--export", dir + "handles_plain.vvm"});
  test_run::result tense = batch({"--steps", "2", "--set", "tension=0.8", "--export", dir + "handles_tense.vvm"});
  ASSERT_EQ(plain.status, 0) << report(plain);
  ASSERT_EQ(tense.status, 0) << report(tense);
  EXPECT_EQ(tense.out, plain.out);
  EXPECT_EQ(tense.out,
            "start: V 8, E 12, F 6, genus 0\nstep 1: V 16, E 32, F 16, genus 1\nstep 2: V 64, E 128, F 64, genus 1\n");
  EXPECT_NE(test_files::slurp(dir + "handles_tense.vvm"), test_files::slurp(dir + "handles_plain.vvm"));
}

TEST(HandlesExample, TensionOutsideItsRangeIsRefused) {
  test_run::result r = batch({"--steps", "1", "--set", "tension=0.95"});
  EXPECT_EQ(r.status, 1) << report(r);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "vvinterpreter: " + handles_vvp +
                       ":26: --set tension=0.95: 0.95 is outside the range [0.3, 0.9] of parameter tension\n");
}

TEST(HandlesExample, FirstStepMakesAClosedTorusOfQuads) {
  const std::string out = test_files::scratch_dir() + "handles_step1.vvm";
  test_run::result r = batch({"--steps", "1", "--export", out});
  ASSERT_EQ(r.status, 0) << report(r);
  graph::context ctx;
  graph::mesh S(ctx);
  S.readXMLFile(out);
  EXPECT_NO_THROW(vv::check_invariants(S, {true, true}));  // symmetric, every face a simple orbit
  std::vector<std::vector<std::uint32_t>> faces = vv::face_orbits(S);
  EXPECT_EQ(S.size(), 16u);
  EXPECT_EQ(vv::edge_count(S), 32u);
  ASSERT_EQ(faces.size(), 16u);
  for (const auto& face : faces) EXPECT_EQ(face.size(), 4u);
  EXPECT_EQ(vv::euler_characteristic(S), 0);  // genus 1
  // The tube's four walls stand at the window's edges, |x| or |y| = 0.5.
  std::size_t window_corners = 0;
  for (graph::vertex v : vv::each(S)) {
    const auto& p = v->pos;
    window_corners += std::abs(p.x()) == 0.5 && std::abs(p.y()) == 0.5 && std::abs(p.z()) == 1;
  }
  EXPECT_EQ(window_corners, 8u);
}
