#pragma once
/// \file
/// Dimensionless poroelastic material parameters shared by every model (paper Section 2.4).
/// Units: lengths / R, stresses and pressures / E (pressure as deviation from p0), time / t_s.
/// Sign convention, once for the whole toolkit: tension positive, pressure positive when dilative.
#include <array>
#include <string>
#include <string_view>

#include "hm/analytic/biot_modulus.hpp"
#include "hm/core/enum_names.hpp"

namespace hm::analytic {

/// How the fluid equation (Eq. 2/14) measures volumetric strain in radial plane strain.
/// plane_strain: eps_v = eps_r + eps_theta (what plane-strain kinematics give).
/// appendix_a:   eps_v = (eps_r + eps_theta)/3, as printed in the paper's Eq. A5 (see docs/errata.md).
enum class VolStrain { plane_strain, appendix_a };
constexpr auto enum_names(VolStrain) {
  return core::enum_table<VolStrain>(
      {{VolStrain::plane_strain, "plane-strain"}, {VolStrain::appendix_a, "appendix-a"}});
}

/// Factor multiplying (eps_r + eps_theta) in the fluid equation: 1 or 1/3.
double vol_strain_factor(VolStrain v);

/// Dimensionless material of the poroelastic continuum (E = 1 by scaling).
struct PoroelasticParameters {
  /// nu, drained Poisson ratio (Table 1: 0.25). Allowed: 0 < nu < 0.5.
  double nu = 0.25;
  /// b, Biot coefficient (Eq. 1; Table 1: 0.2-0.8). Allowed: 0 <= b <= 1.
  double b = 0.5;
  /// E/M, Young modulus over Biot modulus (Eq. 22). Allowed: > 0.
  /// Default: Eq. 22 with Table 1's porosity, K_w, E at the default b and nu.
  double E_over_M = E_over_M_table1(0.5, 0.25);
  /// Volumetric-strain measure in the fluid equation; our default is the physically right one.
  VolStrain vol_strain = VolStrain::plane_strain;

  /// Throws hm::InputError "field = value, allowed: rule" for the first violated rule.
  void validate() const;
};

/// (1+nu)(1-2nu)/(1-nu): the oedometric (constrained) compliance 1/(lambda+2G) for E = 1,
/// the factor on the right of Eq. A1/A3 divided by b.
double oedometric_compliance(double nu);

/// Storage coefficient S of the radial plane-strain diffusion equation S dp/dt = lap p obtained by
/// eliminating eps_v with the radial equilibrium (docs/rudnicki.md):
/// S = E/M + f b^2 (1+nu)(1-2nu)/(1-nu), f = vol_strain_factor. Diffusivity c = 1/S.
/// Valid where eps_r+eps_theta = b (1+nu)(1-2nu)/(1-nu) p, i.e. an unbounded plane (no outer boundary).
double storage_coefficient(const PoroelasticParameters& m);

}  // namespace hm::analytic
