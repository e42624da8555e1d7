// Reading VTK files with VTK itself, for tests: runs tests/unit/read_vtk.py
// with the python3 that has python3-vtk9 (VV_VTK_PYTHON, found by CMake)
// and parses what it prints.
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#ifndef VV_SOURCE_DIR
#error "compile with -DVV_SOURCE_DIR='\"/path/to/source\"'"
#endif
#ifndef VV_VTK_PYTHON
#error "compile with -DVV_VTK_PYTHON='\"python3 with vtkmodules\"' (empty when none was found)"
#endif

namespace vtk_read_back {

// What read_vtk.py printed about a .vtp file.
struct read_back {
  std::vector<std::array<double, 3>> points;
  std::map<std::string, std::vector<std::vector<std::size_t>>> cells;  // verts, lines, polys
  struct array {
    std::string name, type;
    unsigned components = 0;
    std::vector<std::vector<double>> values;  // per point
  };
  std::vector<array> arrays;
  std::vector<std::string> datasets;  // "STEP FILE POINTS", for a .pvd
};

// Runs VTK's reader (python3-vtk9) on path; fails the test with what it
// said when it cannot read the file.
inline read_back read_with_vtk(const std::string& path) {
  read_back out;
  std::string python = VV_VTK_PYTHON;
  if (python.empty()) {
    ADD_FAILURE() << "no python3 with VTK (python3-vtk9) was found when configuring: run scripts/install-deps";
    return out;
  }
  std::string command = python + " " VV_SOURCE_DIR "/tests/unit/read_vtk.py '" + path + "' 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  EXPECT_NE(pipe, nullptr);
  if (!pipe) return out;
  std::string text;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) text.append(buf, n);
  int status = ::pclose(pipe);
  bool succeeded = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  EXPECT_TRUE(succeeded) << command << ":\n" << text;
  if (!succeeded) return out;

  std::istringstream lines(text);
  std::string line, kind;
  std::vector<std::vector<std::size_t>>* cells = nullptr;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    words >> kind;
    auto numbers = [&] {
      std::vector<double> v;
      for (std::string w; words >> w;) v.push_back(std::strtod(w.c_str(), nullptr));
      return v;
    };
    if (kind == "p") {
      std::vector<double> v = numbers();
      EXPECT_EQ(v.size(), 3u) << line;
      if (v.size() == 3) out.points.push_back({v[0], v[1], v[2]});
    } else if (kind == "verts" || kind == "lines" || kind == "polys") {
      cells = &out.cells[kind];
    } else if (kind == "c") {
      std::vector<std::size_t> cell;
      for (std::size_t i; words >> i;) cell.push_back(i);
      if (cells) cells->push_back(cell);
    } else if (kind == "array") {
      out.arrays.emplace_back();
      words >> out.arrays.back().name >> out.arrays.back().type >> out.arrays.back().components;
    } else if (kind == "v") {
      if (!out.arrays.empty()) out.arrays.back().values.push_back(numbers());
    } else if (kind == "dataset") {
      std::string rest;
      std::getline(words >> std::ws, rest);
      out.datasets.push_back(rest);
    } else if (kind != "points") {
      ADD_FAILURE() << "unexpected line from read_vtk.py: " << line;
    }
  }
  return out;
}

}  // namespace vtk_read_back
