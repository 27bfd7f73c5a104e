#pragma once
/// \file
/// A 2D lattice case file (model = "lattice2d"), the one format of every `hmlattice run`: [physics]
/// or [physics_si] (read_physics), then the tables of run_case_keys() — [lattice], [mechanics],
/// [flow], [coupling], [numerics], [fracture], [output]. Every key, its default and its rule:
/// docs/case-format.md (`hmlattice case-format`). Every key is optional; unknown keys are errors.
#include <filesystem>
#include <string>
#include <vector>

#include "hm/analytic/insitu_annulus.hpp"
#include "hm/case/case_file.hpp"
#include "hm/case/case_keys.hpp"
#include "hm/lattice2d/coupled/coupled_model.hpp"
#include "hm/lattice2d/flow/flow_network.hpp"
#include "hm/lattice2d/fracture/fracture_statistics.hpp"
#include "hm/lattice2d/fracture/notch.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/mechanics/beam_stiffness.hpp"
#include "hm/lattice2d/mechanics/mechanics.hpp"

namespace hm::cases {

/// What [output] asks for besides its times, which are the stepping's (RunCase::stepping.output_times).
struct RunOutput {
  /// Write VTK snapshots (.vtu + .pvd) at the output times. Default true.
  bool vtk = true;
  /// Number of equal radial shells of radial.csv on [R_i, radial_max]. Allowed: 1 <= radial_bins <= 10000.
  int radial_bins = 50;
  /// Outer edge of the radial shells. Allowed: R_i < radial_max <= 1.
  double radial_max = 1.0;
  /// How fractures.csv and fracture_summary.csv are counted: which broken beams form one fracture
  /// ([output] fracture_link) and the arms' gap in R ([output] arm_gap); the rest at their defaults.
  hm::lattice2d::FractureStatisticsOptions statistics;
};

/// [mechanics]' in-situ state of the rock before injection (docs/insitu.md): the far-field total
/// stress and the rest pore pressure, over E, compression positive.
struct InSituState {
  double S_H = 0.0;          ///< largest horizontal stress. Allowed: >= S_h.
  double S_h = 0.0;          ///< smallest horizontal stress. Allowed: >= 0.
  double theta_H_deg = 0.0;  ///< azimuth of S_H from the x axis [degrees]. Allowed: finite.
  double p0 = 0.0;           ///< rest pore pressure (the flow's p is the deviation from it). Allowed: >= 0.
  bool is_zero() const { return S_H == 0.0 && S_h == 0.0 && p0 == 0.0; }
  hm::analytic::FarFieldStress far_field() const;
};

/// A fully read and validated 2D case.
struct RunCase {
  CasePhysics physics;
  hm::lattice2d::LatticeSpec lattice;
  /// Which calibrated beams (calibrated_beam_parameters(stiffness_scaling)); default the toolkit's.
  hm::lattice2d::StiffnessScaling stiffness_scaling = hm::lattice2d::StiffnessScaling::voronoi_facet;
  hm::lattice2d::BoundaryConditions boundary;  ///< only `outer` is read from the case
  InSituState insitu;                          ///< [mechanics] S_H, S_h, theta_H, p0
  hm::lattice2d::MechanicsOptions mechanics;   ///< only `solver` is read from the case
  /// [flow]'s options (borehole_deformation read with the default of its borehole_storage); the flow's
  /// physics comes from [physics] (flow_parameters()).
  hm::lattice2d::FlowOptions flow;
  hm::lattice2d::CouplingOptions coupling;
  hm::lattice2d::TimeStepping stepping;  ///< its output_times are [output] times
  bool fracture_enabled = false;
  /// End the run with the accepted step that breaks the first beam: Section 3.5's breakdown pressure
  /// is known then, and the fracture after it is not needed (Fig. 18). That step's state is written
  /// as an output time's; the folder is complete. Allowed only with fracture_enabled. Default false.
  bool stop_at_first_break = false;
  /// With stop_at_first_break, whether `model` has reached the run's end: a beam has failed (a notch's
  /// cut beams do not count). The one rule for `hmlattice run` and the verification runs.
  bool reached_first_break(const hm::lattice2d::CoupledModel& model) const {
    return stop_at_first_break && model.n_broken() > model.n_cut();
  }
  /// Beam strengths (means from [physics]) and the break loop's crack-tip rule; used when enabled.
  hm::lattice2d::StrengthSpec strength;
  hm::lattice2d::BreakLoopOptions break_loop;
  /// The tension law and, for the saw-tooth law, its fracture energy and teeth.
  hm::lattice2d::FractureLaw fracture_law = hm::lattice2d::FractureLaw::brittle;
  hm::lattice2d::SawtoothLawOptions sawtooth;
  /// Pre-cut cracks: the beams each segment crosses are broken before the first step (notch.hpp).
  std::vector<hm::lattice2d::NotchSegment> notches;
  /// The notches' own aperture over R, a cut slot's width (flow with fracture_flow = "cubic" only).
  double notch_aperture = 0.0;
  RunOutput output;

  /// The calibrated beam constants of this case's stiffness scaling.
  hm::lattice2d::BeamParameters beams() const;
  /// `boundary` with the in-situ state's rest loads (add_far_field_loads with [physics] b).
  hm::lattice2d::BoundaryConditions boundary_conditions() const;
  /// The flow parameters of the physics (Q, b, iota, E/M) with this case's borehole node.
  hm::lattice2d::FlowParameters flow_parameters() const;
};

/// The keys of a 2D case after [physics]: the reader, the config.toml writer and the reference.
const CaseKeys<RunCase>& run_case_keys();

/// Reads and validates the whole case; throws hm::InputError "<file>: [table] key = value, allowed: ...".
RunCase read_run_case(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});
/// The same for a case already parsed (or made in memory).
RunCase read_run_case(const CaseFile& file);

/// The resolved case as TOML (itself a valid case file), with a [provenance] table.
std::string run_case_to_toml(const RunCase& c, const std::string& provenance_toml);

}  // namespace hm::cases
