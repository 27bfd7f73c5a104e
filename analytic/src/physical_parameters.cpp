#include "hm/analytic/physical_parameters.hpp"

#include "hm/analytic/biot_modulus.hpp"
#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

#include <string>
#include <utility>

namespace hm::analytic {

using namespace hm::core;  // require_* and format_value

void PhysicalParameters::validate() const {
  require_positive(E_si, "E");
  require_open(nu, "nu", 0.0, 0.5);
  require_positive(k_si, "k");
  require_positive(k_f_si, "k_f");
  // iota = k_f/k >= 1 (DimensionlessParameters::kMinIota): said in the keys the user wrote.
  if (!(k_f_si >= DimensionlessParameters::kMinIota * k_si))
    throw InputError("k_f = " + format_value(k_f_si) + ", allowed: k_f >= k = " + format_value(k_si) +
                     " (an open crack conducts at least as the rock it cuts)");
  require_positive(mu_si, "mu");
  require_non_negative(q_si, "q");
  require_positive(R_si, "R");
  require_half_open(R_i_si, "R_i", 0.0, R_si);
  require_open(porosity, "porosity", 0.0, 1.0);
  require_positive(K_w_si, "K_w");
  require_closed(b, "b", 0.0, 1.0);
  require_positive(T_u_si, "T_u");
  require_positive(C_u_si, "C_u");
  require_non_negative(mu_i, "mu_i");
  // Eq. 22 gives E/M <= 0 when b is well below the porosity: no physical Biot modulus.
  if (E_over_M_eq22(b, nu, porosity, E_si / K_w_si) <= 0.0)
    throw InputError("b = " + format_value(b) +
                     ", allowed: b large enough that Eq. 22 gives M > 0 (porosity = " + format_value(porosity) + ")");
}

void DimensionlessParameters::validate() const {
  material.validate();
  // Pressures scale with Q (p_h ~ Q ln(1/R_i) / 2 pi): Q = 1e6 is already a borehole pressure of
  // ~3e5 E, beyond any rock; far above it the solvers' numbers overflow.
  require_closed(Q, "Q", 0.0, 1e6);
  if (!(iota >= kMinIota && iota <= kMaxIota))
    throw InputError("iota = " + format_value(iota) + ", allowed: " + format_value(kMinIota) +
                     " <= iota <= " + format_value(kMaxIota));
  require_half_open(R_i, "R_i", 0.0, 1.0);
  for (const auto& [value, name] :
       {std::pair{tensile_strength, "tensile_strength"}, std::pair{compressive_strength, "compressive_strength"}})
    if (!(value > 0.0 && value <= kMaxStrength))
      throw InputError(std::string(name) + " = " + format_value(value) + ", allowed: 0 < " + name +
                       " <= " + format_value(kMaxStrength) +
                       " (over E, a strain at failure; a strength in Pa belongs in a case "
                       "in SI units)");
  require_non_negative(friction, "friction");
  require_positive(E_over_Kw, "E_over_Kw");
}

DimensionlessParameters to_dimensionless(const PhysicalParameters& phys, VolStrain vol_strain) {
  phys.validate();
  DimensionlessParameters d;
  d.material.nu = phys.nu;
  d.material.b = phys.b;
  d.material.E_over_M = E_over_M_eq22(phys.b, phys.nu, phys.porosity, phys.E_si / phys.K_w_si);
  d.material.vol_strain = vol_strain;
  d.Q = phys.mu_si * phys.q_si / (phys.k_si * phys.E_si);
  d.iota = phys.k_f_si / phys.k_si;
  d.R_i = phys.R_i_si / phys.R_si;
  d.tensile_strength = phys.T_u_si / phys.E_si;
  d.compressive_strength = phys.C_u_si / phys.E_si;
  d.friction = phys.mu_i;
  d.E_over_Kw = phys.E_si / phys.K_w_si;
  return d;
}

DimensionlessParameters table1_borehole(double b, double Q, VolStrain vol_strain) {
  DimensionlessParameters d;  // the struct's defaults are Table 1's nu, R_i, strengths, friction
  d.Q = Q;
  d.material.b = b;
  d.material.E_over_M = E_over_M_table1(b, d.material.nu);
  d.material.vol_strain = vol_strain;
  return d;
}

Scales scales_of(const PhysicalParameters& phys) {
  return {phys.R_si, phys.E_si, phys.mu_si * phys.R_si * phys.R_si / (phys.k_si * phys.E_si)};
}

}  // namespace hm::analytic
