#pragma once
/// \file
/// The saw-tooth law across a lattice: which tooth (sawtooth.hpp) each beam is on, the axial stress
/// that drives it, and the energy the teeth have dissipated. The break loop (fracture.hpp) steps a
/// beam whose axial stress reaches its tooth's strength down to the next tooth (BeamMechanics::
/// soften_beam), or breaks it after the last one. Dimensionless (stresses over E, lengths over R,
/// G_f over E R, energies over E R^2 per unit thickness).
///
/// The beam's own variables: its section d is the facet its stiffness stands for (the Voronoi facet
/// under uniform k_n; under voronoi_facet scaling max(d, facet_floor L), so that every beam has the
/// same axial modulus E_n = k_n,beam L / d); its axial stress is sigma = N / d, N its normal force
/// (softening included), and its strain the elongation over L. Then each beam taken through all its
/// teeth dissipates G_f d: a crack across it costs G_f per unit crack length.
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "hm/core/enum_names.hpp"
#include "hm/core/state_archive.hpp"
#include "hm/lattice2d/fracture/sawtooth.hpp"
#include "hm/lattice2d/fracture/strength.hpp"
#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/mechanics/beam_stiffness.hpp"

namespace hm::lattice2d {

/// How a beam fails in tension.
enum class FractureLaw {
  brittle,   ///< the paper's: removed at its strength, with the crack-tip factor (Section 2.1, Fig. 2)
  sawtooth,  ///< softened tooth by tooth with a fracture energy (this file)
};
constexpr auto enum_names(FractureLaw) {
  return core::enum_table<FractureLaw>({{FractureLaw::brittle, "brittle"}, {FractureLaw::sawtooth, "sawtooth"}});
}

/// The law's material constants.
struct SawtoothLawOptions {
  /// G_f / (E R), the energy per unit crack area over E R. Allowed: > 0, finite.
  double fracture_energy = 0.0;
  /// The teeth's shape, the same for every beam.
  SawtoothSpec teeth;
  /// A beam's f_t over its drawn tensile strength (strengths.tensile): the beams' axial stress is not
  /// the mean stress, so the lattice's strength is not its beams'. 1 takes the strengths as they are;
  /// calibrated_sawtooth_strength_factor() makes uniaxial tension peak at T_u. Allowed: > 0, finite.
  double strength_factor = 1.0;

  /// Throws hm::InputError "sawtooth_law.field = value, allowed: rule".
  void validate() const;
};

/// The strength_factor with which uniaxial tension of an unnotched lattice (N = 1e4 square, grips,
/// +-5% strengths, G_f / (E R) = 2.34e-9) peaks at T_u: 1.36, by secant steps on the measured peak
/// over T_u (factor 1: 0.798, 0.796, 0.792 for seeds 2-4; 1.258: 0.951; 1.34: 0.987, 0.995). The
/// peak is not linear in the factor (a stronger beam is more brittle for the same G_f) and depends on
/// the resolution (0.87 at N = 4000 with 1.258): docs/fracture_law.md. The verification suite's
/// lattice2d.sawtooth_uniaxial_tension measures it.
double calibrated_sawtooth_strength_factor();

/// One tooth of a beam giving way; the last one (stiffness_factor 0) breaks the beam and is also its
/// BreakEvent. The energies of a beam's events sum to G_f d.
struct ToothEvent {
  int sequence = 0;  ///< 0, 1, ... in order, counted apart from the breaks
  int beam = -1;
  double load = 0.0;              ///< load factor or time, the caller's choice (as BreakEvent::load)
  int tooth = 0;                  ///< the tooth that gave way (0 = the intact beam)
  double stiffness_factor = 1.0;  ///< the beam's stiffness over its intact one after the step (0: broken)
  double axial_stress = 0.0;      ///< N / d at the step (judged scale)
  double ratio = 0.0;             ///< axial stress over the tooth's strength, >= 1
  double energy = 0.0;            ///< the energy this step releases: (1/2)(E_i - E_{i+1}) eps_i^2 d L
};

class SawtoothLaw {
 public:
  /// For `lattice` with its `dual`, the beams' constants `parameters` (stiffness scaling included) and
  /// their tensile strengths (strengths.tensile, each beam's f_t). Throws hm::InputError for invalid
  /// options, strengths not sized one per beam, or a beam with a facet of zero length (no section).
  SawtoothLaw(const Lattice& lattice, const DualGraph& dual, const BeamParameters& parameters,
              const BeamStrengths& strengths, const SawtoothLawOptions& options);

  /// The beam's section d (file comment).
  double section(int beam) const { return section_[static_cast<std::size_t>(beam)]; }
  /// Its axial stress for normal force N (BeamForce::normal): N / d.
  double axial_stress(int beam, double normal_force) const { return normal_force / section(beam); }
  /// The linear envelope the beam's teeth approximate (sawtooth.hpp), for following it continuously.
  LinearSoftening envelope(int beam) const;
  /// The current tooth (0 = intact beam at f_t, or at the reduced strength of a beam too long for its G_f).
  int tooth(int beam) const { return tooth_[static_cast<std::size_t>(beam)]; }
  /// The strength of the current tooth: the axial stress at which it gives way.
  double strength(int beam) const;
  /// True when the current tooth is the beam's last: its giving way breaks the beam.
  bool on_last_tooth(int beam) const;
  /// The stiffness factor of the next tooth (precondition: !on_last_tooth).
  double next_stiffness_factor(int beam);
  /// The beam's teeth (computed once per beam, on first use).
  const BeamTeeth& teeth(int beam);

  /// The current tooth gives way: the beam moves to the next tooth (or is spent after the last) and
  /// the tooth's energy is added to dissipated_energy(). Returns that energy.
  double give_way(int beam);

  /// Energy dissipated so far by all the teeth that gave way (the crack's G_f times its facets for
  /// beams taken through every tooth).
  double dissipated_energy() const { return dissipated_; }
  /// Beams too long for their G_f (one tooth at the reduced strength; sawtooth.hpp).
  int n_brittle_beams() const { return n_brittle_; }
  const SawtoothLawOptions& options() const { return options_; }

  /// Each beam's tooth and the dissipated energy, for checkpoints (the teeth are recomputed).
  void save_state(core::StateWriter& w) const;
  /// Throws hm::InputError for a state of another lattice.
  void restore_state(core::StateReader& r);

 private:
  const Lattice& lattice_;
  SawtoothLawOptions options_;
  std::vector<double> section_;               // d per beam
  std::vector<double> axial_modulus_;         // E_n = k_n,beam L / d per beam
  std::vector<double> tensile_;               // f_t per beam
  std::vector<double> first_strength_;        // strength of tooth 0 (f_t, or the reduced one of a brittle beam)
  std::vector<int> tooth_;                    // current tooth per beam
  std::unordered_map<int, BeamTeeth> teeth_;  // of the beams that have been asked for them
  double dissipated_ = 0.0;
  int n_brittle_ = 0;
};

}  // namespace hm::lattice2d
