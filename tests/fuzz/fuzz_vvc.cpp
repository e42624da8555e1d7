// libFuzzer target for the translator: any bytes as a .vvp file must be
// translated or rejected with diagnostics, without crashing, hanging or a
// sanitizer report.
#include <cstddef>
#include <cstdint>
#include <string>

#include "translate.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  vvc::translation t = vvc::translate_text("fuzz.vvp", std::string(reinterpret_cast<const char*>(data), size));
  // Formatting touches every diagnostic's source line and caret.
  std::size_t total = 0;
  for (const auto& d : t.diag.list()) total += vvc::format(d).size();
  return total == static_cast<std::size_t>(-1) ? 1 : 0;
}
