// --merge DIR... --out DIR: the shards of one sweep joined into one folder
// that is what a sweep on one machine would have made (the run folders,
// sweep.txt, runs.csv and failed.csv, byte for byte).
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>

#include <vv/io/files.hpp>

#include "experiment/run_record.hpp"
#include "experiment/runs_table.hpp"
#include "experiment/sweep.hpp"
#include "experiment/sweep_folder.hpp"
#include "experiment/sweep_identity.hpp"

namespace vvi {

namespace fs = std::filesystem;

namespace {

int merge_refused(const std::string& why) {
  std::fprintf(stderr, "vvinterpreter: %s\n", why.c_str());
  return 1;
}

std::string canonical(const std::string& p) {
  std::error_code ec;
  fs::path c = fs::weakly_canonical(p, ec);
  return ec ? p : c.string();
}

// The identity text in a folder to merge, or "" with the reason in why.
std::string identity_in(const std::string& dir, std::string& why) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    why = dir + ": no such folder";
    return "";
  }
  std::optional<std::string> text = vv::io::read_file(dir + "/" + identity_file);
  if (!text) {
    why = dir + ": not the folder of a sweep (it has no " + identity_file + ")";
    return "";
  }
  std::string bad;
  if (!parse_identity(*text, bad)) {
    why = dir + "/" + identity_file + ": " + bad;
    return "";
  }
  return *text;
}

// A run's folder copied in (hard links where the file system allows),
// under a temporary name, then renamed into place: a merge killed midway
// leaves no half-copied run.
std::string bring_in(const std::string& from, const std::string& to) {
  std::string part = to + ".merging";
  std::error_code ec;
  fs::remove_all(part, ec);
  fs::copy(from, part, fs::copy_options::recursive | fs::copy_options::create_hard_links, ec);
  if (ec) {
    fs::remove_all(part, ec);
    fs::copy(from, part, fs::copy_options::recursive, ec);
  }
  if (!ec) fs::remove_all(to, ec);
  if (!ec) fs::rename(part, to, ec);
  return ec ? to + ": cannot copy the run from " + from + ": " + ec.message() : "";
}

std::string listed(const std::vector<std::string>& problems) {
  std::string out;
  for (std::size_t i = 0; i < problems.size() && i < 10; ++i) out += "\n  " + problems[i];
  if (problems.size() > 10) out += "\n  and " + std::to_string(problems.size() - 10) + " more";
  return out;
}

}  // namespace

int run_merge(const options& o) {
  const std::vector<std::string>& dirs = o.sweep.merge;
  const std::string& out = o.sweep.out;
  std::string why, text = identity_in(dirs[0], why);
  if (text.empty()) return merge_refused("--merge " + why);
  for (std::size_t i = 1; i < dirs.size(); ++i) {
    std::string other = identity_in(dirs[i], why);
    if (other.empty()) return merge_refused("--merge " + why);
    if (other != text)
      return merge_refused("--merge: " + dirs[i] + " holds another sweep than " + dirs[0] + " (" + identity_file + ": " +
                    first_difference(text, other) + "); only the shards of one sweep can be merged");
  }
  std::string bad;
  sweep_plan plan = parse_identity(text, bad)->plan();

  // Every folder locked while it is read (a shard still running is refused).
  std::string dest = canonical(out);
  std::vector<std::unique_ptr<sweep_folder>> locks;
  std::vector<std::string> sources;
  for (const std::string& d : dirs) {
    if (canonical(d) == dest) continue;
    bool twice = false;
    for (const std::string& s : sources) twice = twice || canonical(s) == canonical(d);
    if (twice) return merge_refused("--merge: " + d + " is named twice");
    locks.push_back(std::make_unique<sweep_folder>(d, text));
    if (!locks.back()->error().empty()) return merge_refused("--merge: " + locks.back()->error());
    sources.push_back(d);
  }
  // Each run in exactly one folder (or already in the target).
  std::vector<std::string> missing, twice;
  std::vector<std::pair<unsigned, std::string>> copies;
  for (unsigned n = 1; n <= plan.size(); ++n) {
    std::vector<std::string> holders;
    for (const std::string& s : sources)
      if (state_of_run(s + "/" + plan.folder(n)) != run_state::unfinished) holders.push_back(s);
    std::string what = "run " + std::to_string(n) + " (" + plan.describe(plan.run(n)) + ")";
    if (holders.size() > 1) twice.push_back(what + " is in " + holders[0] + " and in " + holders[1]);
    else if (holders.size() == 1) copies.emplace_back(n, holders[0]);
    else if (state_of_run(out + "/" + plan.folder(n)) == run_state::unfinished)
      missing.push_back(what + " is finished or failed in none of the folders");
  }
  if (!twice.empty())
    return merge_refused("--merge: " + std::to_string(twice.size()) + " runs are in more than one folder (merge each shard once):" +
                  listed(twice));
  if (!missing.empty())
    return merge_refused("--merge: " + std::to_string(missing.size()) + " of " + std::to_string(plan.size()) +
                  " runs are missing (run their shards again, or to the end):" + listed(missing));

  sweep_folder target(out, text);
  if (!target.error().empty()) return merge_refused("--merge --out " + target.error());
  for (const auto& [n, from] : copies)
    if (std::string e = bring_in(from + "/" + plan.folder(n), out + "/" + plan.folder(n)); !e.empty()) return merge_refused(e);
  std::optional<sweep_identity> id = parse_identity(text, bad);
  try {
    std::string e = write_in_folder(out, "runs.csv", runs_csv(plan, out, id->plots));
    if (e.empty()) e = write_in_folder(out, "failed.csv", failed_csv(plan, out));
    if (!e.empty()) return merge_refused(e);
  } catch (const std::exception& e) {
    return merge_refused(e.what());
  }
  if (!o.quiet)
    std::printf("merged %zu runs from %zu folders into %s\n", copies.size(), sources.size(), out.c_str());
  return 0;
}

}  // namespace vvi
