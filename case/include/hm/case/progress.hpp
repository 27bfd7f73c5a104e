#pragma once
/// \file
/// A progress line for long runs, printed at most once per `interval_s` of wall time and at the end,
/// so logs stay short on CI and a person at a terminal sees the run move.
#include <chrono>
#include <ostream>
#include <string>

namespace hm::cases {

class ProgressReporter {
 public:
  ProgressReporter(std::ostream& out, std::string label, double interval_s = 2.0);
  /// Reports model time t of t_end; `extra` is appended (e.g. "breaks 12, iterations 3").
  void update(double t, double t_end, const std::string& extra = "");
  void finish(const std::string& summary);

 private:
  std::ostream& out_;
  std::string label_;
  double interval_s_;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace hm::cases
