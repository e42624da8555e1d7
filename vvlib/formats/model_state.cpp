// The parts of a model's saved state that do not depend on its types
// (model/state_parts.hpp, model/c_random.hpp), compiled once here rather
// than in every model's declarations' part.
#include <stdlib.h>

#include <array>
#include <cstdint>
#include <cstring>
#include <locale>
#include <sstream>
#include <vector>

#include <model/c_random.hpp>
#include <model/state_parts.hpp>

namespace vv::model {

namespace {

#ifdef __GLIBC__
// The table's bytes for the type in its first word: the type word, then
// 0, 7, 15, 31 or 63 numbers.
std::size_t table_bytes(const char* table) {
  std::int32_t word;
  std::memcpy(&word, table, 4);
  static const std::size_t degree[] = {0, 7, 15, 31, 63};
  const int type = static_cast<int>(static_cast<std::uint32_t>(word) % 5u);
  return 4 * (1 + degree[type]);
}
#endif

void save_plot(state_writer& w, const vv::plot_series& s) {
  w.text(s.name);
  w.u64(s.steps.size());
  for (std::size_t i = 0; i < s.steps.size(); ++i) w.u32(s.steps[i]), w.f64(s.values[i]);
}

vv::plot_series load_plot(state_reader& r) {
  vv::plot_series s;
  s.name = r.text("a plot's name");
  for (std::uint64_t n = r.count("a plot's values", 12); n > 0; --n) {
    s.steps.push_back(r.u32("a plot's step"));
    s.values.push_back(r.f64("a plot's value"));
  }
  return s;
}

std::array<std::vector<file_object*>*, 4> file_lists(vv::proxy& p) {
  return {&p.materials, &p.palettes, &p.functions, &p.contours};
}

}  // namespace

void save_c_random(state_writer& w) {
#ifdef __GLIBC__
  alignas(std::int32_t) char spare[128];
  char* table = initstate(1, spare, sizeof spare);  // the model's table, with its position written in
  w.text(std::string(table, table_bytes(table)));
  setstate(table);
#else
  w.text("");
#endif
  unsigned short any[3] = {0, 0, 0};
  unsigned short x[3];
  std::memcpy(x, seed48(any), sizeof x);
  seed48(x);
  for (unsigned short part : x) w.u32(part);
}

void restore_c_random(state_reader& r) {
  const std::string saved = r.text("the C library's random table");
#ifdef __GLIBC__
  if (!saved.empty()) {
    alignas(std::int32_t) char spare[128];
    char* table = initstate(1, spare, sizeof spare);
    if (saved.size() != table_bytes(table) || saved.size() != table_bytes(saved.data())) {
      setstate(table);
      throw state_error("the C library's random table has another size than the saved one");
    }
    std::memcpy(table, saved.data(), saved.size());
    setstate(table);
  }
#endif
  unsigned short x[3];
  for (unsigned short& part : x) part = static_cast<unsigned short>(r.u32("drand48's state"));
  seed48(x);
}

void save_proxy(state_writer& w, const vv::proxy& p, const file_object* const* files, std::size_t n) {
  w.u32(p.steps), w.u32(p.delay_msec), w.u8(p.no_animate), w.u8(p.record_frame), w.u32(p.max_face);
  w.u8(p.has_view_volume);
  for (int i = 0; i < 3; ++i) w.f64(p.view_min[i]), w.f64(p.view_max[i]);
  w.u32(p.plot_step);
  w.u64(p.plots.size());
  for (const vv::plot_series& s : p.plots) save_plot(w, s);
  for (std::vector<file_object*>* list : file_lists(const_cast<vv::proxy&>(p))) {
    w.u64(list->size());
    for (const file_object* f : *list) {
      std::size_t i = 0;
      while (i < n && (files[i] != f || !f)) ++i;
      if (i == n) throw state_error("the proxy lists a file object that is no global of the program");
      w.u64(i);
    }
  }
}

void restore_proxy(state_reader& r, vv::proxy& p, const file_object* const* files, std::size_t n) {
  p.steps = r.u32("proxy.steps"), p.delay_msec = r.u32("proxy.delay_msec");
  p.no_animate = r.u8("proxy.no_animate") != 0, p.record_frame = r.u8("proxy.record_frame") != 0;
  p.max_face = r.u32("proxy.max_face");
  p.has_view_volume = r.u8("the view volume") != 0;
  for (int i = 0; i < 3; ++i) p.view_min[i] = r.f64("the view volume"), p.view_max[i] = r.f64("the view volume");
  p.plot_step = r.u32("the plot step");
  p.plots.clear();
  for (std::uint64_t k = r.count("the plots", 16); k > 0; --k) p.plots.push_back(load_plot(r));
  for (std::vector<file_object*>* list : file_lists(p)) {
    list->clear();
    for (std::uint64_t k = r.count("the proxy's file objects", 8); k > 0; --k) {
      std::uint64_t i = r.u64("a file object");
      if (i >= n || !files[i]) throw state_error("a file object that is no global of the program");
      list->push_back(const_cast<file_object*>(files[i]));
    }
  }
}

void save_engine(state_writer& w, const std::mt19937_64& e) {
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os << e;
  w.text(os.str());
}

void restore_engine(state_reader& r, std::mt19937_64& e) {
  std::istringstream is(r.text("the random generator"));
  is.imbue(std::locale::classic());
  is >> e;
  if (is.fail()) throw state_error("the random generator's state does not read back");
}

void save_texts(state_writer& w, const std::set<std::string>& texts) {
  w.u64(texts.size());
  for (const std::string& t : texts) w.text(t);
}

void restore_texts(state_reader& r, std::set<std::string>& texts) {
  texts.clear();
  for (std::uint64_t n = r.count("the warnings said", 8); n > 0; --n) texts.insert(r.text("a warning"));
}

}  // namespace vv::model
