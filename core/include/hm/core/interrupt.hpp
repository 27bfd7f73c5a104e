#pragma once
/// \file
/// SIGINT (Ctrl-C) and SIGTERM (a batch system's time limit) as a request to stop: while an
/// InterruptRequest lives, the first such signal is only recorded, so a long run can finish the step
/// it is in and keep what it has done; a second one ends the process at once, as usual.
namespace hm::core {

class InterruptRequest {
 public:
  InterruptRequest();   ///< installs the handlers
  ~InterruptRequest();  ///< restores the previous ones
  InterruptRequest(const InterruptRequest&) = delete;
  InterruptRequest& operator=(const InterruptRequest&) = delete;

  /// The signal received (SIGINT or SIGTERM), 0 while none has arrived.
  int signal() const;
  /// "SIGINT", "SIGTERM" or "" (for messages).
  const char* signal_name() const;
  /// The shell's exit status of a process ended by the signal: 128 + its number (130, 143).
  int exit_code() const { return 128 + signal(); }
};

}  // namespace hm::core
