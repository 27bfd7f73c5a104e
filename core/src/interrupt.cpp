#include "hm/core/interrupt.hpp"

#include <unistd.h>

#include <csignal>

namespace hm::core {

namespace {

volatile std::sig_atomic_t received = 0;
void (*previous_int)(int) = SIG_DFL;
void (*previous_term)(int) = SIG_DFL;

extern "C" void record_signal(int sig) {
  if (received != 0) {  // asked twice: stop now, and say what is left (write(2): safe in a handler)
    constexpr char said[] =
        "hmlattice: interrupted again: ended at once; what was written so far stays in the hidden "
        ".hmlattice-staging-* folder beside the result folder (the next command there names it; a run "
        "continues from its last checkpoint with hmlattice run --resume <that folder>)\n";
    [[maybe_unused]] const ssize_t n = ::write(STDERR_FILENO, said, sizeof said - 1);
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  received = sig;
}

}  // namespace

InterruptRequest::InterruptRequest() {
  received = 0;
  previous_int = std::signal(SIGINT, record_signal);
  previous_term = std::signal(SIGTERM, record_signal);
}

InterruptRequest::~InterruptRequest() {
  std::signal(SIGINT, previous_int);
  std::signal(SIGTERM, previous_term);
}

int InterruptRequest::signal() const { return received; }

const char* InterruptRequest::signal_name() const {
  return received == SIGINT ? "SIGINT" : received == SIGTERM ? "SIGTERM" : "";
}

}  // namespace hm::core
