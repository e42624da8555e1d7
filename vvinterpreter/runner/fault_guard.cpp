#include "runner/fault_guard.hpp"

#include <cxxabi.h>
#include <execinfo.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <sys/syscall.h>
#include <time.h>
#include <ucontext.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <typeinfo>

#include "runner/report_words.hpp"
#include "runner/throw_points.hpp"

namespace vvi::fault_guard {

namespace words = report_words;

namespace {

// Everything the signal handler touches is static: it may not allocate.
int report = -1;
char activity[128] = "";  // room for an action's name
unsigned activity_step = 0;
// The thread of the announced activity (0: none): the one a sample is of.
volatile pid_t activity_thread = 0;
char exception_text[512] = "";
// Where the uncaught exception was thrown, when the host kept it: reported
// as the crash's stack (on_terminate).
void* thrown_frames[64];
std::size_t thrown_count = 0;
volatile sig_atomic_t handling = 0;
char maps_buffer[1 << 18];
char sample_maps_buffer[1 << 18];  // a sample may run while another thread crashes
volatile sig_atomic_t samples_sent = 0;
volatile sig_atomic_t last_sample = 0;
volatile sig_atomic_t sample_number = 0;  // of the request being answered

// The temporaries being written (runner/output_file.hpp): unlinked on a
// termination signal.
constexpr int max_writing = 4;
char writing[max_writing][PATH_MAX];

pid_t thread_id() { return static_cast<pid_t>(syscall(SYS_gettid)); }

constexpr int fatal_signals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};

const char* signal_name(int sig) {
  switch (sig) {
    case SIGSEGV: return "SIGSEGV";
    case SIGBUS: return "SIGBUS";
    case SIGFPE: return "SIGFPE";
    case SIGILL: return "SIGILL";
    case SIGABRT: return "SIGABRT";
    default: return "a signal";
  }
}

// ---- async-signal-safe output ----
void put_bytes(int fd, const char* s, std::size_t n) {
  while (n > 0) {
    ssize_t w = write(fd, s, n);
    if (w <= 0) return;
    s += w, n -= static_cast<std::size_t>(w);
  }
}

// One whole line per write: lines of other threads never cut into it.
class line {
 public:
  line& operator<<(const char* s) {
    while (*s && n_ < sizeof buf_ - 1) buf_[n_++] = *s++;
    return *this;
  }
  line& number(unsigned long long v, unsigned base) {
    char digits[24];
    int k = 0;
    do digits[k++] = "0123456789abcdef"[v % base]; while ((v /= base) && k < 24);
    while (k > 0 && n_ < sizeof buf_ - 1) buf_[n_++] = digits[--k];
    return *this;
  }
  void send() {
    buf_[n_++] = '\n';
    if (report >= 0) put_bytes(report, buf_, n_);
    n_ = 0;
  }

 private:
  char buf_[640];
  std::size_t n_ = 0;
};

// What the model printed but stdio still holds (a pipe is fully buffered):
// written straight from glibc's buffer, without the stdio lock the crash
// may have left held.
void flush_unlocked(FILE* f) {
  if (f->_IO_write_ptr > f->_IO_write_base) {
    put_bytes(fileno(f), f->_IO_write_base, static_cast<std::size_t>(f->_IO_write_ptr - f->_IO_write_base));
    f->_IO_write_ptr = f->_IO_write_base;
  }
}

template <std::size_t N>
void send_maps(char (&buffer)[N]) {
  int fd = open("/proc/self/maps", O_RDONLY | O_CLOEXEC);
  if (fd < 0) return;
  std::size_t n = 0;
  ssize_t r;
  while (n < N - 1 && (r = read(fd, buffer + n, N - 1 - n)) > 0) n += static_cast<std::size_t>(r);
  close(fd);
  buffer[n] = '\0';
  // Only mappings of files: the supervisor looks up code addresses.
  for (char* at = buffer; *at;) {
    char* eol = std::strchr(at, '\n');
    if (eol) *eol = '\0';
    if (std::strchr(at, '/')) {
      line l;
      (l << words::map << " " << at).send();
    }
    at = eol ? eol + 1 : at + std::strlen(at);
  }
}

std::uintptr_t fault_pc(void* context) {
  auto* uc = static_cast<ucontext_t*>(context);
#if defined(__x86_64__)
  return static_cast<std::uintptr_t>(uc->uc_mcontext.gregs[REG_RIP]);
#elif defined(__aarch64__)
  return static_cast<std::uintptr_t>(uc->uc_mcontext.pc);
#else
  (void)uc;
  return 0;
#endif
}

// Where the interrupted code returns to, when it has not yet made a frame
// of its own: a linker's call stub (PLT), which has no unwind table, or a
// call through a null function pointer. 0 where unknown.
std::uintptr_t return_address_at_entry(void* context) {
  auto* uc = static_cast<ucontext_t*>(context);
#if defined(__x86_64__)
  return *reinterpret_cast<const std::uintptr_t*>(uc->uc_mcontext.gregs[REG_RSP]);
#elif defined(__aarch64__)
  return static_cast<std::uintptr_t>(uc->uc_mcontext.regs[30]);
#else
  (void)uc;
  return 0;
#endif
}

// The stack as return addresses. The unwinder stops at an instruction it has
// no table for (a PLT stub, address 0): the caller is then added from the
// interrupted registers, so the report still names the model's line.
// Whether the stack still holds the frames just outside the throw (the
// kept record's first ones past the host's own __cxa_throw).
bool reaches_throw(void* const* frames, int n) {
  for (std::size_t k = 1; k < thrown_count && k <= 3; ++k)
    for (int i = 0; i < n; ++i)
      if (frames[i] == thrown_frames[k]) return true;
  return false;
}

void send_frames(void* context = nullptr) {
  void* frames[65];
  int n = backtrace(frames, 64);
  if (exception_text[0] && thrown_count > 1 && !reaches_throw(frames, n)) {
    // The stack no longer reaches the throw (on_terminate): its record does.
    n = 0;
    for (std::size_t i = 0; i < thrown_count; ++i) frames[n++] = thrown_frames[i];
    context = nullptr;  // abort()'s pc is not the throw's
  }
  if (context) {
    std::uintptr_t pc = fault_pc(context);
    bool stopped_at_pc = n > 0 && reinterpret_cast<std::uintptr_t>(frames[n - 1]) == pc;
    if (pc == 0 || stopped_at_pc) {
      if (std::uintptr_t caller = return_address_at_entry(context)) frames[n++] = reinterpret_cast<void*>(caller);
    }
  }
  line l;
  for (int i = 0; i < n; ++i) (l << words::frame << " ").number(reinterpret_cast<std::uintptr_t>(frames[i]), 16).send();
}

void on_fatal(int sig, siginfo_t*, void* context) {
  if (handling) {  // a fault while reporting one: just die
    signal(sig, SIG_DFL);
    raise(sig);
    return;
  }
  handling = 1;
  flush_unlocked(stdout);
  flush_unlocked(stderr);
  if (report >= 0) {
    line l;
    (l << words::crash << " " << signal_name(sig)).send();
    if (activity[0]) (l << words::activity << " " << activity << " ").number(activity_step, 10).send();
    if (exception_text[0]) (l << words::exception << " " << exception_text).send();
    (l << words::pc << " ").number(fault_pc(context), 16).send();
    send_frames(context);
    send_maps(maps_buffer);
    (l << words::end).send();
  }
  signal(sig, SIG_DFL);  // the signal is blocked here: it kills us on return
  raise(sig);
}

// The supervisor asks where the running block is (a long step, a time-out,
// a stop). Any thread may receive the signal: it goes on to the one that
// runs the announced activity, which reports its own stack and runs on.
void on_sample(int sig, siginfo_t* info, void* context) {
  int saved_errno = errno;
  // The last sample before the supervisor ends the process: what the model
  // printed is written out first, as on a crash.
  if (info && info->si_code == SI_QUEUE) {  // the request; forwarded without it (tgkill)
    sample_number = info->si_value.sival_int / 2;
    if (info->si_value.sival_int % 2 == 1) last_sample = 1;
  }
  pid_t target = activity_thread;
  if (target != 0 && target != thread_id()) {
    syscall(SYS_tgkill, getpid(), target, sig);
  } else if (!handling && report >= 0) {
    if (last_sample) {
      flush_unlocked(stdout);
      flush_unlocked(stderr);
    }
    line l;
    (l << words::sample << " " << (target ? words::running : words::idle) << " ").number(static_cast<unsigned>(sample_number), 10).send();
    if (target) {
      (l << words::pc << " ").number(fault_pc(context), 16).send();
      send_frames(context);
      send_maps(sample_maps_buffer);
    }
    (l << words::end).send();
    samples_sent = samples_sent + 1;
    // The supervisor ends the process now: the model must not go on (and
    // finish, or print) in the meantime.
    if (last_sample)
      for (;;) pause();
  }
  errno = saved_errno;
}

// exit() inside a block ends the run before its end: tell the supervisor
// where it was called (_exit cannot be seen; the supervisor still knows the
// block from the protocol). False outside a block.
bool report_exit_call() {
  if (activity_thread == 0 || report < 0) return false;
  flush_unlocked(stdout);
  line l;
  (l << words::sample << " " << words::exit_call).send();
  send_frames();
  send_maps(sample_maps_buffer);
  (l << words::end).send();
  return true;
}

// Then the process ends at once, with the model's status: the exit
// handlers registered before this one (the libraries' destructors, the GL
// driver's among them) would run on the model's thread while the window's
// thread still draws, and crash it there.
void on_exit_call(int status, void*) {
  if (report_exit_call()) {
    flush_unlocked(stderr);
    _exit(status);
  }
}

void on_quick_exit_call() { report_exit_call(); }  // quick_exit runs no destructors

// A termination signal (the supervisor went, Ctrl-C) ends the process as
// it would have, without leaving a half-written file behind.
void on_termination(int sig) {
  for (auto& temporary : writing)
    if (temporary[0]) unlink(temporary);
  signal(sig, SIG_DFL);
  raise(sig);
}

void on_terminate() {
  // Keep what the exception said; abort() then reports it with the stack
  // where it was thrown. g++ calls terminate from the throw, nothing
  // unwound; clang first unwinds to the noexcept function the exception
  // would leave, so the host's record of the throw is the stack to report.
  if (std::exception_ptr e = std::current_exception()) {
    thrown_count = vv_host_throw_frames(thrown_frames, sizeof thrown_frames / sizeof thrown_frames[0]);
    try {
      std::rethrow_exception(e);
    } catch (const std::exception& x) {
      std::snprintf(exception_text, sizeof exception_text, "%s", x.what());
    } catch (const std::string& text) {
      std::snprintf(exception_text, sizeof exception_text, "an exception of type std::string: %s", text.c_str());
    } catch (const char* text) {
      std::snprintf(exception_text, sizeof exception_text, "an exception of type const char*: %s",
                    text ? text : "(null)");
    } catch (...) {
      const std::type_info* type = abi::__cxa_current_exception_type();
      int status = 0;
      char* name = type ? abi::__cxa_demangle(type->name(), nullptr, nullptr, &status) : nullptr;
      std::snprintf(exception_text, sizeof exception_text, "an exception of type %s",
                    name ? name : type ? type->name() : "unknown");
      std::free(name);
    }
  } else {
    std::snprintf(exception_text, sizeof exception_text, "std::terminate was called");
  }
  for (char* c = exception_text; *c; ++c)
    if (*c == '\n') *c = ' ';
  std::abort();
}

void copy_text(char* to, std::size_t size, const char* from) {
  std::size_t i = 0;
  for (; from[i] && i + 1 < size; ++i) to[i] = from[i];
  to[i] = '\0';
}

}  // namespace

void prepare_thread() {
  static thread_local void* stack = nullptr;
  if (stack) return;
  // A sanitizer runtime gives each thread an alternate stack of its own
  // (and frees it at thread exit): keep it.
  stack_t current{};
  if (sigaltstack(nullptr, &current) == 0 && !(current.ss_flags & SS_DISABLE) && current.ss_size >= (1 << 14)) return;
  std::size_t size = 1 << 16;
  stack = std::malloc(size);  // lives as long as the thread (and past it: harmless)
  stack_t ss{};
  ss.ss_sp = stack;
  ss.ss_size = size;
  sigaltstack(&ss, nullptr);
}

void install(int report_fd) {
  report = report_fd;
  void* warm[2];
  backtrace(warm, 2);  // loads the unwinder now, not inside a handler
  prepare_thread();
  struct sigaction sa {};
  sa.sa_sigaction = on_fatal;
  sa.sa_flags = SA_SIGINFO | SA_ONSTACK;
  sigemptyset(&sa.sa_mask);
  for (int sig : fatal_signals) sigaction(sig, &sa, nullptr);
  std::set_terminate(on_terminate);
  if (report < 0) return;
  struct sigaction sample {};
  sample.sa_sigaction = on_sample;
  sample.sa_flags = SA_SIGINFO | SA_ONSTACK | SA_RESTART;  // the model's system calls go on
  sigemptyset(&sample.sa_mask);
  sigaction(sample_signal(), &sample, nullptr);
  struct sigaction term {};
  term.sa_handler = on_termination;
  sigemptyset(&term.sa_mask);
  for (int sig : {SIGTERM, SIGINT, SIGHUP}) sigaction(sig, &term, nullptr);
  on_exit(on_exit_call, nullptr);
  std::at_quick_exit(on_quick_exit_call);
}

void begin(const char* what, unsigned step, bool announce) {
  copy_text(activity, sizeof activity, what);
  activity_step = step;
  if (announce && report >= 0) {
    activity_thread = thread_id();
    line l;
    (l << words::begin << " " << what << " ").number(step, 10).send();
    (l << words::thread << " ").number(static_cast<unsigned long long>(activity_thread), 10).send();
  }
}

void finish(bool announce) {
  if (announce && report >= 0) {
    activity_thread = 0;
    line l;
    (l << words::done << " " << activity << " ").number(activity_step, 10).send();
  }
  activity[0] = '\0';
  activity_step = 0;
}

int sample_signal() { return SIGRTMIN + 3; }

bool report_activity_stack(double max_seconds) {
  pid_t target = activity_thread;
  if (target == 0 || report < 0) return false;
  sig_atomic_t before = samples_sent;
  if (syscall(SYS_tgkill, getpid(), target, sample_signal()) != 0) return false;
  const timespec pause{0, 1000000};
  for (double waited = 0; waited < max_seconds; waited += 0.001) {
    if (samples_sent != before) return true;
    nanosleep(&pause, nullptr);
  }
  return samples_sent != before;
}

void note_writing(const std::string& temporary, const std::string& target) {
  for (auto& slot : writing)
    if (!slot[0]) {
      // The first byte last: a signal handler sees the whole path or none.
      if (!temporary.empty() && temporary.size() < PATH_MAX) {
        copy_text(slot + 1, PATH_MAX - 1, temporary.c_str() + 1);
        slot[0] = temporary[0];
      }
      break;
    }
  send(std::string(words::writing) + " " + temporary + "\t" + target);
}

void note_writing_in(const std::string& folder) { send(std::string(words::writing_in) + " " + folder); }

void note_written(const std::string& temporary) {
  for (auto& slot : writing)
    if (temporary == slot) slot[0] = '\0';
  send(std::string(words::written) + " " + temporary);
}

void note_module(const std::string& loaded, const std::string& original) {
  send(std::string(words::module) + " " + loaded + "\t" + original);
}

void send(const std::string& text) {
  if (report < 0) return;
  std::string l = text + "\n";
  put_bytes(report, l.data(), l.size());
}

int report_fd() { return report; }

}  // namespace vvi::fault_guard
