#include "viewer/file_events.hpp"

#include <poll.h>
#include <sys/eventfd.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>

namespace vvi {

namespace {

// A file saved in place (closed after writing), renamed into place, or
// removed. Not its creation or each write: a look then could find it half
// written.
constexpr std::uint32_t saved_mask = IN_CLOSE_WRITE | IN_MOVED_TO | IN_DELETE | IN_MOVED_FROM;

}  // namespace

file_events::file_events() {
  inotify_ = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  stop_ = eventfd(0, EFD_CLOEXEC);
  if (inotify_ >= 0 && stop_ >= 0) listener_ = std::thread([this] { listen(); });
}

file_events::~file_events() {
  if (listener_.joinable()) {
    std::uint64_t one = 1;
    if (write(stop_, &one, sizeof one) == sizeof one) listener_.join();
    else listener_.detach();  // cannot happen with an eventfd; never block the window's close
  }
  if (inotify_ >= 0) close(inotify_);
  if (stop_ >= 0) close(stop_);
}

void file_events::watch(const std::vector<std::string>& paths) {
  if (inotify_ < 0) return;
  namespace fs = std::filesystem;
  std::set<std::pair<std::string, std::string>> files;
  std::set<std::string> folders;
  for (const std::string& p : paths) {
    fs::path path = fs::absolute(p).lexically_normal();
    files.emplace(path.parent_path().string(), path.filename().string());
    folders.insert(path.parent_path().string());
  }
  std::lock_guard<std::mutex> lock(m_);
  for (auto it = folders_.begin(); it != folders_.end();) {
    if (folders.count(it->second)) {
      folders.erase(it->second);  // watched already
      ++it;
    } else {
      inotify_rm_watch(inotify_, it->first);
      it = folders_.erase(it);
    }
  }
  for (const std::string& folder : folders) {
    int wd = inotify_add_watch(inotify_, folder.c_str(), saved_mask | IN_ONLYDIR);
    if (wd >= 0) folders_[wd] = folder;
  }
  files_ = std::move(files);
}

void file_events::listen() {
  // Aligned as inotify_event is: the kernel writes whole events into it.
  alignas(inotify_event) char buffer[16 * 1024];
  for (;;) {
    pollfd fds[2] = {{inotify_, POLLIN, 0}, {stop_, POLLIN, 0}};
    if (poll(fds, 2, -1) < 0) continue;  // a signal
    if (fds[1].revents) return;
    ssize_t got = read(inotify_, buffer, sizeof buffer);
    if (got <= 0) continue;
    int saves = 0;
    {
      std::lock_guard<std::mutex> lock(m_);
      for (ssize_t at = 0; at < got;) {
        const auto* e = reinterpret_cast<const inotify_event*>(buffer + at);
        at += static_cast<ssize_t>(sizeof(inotify_event) + e->len);
        auto folder = folders_.find(e->wd);
        if (folder != folders_.end() && e->len > 0) saves += static_cast<int>(files_.count({folder->second, e->name}));
      }
    }
    // A wake for each: the window's loop takes them as one.
    for (int i = 0; i < saves; ++i) {
      saved_since_ = true;
      saved_();
    }
  }
}

}  // namespace vvi
