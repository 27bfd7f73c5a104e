#pragma once
// What the paper says of its fracture figures (Sections 3.3-3.6, the captions of Figs. 12-20), one
// reading per figure and Biot coefficient, for the tables that show our runs beside it. These are the
// paper's words turned into numbers where it gives numbers; nothing here is a tolerance.
#include <string>

namespace hm::verification {

struct PaperReading {
  static constexpr int all = -1, not_stated = -2;
  std::string figure;               ///< "Fig. 12"
  int fractures = not_stated;       ///< radial fractures at the last snapshot
  int reaching_outer = not_stated;  ///< how many of them reach r = 1 then: a count, all or not_stated
  enum class Secondary { not_stated, none, at_outer_boundary, between_primaries } secondary = Secondary::not_stated;
  enum class FracturePressureSign {
    not_stated,
    negative_at_every_time,
    negative_at_last_time
  } pressure = FracturePressureSign::not_stated;
  bool backflow_into_borehole = false;   ///< "fluid flows back into the borehole"
  bool backflow_into_domain = false;     ///< "a backflow of fluid into the domain" (through r = 1)
  bool borehole_pressure_drops = false;  ///< p_h falls below its peak once fractures drain it
  std::string quote;                     ///< the paper's words, shortened

  /// "3, all at r = 1": the count and where the fractures end.
  std::string fractures_text() const;
  std::string secondary_text() const;
};

/// The reading of figure `figure_id` ("fig12") for the panel with Biot coefficient b at `n_particles`,
/// from its spec file (verification/specs/<figure_id>.toml).
PaperReading paper_reading(const std::string& figure_id, double b, long long n_particles = 0);

}  // namespace hm::verification
