#pragma once
/// \file
/// The saw-tooth approximation of a beam's linear tension softening (the crack band of Bažant & Oh
/// 1983, in sequentially linear form: Rots & Invernizzi 2004, Rots, Belletti & Invernizzi 2008),
/// which gives a beam a fracture energy G_f instead of a bare strength. Dimensionless (stresses over
/// E, lengths over R, G_f over E R).
///
/// In the beam's own variables (axial modulus E_n = k_n L / d, stress sigma = F / d, strain
/// eps = elongation / L): the envelope rises elastically to (eps_0 = f_t / E_n, f_t) and falls linearly to
/// zero stress at eps_u = 2 G_f / (f_t L); its area (1/2) f_t eps_u times the beam's volume d L is G_f d,
/// the energy of a crack across the beam's facet. Tooth i is the secant E_i = E_n / a^i (a the
/// reduction factor, i = 0 ... n - 1), holding until the stress reaches the envelope at
/// f_i = E_i D eps_u / (E_i + D), D = f_t / (eps_u - eps_0) the softening modulus; then the beam steps
/// down to E_{i+1} (after the last tooth, E_n = 0: broken). Each step releases, per unit volume, the
/// triangle between the two secants up to eps_i = f_i / E_i, (1/2)(E_i - E_{i+1}) eps_i^2.
///
/// The teeth touch the envelope only at their peaks, so on the envelope itself they release less
/// than G_f. Here eps_u is stretched per beam (the teeth stay on the stretched envelope) until the
/// released energy is G_f / L per unit volume exactly: every beam dissipates G_f times its facet,
/// whatever its length ("area-preserving" saw-tooth). A beam too long for its G_f (eps_u <= eps_0 on
/// the unstretched envelope: L >= 2 E_n G_f / f_t^2, the crack band's snap-back) has one tooth at the
/// reduced strength sqrt(2 E_n G_f / L), which releases the same G_f / L.
#include <vector>

namespace hm::lattice2d {

/// The saw-tooth's shape, the same for every beam.
struct SawtoothSpec {
  /// a: each tooth's secant over the next's. Rots & Invernizzi use 1.5-2; our default 2 with 10 teeth
  /// ends at E_9 = E_n / 512, after which the beam is broken. Allowed: > 1, finite.
  double reduction = 2.0;
  /// n, the teeth before the beam breaks. Allowed: 1 ... 100.
  int n_teeth = 10;

  /// Throws hm::InputError "sawtooth.field = value, allowed: rule".
  void validate() const;
};

/// One beam's teeth.
struct BeamTeeth {
  /// E_i / E_n of tooth i (1, 1/a, 1/a^2, ...); one entry (1) for a brittle beam.
  std::vector<double> stiffness_factor;
  /// f_i, the axial stress at which tooth i gives way (f_0 = f_t unless brittle).
  std::vector<double> strength;
  /// eps_u of the stretched envelope the teeth lie on (that of the unstretched one for a brittle beam).
  double ultimate_strain = 0.0;
  /// The beam is too long for its G_f: one tooth at the energy-equivalent strength.
  bool brittle = false;
};

/// The teeth of a beam of axial modulus E_n, tensile strength f_t, fracture energy G_f and length L (all
/// > 0, finite; throws hm::InputError otherwise, or for an invalid spec).
BeamTeeth sawtooth_teeth(double axial_modulus, double tensile_strength, double fracture_energy, double length,
                         const SawtoothSpec& spec = {});

/// The beam is too long for its G_f (eps_u <= eps_0, L >= 2 E_n G_f / f_t^2): one tooth. No validation.
bool is_snap_back(double axial_modulus, double tensile_strength, double fracture_energy, double length);
/// The strength of the first tooth, sawtooth_teeth(...).strength[0], without the other teeth: f_t, or
/// sqrt(2 E_n G_f / L) for a beam too long for its G_f. No validation.
double first_tooth_strength(double axial_modulus, double tensile_strength, double fracture_energy, double length);

/// The linear envelope the teeth approximate, followed continuously (the teeth's limit of infinitely many,
/// infinitely small steps): a damage law in the beam's own variables with the largest strain kappa it has
/// reached as its history. Rises elastically to (eps_0 = f_t / E_n, f_t), falls linearly to zero stress at
/// eps_u = 2 G_f / (f_t L); on the envelope the beam's secant is s(kappa) E_n, s = f(kappa) / (E_n kappa),
/// and it has dissipated, per unit volume, the envelope's area up to kappa less the secant's stored
/// triangle, G_f / L at eps_u. A beam too long for its G_f (is_snap_back) has no softening branch: it
/// breaks at its first tooth's strength, at the same G_f / L.
struct LinearSoftening {
  double modulus = 0.0;          ///< E_n
  double strength = 0.0;         ///< f_t (the energy-equivalent strength for a snap-back beam)
  double ultimate_strain = 0.0;  ///< eps_u (= eps_0 for a snap-back beam)
  double dissipation = 0.0;      ///< G_f / L, the energy per unit volume at eps_u

  double peak_strain() const { return strength / modulus; }
  /// The beam is spent at strain kappa: broken.
  bool is_spent(double kappa) const { return kappa >= ultimate_strain; }
  /// s(kappa) in (0, 1] for eps_0 <= kappa < eps_u (1 below eps_0).
  double secant_factor(double kappa) const;
  /// The energy dissipated per unit volume once the beam has reached strain kappa: 0 up to eps_0,
  /// G_f / L from eps_u on.
  double dissipated_density(double kappa) const;
};

/// The envelope of a beam (the arguments of sawtooth_teeth; no validation).
LinearSoftening linear_softening(double axial_modulus, double tensile_strength, double fracture_energy, double length);

/// The energy per unit volume the beam releases when taken through all its teeth:
/// sum_i (1/2)(E_i - E_{i+1}) (f_i / E_i)^2, E_n = 0 after the last tooth.
double released_energy_density(const BeamTeeth& teeth, double axial_modulus);

}  // namespace hm::lattice2d
