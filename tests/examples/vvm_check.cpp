// Checks an exported .vvm against expectations:
//   vvm_check OUT.vvm [--golden FILE] [--tolerance T] [--vertices N] [--edges N]
//             [--faces N] [--max-face N]
// --golden: the same vertices, neighbourhoods, edge records and mesh
//   properties, numbers equal within T (default 1e-9, relative to the
//   larger magnitude, absolute below 1); other text identical.
// --vertices/--edges/--faces: exact counts (faces: closed orbits of at most
//   --max-face corners, at least 3).
// Prints what differs; exits 0 when everything matches, 1 otherwise, 2 on
// bad input.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include <pugixml.hpp>
#include <vv/vv.hpp>

namespace {

struct no_fields {};
using graph = vv::graph<no_fields>;

bool numbers_match(const std::string& a, const std::string& b, double tol) {
  std::istringstream sa(a), sb(b);
  std::string ta, tb;
  while (true) {
    bool ra = static_cast<bool>(sa >> ta), rb = static_cast<bool>(sb >> tb);
    if (ra != rb) return false;
    if (!ra) return true;
    if (ta == tb) continue;
    char* ea = nullptr;
    char* eb = nullptr;
    double x = std::strtod(ta.c_str(), &ea), y = std::strtod(tb.c_str(), &eb);
    if (*ea || *eb) return false;  // words that differ
    double scale = std::max({1.0, std::fabs(x), std::fabs(y)});
    if (!(std::fabs(x - y) <= tol * scale)) return false;
  }
}

int compare(const std::string& out, const std::string& golden, double tol) {
  pugi::xml_document a, b;
  if (!a.load_file(out.c_str()) || !b.load_file(golden.c_str())) {
    std::fprintf(stderr, "vvm_check: cannot parse %s or %s\n", out.c_str(), golden.c_str());
    return 2;
  }
  int differences = 0;
  auto report = [&](const std::string& what) {
    if (++differences <= 10) std::fprintf(stderr, "differs from %s: %s\n", golden.c_str(), what.c_str());
  };
  auto compare_attributes = [&](const pugi::xml_node& x, const pugi::xml_node& y, const std::string& where) {
    for (pugi::xml_attribute ay : y.attributes()) {
      pugi::xml_attribute ax = x.attribute(ay.name());
      if (!ax) report(where + ": no attribute " + ay.name());
      else if (!numbers_match(ax.value(), ay.value(), tol))
        report(where + ": " + ay.name() + " is \"" + ax.value() + "\", expected \"" + ay.value() + "\"");
    }
    for (pugi::xml_attribute ax : x.attributes())
      if (!y.attribute(ax.name())) report(where + ": unexpected attribute " + ax.name());
  };
  pugi::xml_node ra = a.document_element(), rb = b.document_element();
  compare_attributes(ra, rb, "<mesh>");
  std::vector<pugi::xml_node> ca(ra.children().begin(), ra.children().end());
  std::vector<pugi::xml_node> cb(rb.children().begin(), rb.children().end());
  if (ca.size() != cb.size())
    report(std::to_string(ca.size()) + " elements, expected " + std::to_string(cb.size()));
  for (std::size_t i = 0; i < std::min(ca.size(), cb.size()); ++i) {
    std::string where = std::string("<") + cb[i].name() + "> #" + std::to_string(i);
    if (std::strcmp(ca[i].name(), cb[i].name()) != 0) report(where + ": is <" + ca[i].name() + ">");
    else compare_attributes(ca[i], cb[i], where);
  }
  if (differences > 10) std::fprintf(stderr, "... %d differences in all\n", differences);
  return differences ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: vvm_check OUT.vvm [--golden FILE] [--tolerance T] [--vertices N] [--edges N] [--faces N] [--max-face N]\n");
    return 2;
  }
  std::string out = argv[1], golden;
  double tol = 1e-9;
  long want_v = -1, want_e = -1, want_f = -1;
  std::size_t max_face = static_cast<std::size_t>(-1);
  for (int i = 2; i + 1 < argc; i += 2) {
    std::string a = argv[i], v = argv[i + 1];
    if (a == "--golden") golden = v;
    else if (a == "--tolerance") tol = std::atof(v.c_str());
    else if (a == "--vertices") want_v = std::atol(v.c_str());
    else if (a == "--edges") want_e = std::atol(v.c_str());
    else if (a == "--faces") want_f = std::atol(v.c_str());
    else if (a == "--max-face") max_face = static_cast<std::size_t>(std::atol(v.c_str()));
    else {
      std::fprintf(stderr, "vvm_check: unknown option %s\n", a.c_str());
      return 2;
    }
  }
  int status = 0;
  if (want_v >= 0 || want_e >= 0 || want_f >= 0) {
    graph::context ctx;
    graph::mesh m(ctx);
    try {
      vv::read_vvm(m, out);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "vvm_check: %s\n", e.what());
      return 2;
    }
    long v = static_cast<long>(m.size()), e = static_cast<long>(vv::edge_count(m)), f = 0;
    for (const auto& face : vv::face_orbits(m, max_face)) f += face.size() >= 3;
    auto check = [&](const char* what, long got, long want) {
      if (want >= 0 && got != want) {
        std::fprintf(stderr, "%s: %ld %s, expected %ld\n", out.c_str(), got, what, want);
        status = 1;
      }
    };
    check("vertices", v, want_v);
    check("edges", e, want_e);
    check("faces", f, want_f);
    std::printf("%s: V=%ld E=%ld F=%ld\n", out.c_str(), v, e, f);
  }
  if (!golden.empty()) status = std::max(status, compare(out, golden, tol));
  return status;
}
