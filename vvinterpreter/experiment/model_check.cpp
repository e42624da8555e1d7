#include "experiment/model_check.hpp"

#include <cstdio>

#include "compile/model_build.hpp"
#include "experiment/child_process.hpp"
#include "experiment/sweep_identity.hpp"
#include "runner/model_runner.hpp"

namespace vvi {

namespace {

// The host's reason from its standard error: the line after
// "vvinterpreter: " that is not the usage text.
std::string reason_in(const std::string& err) {
  const std::string prefix = "vvinterpreter: ";
  std::size_t at = err.rfind("\n" + prefix);
  at = at == std::string::npos ? (err.rfind(prefix, 0) == 0 ? 0 : std::string::npos) : at + 1;
  if (at == std::string::npos) return err.empty() ? "the model's parameters could not be listed" : err;
  std::size_t end = err.find('\n', at);
  return err.substr(at + prefix.size(), end == std::string::npos ? std::string::npos : end - at - prefix.size());
}

std::vector<std::string> list_command(const std::string& self, const run_arguments& a) {
  std::vector<std::string> cmd = {self, "--list-params", "--cache", a.cache};
  cmd.insert(cmd.end(), a.batch_options.begin(), a.batch_options.end());
  return cmd;
}

// The model's absolute path (what the runs are given) as the user typed it.
std::string shown(std::string text, const std::string& absolute, const std::string& typed) {
  for (std::size_t at = 0; (at = text.find(absolute + ":", at)) != std::string::npos; at += typed.size())
    text.replace(at, absolute.size(), typed);
  return text;
}

}  // namespace

checked_model check_model(const options& o, const std::string& self, const run_arguments& a,
                          const std::vector<swept_parameter>& swept) {
  checked_model m;
  build_result b = model_runner(o).build(o.rebuild);
  if (!b.ok) {
    if (!o.quiet) std::printf("%s", b.details.c_str());
    m.error = b.error;
    return m;
  }
  if (!b.warnings.empty()) std::fprintf(stderr, "%s", b.warnings.c_str());
  if (!o.quiet) {
    if (b.cached) std::printf("%s: compiled model found in the cache\n", o.model.c_str());
    else std::printf("%s: translated in %.0f ms, compiled in %.2f s\n", o.model.c_str(), b.translate_ms, b.compile_ms / 1000);
  }
  m.program = program_hash(b.sources.empty() ? std::vector<std::string>{o.model} : b.sources);

  // The parameters' names (--list-params: "name type value [range]").
  std::vector<std::string> cmd = list_command(self, a);
  cmd.push_back(a.model);
  captured listed = run_captured(cmd);
  if (listed.status != 0) {
    m.error = shown(reason_in(listed.err), a.model, o.model);
    return m;
  }
  std::vector<std::string> names;
  for (std::size_t from = 0; from < listed.out.size();) {
    std::size_t end = listed.out.find('\n', from);
    if (end == std::string::npos) end = listed.out.size();
    std::string line = listed.out.substr(from, end - from);
    if (!line.empty()) names.push_back(line.substr(0, line.find(' ')));
    from = end + 1;
  }
  std::string known;
  for (const std::string& n : names) known += (known.empty() ? "" : ", ") + n;
  for (const swept_parameter& p : swept) {
    bool found = false;
    for (const std::string& n : names) found = found || n == p.name;
    if (!found) {
      m.error = "--sweep " + p.typed + ": the model " + o.model + " has no parameter " + p.name +
                (known.empty() ? " (it has none)" : " (its parameters: " + known + ")");
      return m;
    }
    for (const auto& [name, value] : o.parameter_values)
      if (name == p.name) {
        m.error = "--sweep " + p.typed + " and --set " + name + "=" + value + ": a parameter is either swept or set";
        return m;
      }
  }

  // Every value, against the parameter's type and range, in one process.
  cmd = list_command(self, a);
  for (const swept_parameter& p : swept)
    for (const std::string& v : p.values) {
      cmd.push_back("--set");
      cmd.push_back(p.name + "=" + v);
    }
  cmd.push_back(a.model);
  captured checked = run_captured(cmd);
  if (checked.status != 0) {
    std::string why = shown(reason_in(checked.err), a.model, o.model);
    for (const swept_parameter& p : swept)
      if (why.find("--set " + p.name + "=") != std::string::npos) why = "--sweep " + p.typed + ": " + why;
    m.error = why;
  }
  return m;
}

}  // namespace vvi
