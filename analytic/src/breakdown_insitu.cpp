#include "hm/analytic/breakdown_insitu.hpp"

#include "hm/core/validation.hpp"

namespace hm::analytic {

using namespace hm::core;  // require_* and format_value

void BreakdownParameters::validate() const {
  require_positive(T_u, "T_u");
  require_non_negative(p0, "p0");
  require_closed(b, "b", 0.0, 1.0);
  require_open(nu, "nu", 0.0, 0.5);
}

double poroelastic_stress_coefficient(double b, double nu) { return b * (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu)); }

WallBreakdown hubbert_willis_breakdown(const FarFieldStress& far, const BreakdownParameters& m) {
  far.validate();
  m.validate();
  return {3.0 * far.S_h - far.S_H + m.T_u - m.b * m.p0, 0.0};
}

WallBreakdown haimson_fairhurst_breakdown(const FarFieldStress& far, const BreakdownParameters& m) {
  far.validate();
  m.validate();
  const double eta = poroelastic_stress_coefficient(m.b, m.nu);
  // The fluid at the wall both adds b p_w to the effective stress and, by penetrating, takes
  // 2 eta (p_w - p0) off the total hoop stress; 1 + b - 2 eta >= 1, as eta <= b/2.
  return {(3.0 * far.S_h - far.S_H + m.T_u - 2.0 * eta * m.p0) / (1.0 + m.b - 2.0 * eta), 0.0};
}

WallBreakdown annulus_jacketed_breakdown(const FarFieldStress& far, const BreakdownParameters& m, double R_i) {
  m.validate();
  // The hoop stress on the wall is linear in p_w: two evaluations on the S_H axis give it exactly.
  const auto wall_hoop = [&](double p_w) {
    return InSituAnnulus(far, p_w, R_i, m.nu).state(R_i, far.theta_H).sigma_theta;
  };
  const double h0 = wall_hoop(0.0), slope = wall_hoop(1.0) - h0;
  return {(m.T_u - m.b * m.p0 - h0) / slope, 0.0};
}

}  // namespace hm::analytic
