#include "bench_translated.hpp"
#include "heap_usage.hpp"
#include "stopwatch.hpp"

#include <dlfcn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <util/point.hpp>
#include <vv/io/from_faces.hpp>
#include <vv/io/vvm.hpp>
#include <model/abi.hpp>
#include <vv/vv.hpp>

namespace {

struct position_props {
  util::Point<double> pos;
  template <class F>
  void vv_fields(F&& f)
  {
    f("pos", pos);
  }
};
using graph = vv::graph<position_props>;

// The input as the .vvm file the model's start block reads.
void write_input(const bench_input& input, const std::string& path)
{
  graph::context ctx;
  graph::mesh mesh(ctx);
  vv::build_from_faces(mesh, input.points, input.polygons(), "bench input");
  vv::write_vvm(mesh, path);
}

void write_all(int fd, const void* data, std::size_t size)
{
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) std::_Exit(3);
    p += n;
    size -= static_cast<std::size_t>(n);
  }
}

bool read_all(int fd, void* data, std::size_t size)
{
  char* p = static_cast<char*>(data);
  while (size > 0) {
    const ssize_t n = ::read(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

// The child: load, start, time the steps, report through fd. The report
// is a header (an error length, then the numbers) and the positions.
[[noreturn]] void child(const translated_model& model, int levels, bool keep_positions,
                        const std::string& model_dir, int fd)
{
  std::string problem;
  bench_result result;
  std::vector<double> positions;
  // Before loading: the context's first block of vertex storage is made
  // when the model's globals are.
  const std::size_t heap_before = heap_in_use();
  [&] {
    void* so = ::dlopen(model.plugin.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!so) return void(problem = ::dlerror());
    const auto* plugin = static_cast<const vv_plugin*>(::dlsym(so, VV_PLUGIN_DESCRIPTOR_SYMBOL));
    if (!plugin || plugin->abi_version != VV_PLUGIN_ABI_VERSION || !plugin->start || !plugin->step)
      return void(problem = model.plugin + " is not a model of this vvlib");
    const vv_mesh_entry* mesh = nullptr;
    for (std::size_t i = 0; i < plugin->mesh_count; ++i)
      if (std::strcmp(plugin->meshes[i].name, "S") == 0) mesh = &plugin->meshes[i];
    if (!mesh) return void(problem = model.plugin + " has no global mesh S");

    vv_plugin_settings settings{};
    settings.model_dir = model_dir.c_str();
    settings.seed = 1;
    plugin->configure(&settings);
    if (const char* e = plugin->start()) return void(problem = e);
    const stopwatch timer;
    for (int i = 0; i < levels; ++i)
      if (const char* e = plugin->step()) return void(problem = e);
    timer.stop(result);
    result.bytes = heap_in_use() - heap_before;

    vv_geometry geometry{};
    if (const char* e = mesh->geometry(0, &geometry)) return void(problem = e);
    result.vertices = mesh->vertex_count();
    result.faces = geometry.face_count;
    if (keep_positions && geometry.positions)
      positions.assign(geometry.positions, geometry.positions + 3 * geometry.vertex_count);
  }();
  const std::size_t header[5] = {problem.size(), result.bytes, result.vertices, result.faces, positions.size()};
  write_all(fd, header, sizeof header);
  write_all(fd, &result.ms, sizeof result.ms);
  write_all(fd, &result.cpu_ms, sizeof result.cpu_ms);
  write_all(fd, problem.data(), problem.size());
  write_all(fd, positions.data(), positions.size() * sizeof(double));
  ::close(fd);
  std::_Exit(0);
}

}  // namespace

bench_result run_translated(const translated_model& model, const bench_input& input, int levels,
                            bool keep_positions, const std::string& scratch)
{
  // The model reads ../models/<input> relative to its folder.
  const std::string model_dir = scratch + "/examples";
  const std::string input_file = scratch + "/models/" + model.input;
  std::filesystem::create_directories(model_dir);
  std::filesystem::create_directories(scratch + "/models");
  write_input(input, input_file);

  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error("pipe: " + std::string(std::strerror(errno)));
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("fork: " + std::string(std::strerror(errno)));
  if (pid == 0) {
    ::close(fds[0]);
    child(model, levels, keep_positions, model_dir, fds[1]);
  }
  ::close(fds[1]);
  std::size_t header[5] = {};
  bench_result result;
  std::string problem;
  std::vector<double> positions;
  bool complete = read_all(fds[0], header, sizeof header) && read_all(fds[0], &result.ms, sizeof result.ms) &&
                  read_all(fds[0], &result.cpu_ms, sizeof result.cpu_ms);
  if (complete) {
    problem.resize(header[0]);
    positions.resize(header[4]);
    complete = read_all(fds[0], problem.data(), problem.size()) &&
               read_all(fds[0], positions.data(), positions.size() * sizeof(double));
  }
  ::close(fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  std::filesystem::remove(input_file);
  if (!complete || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(model.plugin + ": the model's process ended without a result");
  if (!problem.empty()) throw std::runtime_error(model.plugin + ": " + problem);
  result.bytes = header[1];
  result.vertices = header[2];
  result.faces = header[3];
  for (std::size_t i = 0; i + 2 < positions.size(); i += 3)
    result.positions.push_back({positions[i], positions[i + 1], positions[i + 2]});
  return result;
}
