#pragma once
// Signals blocked in this thread for a scope, to be taken with sigtimedwait: no handler, and no
// signal lost between checking for one and waiting for the next. The local batch blocks SIGINT,
// SIGTERM and SIGCHLD while its runs go; a Slurm submission SIGINT and SIGTERM while sbatch runs.
#include <signal.h>

#include <initializer_list>

namespace kestrel::cli {

class BlockedSignals {
 public:
  explicit BlockedSignals(std::initializer_list<int> signals) {
    sigemptyset(&set_);
    for (const int s : signals) sigaddset(&set_, s);
    pthread_sigmask(SIG_BLOCK, &set_, &old_);
    if (sigismember(&set_, SIGCHLD) == 1) {
      // An ignored SIGCHLD would reap the children behind our back.
      struct sigaction dfl {};
      dfl.sa_handler = SIG_DFL;
      sigaction(SIGCHLD, &dfl, &old_chld_);
      restore_chld_ = true;
    }
  }
  ~BlockedSignals() {
    if (restore_chld_) sigaction(SIGCHLD, &old_chld_, nullptr);
    pthread_sigmask(SIG_SETMASK, &old_, nullptr);
  }
  BlockedSignals(const BlockedSignals&) = delete;
  BlockedSignals& operator=(const BlockedSignals&) = delete;

  const sigset_t& set() const { return set_; }
  const sigset_t& before() const { return old_; }  ///< the mask children get

 private:
  sigset_t set_{}, old_{};
  struct sigaction old_chld_ {};
  bool restore_chld_ = false;
};

}  // namespace kestrel::cli
