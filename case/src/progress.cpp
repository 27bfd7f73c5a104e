#include "hm/case/progress.hpp"

#include <cstdio>

namespace hm::cases {

ProgressReporter::ProgressReporter(std::ostream& out, std::string label, double interval_s)
    : out_(out),
      label_(std::move(label)),
      interval_s_(interval_s),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

void ProgressReporter::update(double t, double t_end, const std::string& extra) {
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - last_).count() < interval_s_) return;
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double fraction = t_end > 0 ? t / t_end : 1.0;
  char line[200];
  // Time steps grow, so the model-time fraction overestimates the remaining wall time: call it a bound.
  std::snprintf(line, sizeof line, "[%s] t* = %.4g / %.4g (%3.0f%%), %.1f s elapsed", label_.c_str(), t, t_end,
                100 * fraction, elapsed);
  out_ << line << (extra.empty() ? "" : ", " + extra) << std::endl;
}

void ProgressReporter::finish(const std::string& summary) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  char line[64];
  std::snprintf(line, sizeof line, " (%.2f s)", elapsed);
  out_ << "[" << label_ << "] " << summary << line << std::endl;
}

}  // namespace hm::cases
