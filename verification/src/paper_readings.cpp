// What the paper says of its fracture figures: see paper_readings.hpp.
#include "paper_readings.hpp"

#include <stdexcept>
#include <vector>

#include "hm/verification/benchmark.hpp"

namespace hm::verification {

namespace {

using Secondary = PaperReading::Secondary;
using Sign = PaperReading::FracturePressureSign;

// Section 4: "In the final state, when fractures reach the boundary of the domain, ... a negative
// pressure in most fractures far from the borehole independent of Q and iota".
constexpr Sign final_state_sign = Sign::negative_at_last_time;

PaperReading fig12(double b) {
  return {.figure = "Fig. 12", .fractures = b < 0.5 ? 3 : 7, .reaching_outer = PaperReading::all,
          // Section 3.3: the secondary fractures of Q = 1 were "not observed in the low Q case".
          .secondary = Secondary::none, .pressure = Sign::negative_at_every_time,
          .quote = b < 0.5 ? "3 nearly equidistant fractures for b = 0.2, growing until reaching the domain boundary"
                           : "7 fractures for b = 0.8, growing until reaching the domain boundary"};
}

PaperReading fig14(double b) {
  return {.figure = "Fig. 14", .fractures = b < 0.5 ? 2 : 3, .reaching_outer = PaperReading::all,
          .secondary = Secondary::none, .pressure = final_state_sign, .borehole_pressure_drops = true,
          .quote = b < 0.5 ? "B: the borehole pressure has dropped significantly; D: both fractures have reached the "
                             "boundary; the deformation is limited by a negative pressure in the fractures"
                           : "E: 2 hardly visible fractures; G: a third fracture is initiated; H: all 3 fractures "
                             "have reached the boundary, and the pressure is reduced"};
}

PaperReading fig16(double b) {
  if (b < 0.5)
    return {.figure = "Fig. 16", .fractures = 4, .reaching_outer = 1, .secondary = Secondary::at_outer_boundary,
            .pressure = Sign::negative_at_every_time, .borehole_pressure_drops = true,
            .quote = "A: three radial fractures, open too rapidly to become fluid filled (negative pressure); B: four, "
                     "secondary fractures initiate at the domain boundary; D: one reaches the boundary, the borehole "
                     "pressure drops"};
  return {.figure = "Fig. 16", .fractures = 7, .reaching_outer = 0, .secondary = Secondary::between_primaries,
          .pressure = Sign::negative_at_every_time, .backflow_into_domain = true,
          .quote = "E: seven radial fractures; F-G: secondary fractures between the primaries; H: the primaries almost "
                   "connected to the boundary, several secondary ones are, causing a backflow of fluid into the domain"};
}

PaperReading fig17(double b) {
  return {.figure = "Fig. 17", .fractures = b < 0.5 ? 3 : 2, .reaching_outer = PaperReading::all,
          .pressure = final_state_sign, .backflow_into_borehole = true, .borehole_pressure_drops = true,
          .quote = b < 0.5 ? "A: a single radial fracture; C: a third; D: all 3 connected to the boundary, fluid flows "
                             "back into the borehole"
                           : "E: two radial fractures; G: they reach the boundary; H: the borehole pressure is "
                             "significantly reduced, backflow into the borehole"};
}

PaperReading fig19(long long n_particles) {
  // Section 3.6 gives the coarsest lattice (684) 2 fractures and every finer one 4.
  return {.figure = "Fig. 19", .fractures = n_particles < 1000 ? 2 : 4,
          .quote = "only 2 fractures at 684 particles, 4 at every higher resolution, of similar length, with a similar "
                   "maximum pressure"};
}

}  // namespace

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

DisplacementReading fig15_reading(double b) {
  // Both panels: "no fractures, DEM data fit 1D FDM data" at t* = 2.3e-3 and 4.5e-3; then b = 0.2 "the
  // displacement increases at most radial positions", b = 0.8 "the displacement is reduced at all".
  return {.last_unbroken_t = 4.5e-3, .above_after = b < 0.5};
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
  if (figure_id == "fig12") return fig12(b);
  if (figure_id == "fig14") return fig14(b);
  if (figure_id == "fig16") return fig16(b);
  if (figure_id == "fig17") return fig17(b);
  if (figure_id == "fig19") return fig19(n_particles);
  throw std::logic_error("paper_reading: no reading of " + figure_id);
}

}  // namespace hm::verification
