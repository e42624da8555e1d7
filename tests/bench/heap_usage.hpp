#pragma once
// Memory currently allocated, used to attribute memory to a mesh structure
// by taking a difference around its lifetime: what glibc malloc has handed
// out, and the runs vvlib maps itself for its vertex storage
// (vv/detail/page_runs.hpp), which malloc does not see.
#include <cstddef>
#include <fstream>
#include <malloc.h>
#include <sstream>
#include <string>

// Bytes of the mappings marked for transparent huge pages (VmFlags "hg"):
// vvlib's runs, whole, touched or not. Nothing else in these benchmarks
// asks for huge pages.
inline std::size_t huge_page_mappings()
{
  std::ifstream smaps("/proc/self/smaps");
  std::string line;
  std::size_t total = 0, size = 0;
  while (std::getline(smaps, line)) {
    unsigned long low = 0, high = 0;
    char dash = 0;
    std::istringstream header(line);
    if (line.rfind("VmFlags:", 0) == 0) {
      if ((line + " ").find(" hg ") != std::string::npos) total += size;
    } else if (header >> std::hex >> low >> dash >> high && dash == '-') {
      size = high - low;
    }
  }
  return total;
}

inline std::size_t heap_in_use()
{
  const struct mallinfo2 info = mallinfo2();
  // uordblks: arena chunks in use; hblkhd: large blocks served by mmap.
  return info.uordblks + info.hblkhd + huge_page_mappings();
}
