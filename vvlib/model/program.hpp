// One translated program's state: the model object. It holds the algebra's
// context, the proxy, the file-object registry and what the model keeps for
// its host, so that nothing of a model is process-global: a generated
// program defines one, as its first global,
//
//   static vv::model::program<vv_traits> vv_model("/folder/of/the.vvp");
//
// and every entry point runs the program's code through vv_model.run().
//
// It is the first global so that it outlives the program's globals and the
// file objects among them find its registry (model/file_registry.hpp): it
// opens the registry when it is made, and globals_made(), the program's
// last global, closes it. The context is made on first use, because the
// program's vertex type is only complete once its vertex block has been
// read, after this object.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <utility>

#include <vv/context.hpp>
#include <vv/detail/thread_stack.hpp>

#include "abi.hpp"
#include "file_registry.hpp"
#include "guarded.hpp"
#include "proxy.hpp"

namespace vv::model {

template <class Tr>
class program {
 public:
  //! source_dir: where the program was translated from; relative file
  //! names resolve against it until the host names a model folder.
  explicit program(std::string source_dir) : source_dir_(std::move(source_dir)), previous_(running_registry()) {
    files_.set_base_dir(source_dir_);
    running_registry() = &files_;
  }
  program(const program&) = delete;
  program& operator=(const program&) = delete;

  //! Called once the program's globals are made: from now on, file
  //! objects join this model's registry only while its code runs.
  void globals_made() noexcept { running_registry() = previous_; }

  context<Tr>& ctx() {
    if (!ctx_) ctx_ = context_ptr(new context<Tr>(), [](context<Tr>* c) { delete c; });
    return *ctx_;
  }
  vv::proxy& host() noexcept { return proxy_; }
  file_registry& files() noexcept { return files_; }
  exchange& host_exchange() noexcept { return exchange_; }

  //! Runs the program's code for the host: file objects made meanwhile
  //! join this model; NULL, or the error (model/guarded.hpp). The code
  //! runs as a block (context::block_scope): handles on its stack hold no
  //! count, and the collector runs, if due, once it has returned.
  template <class Fn>
  const char* run(Fn&& fn) noexcept {
    registry_scope scope(files_);
    if (!ctx_) return guarded(exchange_, fn);  // no handle to count yet
    return run_block(fn);
  }

  // Not inlined: the block's handles are in this frame or below it, the
  // caller's (which may hold counted handles) above.
  template <class Fn>
  [[gnu::noinline]] const char* run_block(Fn& fn) noexcept {
    const char* error;
    {
      typename context<Tr>::block_scope block(*ctx_, stack_.low(), __builtin_frame_address(0));
      error = guarded(exchange_, fn);
    }
    return error ? error : guarded(exchange_, [this] { ctx_->collect_if_due(); });
  }

  //! vv_plugin::configure.
  void configure(const vv_plugin_settings& s) {
    const std::string base = s.model_dir && *s.model_dir ? s.model_dir : source_dir_;
    files_.set_base_dir(base);
    context<Tr>& c = ctx();
    c.base_dir = base;
    c.seed(s.seed);
    c.strict_old_state = s.strict_old_state != 0;
    c.strict_parallel = s.strict_old_state != 0;  // --strict: both checks
    c.threads = s.threads;
    c.track_edits(s.check != 0);
    // Programs written for vv 1.1 draw from the C library's generators:
    // seed them too, so every run with the same seed is the same.
    std::srand(static_cast<unsigned>(s.seed));
    srand48(static_cast<long>(s.seed));
  }

  //! The host's "reread files": the registered objects and those in the
  //! proxy's lists, each once (model/file_registry.hpp).
  void reread_files() {
    files_.reread({&proxy_.materials, &proxy_.palettes, &proxy_.functions, &proxy_.contours});
  }

 private:
  // Declared first, destroyed last: the file objects in the context's
  // vertices and in the program's globals leave it before it goes.
  file_registry files_;
  std::string source_dir_;
  file_registry* previous_;
  vv::proxy proxy_;
  exchange exchange_;
  detail::thread_stack_cache stack_;  // of the thread the blocks run on
  // Deleted through the function given when it was made: this class is
  // complete before Tr is.
  using context_ptr = std::unique_ptr<context<Tr>, void (*)(context<Tr>*)>;
  context_ptr ctx_{nullptr, nullptr};
};

}  // namespace vv::model
