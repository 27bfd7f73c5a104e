#pragma once
/// \file
/// Table 1's physical (SI) inputs and their one conversion to the paper's dimensionless units.
#include "hm/analytic/poroelastic_parameters.hpp"

namespace hm::analytic {

/// Physical inputs (Table 1). SI units; every field is suffixed _si where it carries a unit.
struct PhysicalParameters {
  double E_si = 1e10;      ///< E, Young modulus [Pa] > 0
  double nu = 0.25;        ///< nu, Poisson ratio, 0 < nu < 0.5
  double k_si = 1e-14;     ///< k, permeability [m^2] > 0
  double k_f_si = 1e-14;   ///< k_f, permeability in fractures [m^2] > 0
  double mu_si = 1e-3;     ///< mu, fluid viscosity [Pa s] > 0
  double q_si = 1e-3;      ///< q, injection rate per unit axial length [m^2/s] >= 0
  double R_si = 1.0;       ///< R, domain outer radius [m] > 0
  double R_i_si = 0.138;   ///< R_i, borehole radius [m], 0 <= R_i < R
  double porosity = 1e-3;  ///< Phi, porosity, 0 < Phi < 1 and Phi <= b
  double K_w_si = 2.2e9;   ///< K_w, fluid bulk modulus [Pa] > 0
  double b = 0.5;          ///< b, Biot coefficient, 0 <= b <= 1
  double T_u_si = 2e6;     ///< T_u, uniaxial tensile strength [Pa] > 0
  double C_u_si = 3.33e7;  ///< C_u, uniaxial compressive strength [Pa] > 0
  double mu_i = 0.9;       ///< mu_i, internal friction coefficient >= 0

  /// Throws hm::InputError "field = value, allowed: rule".
  void validate() const;
};

/// The dimensionless parameter set every model reads (Section 2.4).
struct DimensionlessParameters {
  PoroelasticParameters material;  ///< nu, b, E/M, vol_strain
  /// Q = mu q/(k E), dimensionless injection rate (Eq. 14). Allowed: 0 <= Q <= 1e6.
  double Q = 0.01;
  /// iota = k_f/k, fracture permeability enhancement (Section 2.2). Allowed: kMinIota <= iota <= kMaxIota.
  double iota = 1.0;
  /// A broken beam is an open crack: it conducts at least as the rock it cuts. Below, the cracks seal
  /// the rock into cells whose opening draws suction, and the lattice shatters (the Fig. 12 quick case
  /// with iota = 1e-3 breaks 8177 beams and fails at t = 0.026; 1e-12 fails at step 19).
  static constexpr double kMinIota = 1.0;
  /// A fracture of k_f ~ 1e-8 m^2 (a cubic-law aperture of ~0.3 mm) in a nanodarcy shale (k ~ 1e-20
  /// m^2); the paper's largest is 1e6. Beyond it the flow matrix's conductances span more digits than
  /// a double has (1e18 ran for minutes at N = 1000, 1e300 fails the first step).
  static constexpr double kMaxIota = 1e12;
  /// R_i/R, borehole radius (Table 1: 0.138); 0 for point injection. Allowed: 0 <= R_i < 1.
  double R_i = 0.138;
  /// T_u/E, tensile strength (Table 1: 2e-4). Allowed: 0 < tensile_strength <= kMaxStrength.
  double tensile_strength = 2e-4;
  /// C_u/E, uniaxial compressive strength (Table 1: 3.33e-3). Allowed: 0 < compressive_strength <= kMaxStrength.
  double compressive_strength = 3.33e-3;
  /// A strength over E is the strain at failure: rocks fail at 1e-4 ... 1e-2, and above 1 the
  /// small-strain lattice means nothing. A larger value is a strength in Pa typed into this table.
  static constexpr double kMaxStrength = 1.0;
  /// mu_i, internal friction coefficient of Eq. 11 (Table 1: 0.9). Allowed: >= 0.
  double friction = 0.9;
  /// E/K_w, the fluid's compressibility in units of the rock's (Table 1: 1e10/2.2e9); it enters E/M
  /// through Eq. 22 and, on its own, the storage of a water-filled borehole. Allowed: > 0.
  double E_over_Kw = table1_E_over_Kw;

  void validate() const;
};

/// The paper's borehole case (Table 1, Section 3.2): nu = 0.25, R_i = 0.138, E/M by Eq. 22 with
/// Table 1's porosity, K_w and E at this b, strengths and friction of Table 1.
DimensionlessParameters table1_borehole(double b, double Q = 0.01, VolStrain vol_strain = VolStrain::plane_strain);

/// The scales that undo the dimensionless form: x = x* R, sigma = sigma* E, t = t* t_s.
struct Scales {
  double length_m;   ///< R [m]
  double stress_pa;  ///< E [Pa]
  double time_s;     ///< t_s = mu R^2/(k E) [s]
};

/// The one conversion from Table 1 values: Q = mu q/(k E), iota = k_f/k, E/M by Eq. 22,
/// R_i/R, T_u/E, C_u/E. Validates `phys` first.
DimensionlessParameters to_dimensionless(const PhysicalParameters& phys,
                                         VolStrain vol_strain = VolStrain::plane_strain);
Scales scales_of(const PhysicalParameters& phys);

}  // namespace hm::analytic
