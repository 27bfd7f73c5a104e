// What the paper says of its fracture figures: see paper_readings.hpp; the readings themselves are
// the figure specs' (verification/specs/).
#include "paper_readings.hpp"

#include <vector>

#include "figure_specs.hpp"
#include "hm/verification/benchmark.hpp"

namespace hm::verification {

const std::vector<PaperFigure>& paper_result_figures() {
  static const std::vector<PaperFigure> figures = {
      {"7", "Rudnicki's point injection: pressure and displacement, lattice vs closed form"},
      {"8", "the undrained split's Psi: coupling iterations"},
      {"10", "1D model: pressure and displacement"},
      {"11", "1D model: stresses"},
      {"12", "fracture from the borehole, Q = 0.01, iota = 1: pressure and broken beams"},
      {"13", "u_r of Fig. 12's runs against the 1D model"},
      {"14", "fast flow in the fractures, iota = 1e3: pressure and broken beams"},
      {"15", "u_r of Fig. 14's runs against the 1D model"},
      {"16", "high injection rate, Q = 1: pressure and broken beams"},
      {"17", "tight rock, Q = 1, iota = 1e6: pressure and broken beams"},
      {"18", "breakdown pressure against Q for three b"},
      {"19", "lattice-size refinement: pressure and broken beams"},
      {"20", "lattice-size refinement: u_r"},
      {"C2", "Sneddon's pressurised crack: aperture"},
  };
  return figures;
}

std::string PaperReading::fractures_text() const {
  if (fractures == not_stated) return "not stated";
  std::string s = std::to_string(fractures);
  if (reaching_outer == all) return s + ", all at r = 1";
  if (reaching_outer == not_stated) return s;
  return s + ", " + std::to_string(reaching_outer) + " at r = 1";
}

std::string PaperReading::secondary_text() const {
  switch (secondary) {
    case Secondary::none: return "none";
    case Secondary::at_outer_boundary: return "at the outer boundary";
    case Secondary::between_primaries: return "between the primaries";
    case Secondary::not_stated: break;
  }
  return "not stated";
}

PaperReading paper_reading(const std::string& figure_id, double b, long long n_particles) {
  return figure_spec(figure_id).panel(b, n_particles).reading;
}

}  // namespace hm::verification
