#include "hm/core/interrupt.hpp"

#include <csignal>

namespace hm::core {

namespace {

volatile std::sig_atomic_t received = 0;
void (*previous_int)(int) = SIG_DFL;
void (*previous_term)(int) = SIG_DFL;

extern "C" void record_signal(int sig) {
  if (received != 0) {  // asked twice: stop now
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
