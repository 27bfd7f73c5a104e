#pragma once
/// The break loop's failure check of the current solution (Section 2.1), fracture.hpp's
/// break_until_stable: connection forces -> particle stresses (compute_particle_stress) -> beam
/// stresses with the crack-tip factor (beam_stress, CrackTipOptions::factor) -> Eq. 11 on the intact
/// beams (FailureCriterion) -> the one beam most over its threshold. The same functions as
/// select_beam_to_break(current_beam_stress(...)), so the same bits and the same break sequence, but run
/// once per re-solve of a loop that may break thousands of beams, hence:
///  - buffers kept for the whole loop (no per-iteration allocation of per-particle arrays);
///  - stresses only of the intact beams (the candidates), without the principal angle;
///  - the reference and the judged (stress_scale x) checks in the same pass;
///  - the crack-tip set kept up to date by counts per triangle, touched only around a newly broken
///    beam, instead of find_crack_tip_beams' pass over every triangle.
/// Equality with the public path: tests/lattice2d/test_fast_path.cpp (Release, every break).
#include <array>
#include <vector>

#include "hm/lattice2d/fracture/failure.hpp"
#include "hm/lattice2d/fracture/sawtooth_law.hpp"
#include "hm/lattice2d/fracture/strength.hpp"
#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "hm/lattice2d/mechanics/particle_stress.hpp"

namespace hm::lattice2d {

class FailureScan {
 public:
  /// For `lattice` (and its `dual`) with the beam states `states` (one per beam) at the start.
  /// With a saw-tooth `law`, tension is judged on each beam's axial stress against its tooth's
  /// strength and the crack-tip factor is off; shear stays Eq. 11 on the particle stresses.
  FailureScan(const Lattice& lattice, const DualGraph& dual, const CrackTipOptions& crack_tip,
              const std::vector<BeamState>& states, const SawtoothLaw* law = nullptr);

  /// Beam `beam` went from intact to broken: its triangles' broken counts change, and with them which
  /// beams lie in a triangle of exactly one broken beam (find_crack_tip_beams).
  void beam_broken(int beam);

  struct Result {
    BreakCandidate judged;             ///< select_beam_to_break at stress_scale x the stresses
    double max_reference_ratio = 0.0;  ///< its max_ratio at the reference stresses (stress_scale = 1)
    double sigma_1 = 0.0, sigma_3 = 0.0, crack_tip_factor = 1.0;  ///< of judged.beam, judged scale
    double axial_stress = 0.0;  ///< of judged.beam at the judged scale, under a saw-tooth law
  };

  /// The check for connection forces `forces` (BeamMechanics::beam_forces) and the current `states`
  /// (those of the constructor, changed only through beam_broken).
  Result run(const std::vector<BeamForce>& forces, const BeamStrengths& strengths, const std::vector<BeamState>& states,
             double stress_scale);

  /// The crack-tip factor run() applies to intact beam `beam` (compute_beam_stress's, from the counts).
  double crack_tip_factor(int beam) const;
  /// The particle stresses of the last run().
  const ParticleStress& particle_stress() const { return particle_; }

 private:
  static constexpr int kChunks = 2;
  // Below this many beams (N ~ 7000) one thread: waking the second costs more than it saves.
  static constexpr int kParallelBeams = 20000;

  void scan_beams(int first, int last, const std::vector<BeamForce>& forces, const BeamStrengths& strengths,
                  const std::vector<BeamState>& states, double stress_scale, Result& out, bool& any_intact) const;

  const Lattice& lattice_;
  const DualGraph& dual_;
  CrackTipOptions crack_tip_;
  const SawtoothLaw* law_;            // null: the brittle law
  ParticleStress particle_;           // of the last run, storage reused
  std::vector<int> triangle_broken_;  // broken beams per triangle
  std::vector<int> tip_triangles_;    // per beam: its triangles with exactly one broken beam
};

}  // namespace hm::lattice2d
