// Where a running model is (runner/crash_report.hpp: model_stack): a stack
// sample names the .vvp line of the instruction it interrupted, on every
// instruction of a block. The compiler gives some instructions no line of
// their own (line 0: the vv::where a statement stores for its error
// messages); a Stop that landed on one named no line (a CI run's failure of
// ViewerFaults.StopEndsAnEndlessStep...).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cache_harness.hpp"
#include "compile/process.hpp"
#include "runner/crash_report.hpp"
#include "runner/supervisor.hpp"

namespace fs = std::filesystem;

namespace sample_lines {

const std::string endless = VV_TESTS_DIR "/fault_models/endless_step2.vvp";

//! The one model.so a cache of the test's own holds.
std::string built_model(const std::string& cache) {
  std::string found;
  for (const auto& e : fs::recursive_directory_iterator(cache + "/plugins"))
    if (e.path().filename() == "model.so") found = e.path().string();
  return found;
}

//! [first, end) of a function's code, from the symbol table (nm -S).
std::pair<std::uintptr_t, std::uintptr_t> function_range(const std::string& so, const std::string& function) {
  vvi::process_result r = vvi::run_process({"nm", "-C", "-S", "--defined-only", so});
  std::istringstream lines(r.output);
  for (std::string l; std::getline(lines, l);) {
    std::istringstream in(l);
    std::string address, size, kind, name;
    if (!(in >> address >> size >> kind) || !std::getline(in >> std::ws, name) || name != function) continue;
    std::uintptr_t first = std::stoull(address, nullptr, 16);
    return {first, first + std::stoull(size, nullptr, 16)};
  }
  return {0, 0};
}

//! The addresses of the instructions in [first, end) (objdump -d).
std::vector<std::uintptr_t> instructions(const std::string& so, std::pair<std::uintptr_t, std::uintptr_t> range) {
  char start[32], stop[32];
  std::snprintf(start, sizeof start, "--start-address=0x%llx", static_cast<unsigned long long>(range.first));
  std::snprintf(stop, sizeof stop, "--stop-address=0x%llx", static_cast<unsigned long long>(range.second));
  vvi::process_result r = vvi::run_process({"objdump", "-d", "--no-show-raw-insn", start, stop, so});
  std::vector<std::uintptr_t> out;
  std::istringstream lines(r.output);
  for (std::string l; std::getline(lines, l);) {
    std::size_t colon = l.find(':');
    if (colon == std::string::npos || l.empty() || l[0] != ' ') continue;
    out.push_back(std::stoull(l.substr(0, colon), nullptr, 16));
  }
  return out;
}

//! The line of `model` addr2line gives each address by itself (0: none,
//! the compiler's line 0 or another file).
std::vector<unsigned> own_lines(const std::string& so, const std::vector<std::uintptr_t>& addresses,
                                const std::string& model) {
  std::vector<std::string> argv = {"addr2line", "-a", "-i", "-e", so};
  for (std::uintptr_t a : addresses) {
    char hex[32];
    std::snprintf(hex, sizeof hex, "0x%llx", static_cast<unsigned long long>(a));
    argv.push_back(hex);
  }
  vvi::process_result r = vvi::run_process(argv);
  std::vector<unsigned> out;
  std::istringstream lines(r.output);
  for (std::string l; std::getline(lines, l);) {
    if (l.rfind("0x", 0) == 0) out.push_back(0);
    else if (!out.empty() && out.back() == 0 && l.rfind(model + ":", 0) == 0)
      out.back() = static_cast<unsigned>(std::strtoul(l.c_str() + model.size() + 1, nullptr, 10));
  }
  return out;
}

//! A sample interrupted at `at` in the model, loaded at `base`.
vvi::stack_sample sample_at(std::uintptr_t base, std::uintptr_t at, const std::string& loaded) {
  vvi::stack_sample s;
  s.why = "running";
  s.pc = base + at;
  s.frames = {s.pc};
  char map[256];
  std::snprintf(map, sizeof map, "%llx-%llx r-xp 00000000 00:00 0 %s", static_cast<unsigned long long>(base),
                static_cast<unsigned long long>(base + 0x10000000), loaded.c_str());
  s.maps = {map};
  return s;
}

}  // namespace sample_lines

using namespace sample_lines;

// Sampled anywhere in the step block, a model names a line of the block;
// amid the endless loop of line 22 (what a Stop interrupts), line 22.
TEST(SampleLines, EveryInstructionOfAStepNamesItsLineAndTheLoopsAreLine22) {
  const std::string dir = fresh_dir("sample_lines");
  const std::string cache = cache_with_header(dir);
  test_run::result built = run_in(dir, cache, {"--compile-only", endless});
  ASSERT_EQ(built.status, 0) << report(built);
  const std::string so = built_model(cache);
  ASSERT_FALSE(so.empty()) << "no model.so in " << cache;

  auto range = function_range(so, "vv_block_step()");
  ASSERT_LT(range.first, range.second) << "no vv_block_step() in " << so;
  std::vector<std::uintptr_t> code = instructions(so, range);
  ASSERT_GT(code.size(), 10u);
  std::vector<unsigned> own = own_lines(so, code, endless);
  ASSERT_EQ(own.size(), code.size());
  // The lines of the instructions before and after each one that have one.
  std::vector<unsigned> before(code.size(), 0), after(code.size(), 0);
  for (std::size_t i = 1; i < code.size(); ++i) before[i] = own[i - 1] != 0 ? own[i - 1] : before[i - 1];
  for (std::size_t i = code.size() - 1; i-- > 0;) after[i] = own[i + 1] != 0 ? own[i + 1] : after[i + 1];
  ASSERT_NE(std::count(own.begin(), own.end(), 22u), 0) << "no instruction of line 22";

  // The loaded copy as the child's maps name it.
  const std::map<std::string, std::string> modules = {{"/memfd:model", so}};
  const std::uintptr_t base = 0x7f0000000000;
  std::size_t without_own_line = 0;
  for (std::size_t i = 0; i < code.size(); ++i) {
    // Every instruction without a line of its own, and every tenth other.
    if (own[i] != 0 && i % 10 != 0) continue;
    without_own_line += own[i] == 0 ? 1 : 0;
    std::vector<vvi::source_frame> stack =
        vvi::model_stack(sample_at(base, code[i], "/memfd:model (deleted)"), modules);
    ASSERT_FALSE(stack.empty()) << "no line for the instruction at 0x" << std::hex << code[i];
    EXPECT_EQ(stack.front().file, endless);
    EXPECT_EQ(stack.front().function, "the step block");
    if (own[i] != 0) EXPECT_EQ(stack.front().line, own[i]) << std::hex << code[i];
    // The step block is lines 17 to 24.
    EXPECT_GE(stack.front().line, 17u) << std::hex << code[i];
    EXPECT_LE(stack.front().line, 24u) << std::hex << code[i];
    // Amid the loop (instructions of line 22 on both sides), line 22.
    if (own[i] == 0 && before[i] == 22 && after[i] == 22) EXPECT_EQ(stack.front().line, 22u) << std::hex << code[i];
  }
  std::printf("%zu instructions, %zu without a line of their own\n", code.size(), without_own_line);
}
