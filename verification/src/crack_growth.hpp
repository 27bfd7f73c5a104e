#pragma once
// A dry crack grown from a notch (the Griffith benchmark of the saw-tooth law), loaded by a pressure p
// on its faces, under the control of the load's work-conjugate displacement D = f_1 . u (f_1 the load
// at p = 1), the crack's volume V. (A remote tension is no substitute: the disk's own stretch dominates
// its conjugate displacement, so the crack runs away at fixed D as under load control.) For a fixed set of broken and
// softened beams the response is linear in p, so one solve at p = 1 gives D_1 and the largest failure ratio r_1, and
// the next event (a tooth or a break) comes at p = 1 / r_1, D = D_1 / r_1. Events are taken one at a time; after each,
// the load at the same D is D / D_1 of the new state, and further events at that D follow until none is due (an
// unstable jump), then D is raised to the next event's. No work is done at fixed D, so the drop of pD/2 there is the
// energy the event released.
// On the continuous path (the envelope the teeth approximate) D is raised in small steps and, at each,
// every beam strained past its history is softened to its envelope's secant at that strain, the
// solve repeated until none is: a secant fixed point, reached monotonically since damage only grows.
#include <cstdint>
#include <vector>

#include "hm/lattice2d/fracture/fracture.hpp"
#include "hm/lattice2d/fracture/sawtooth_law.hpp"

namespace hm::verification {

/// Which beams' faces the crack's pressure acts on.
enum class PressurisedFaces {
  broken,          ///< the broken beams only: the process zone ahead of them is dry
  with_softening,  ///< also the softening beams, each with weight 1 - its stiffness factor (its damage)
};

/// How the law's softening is followed.
enum class SofteningPath {
  teeth,       ///< the saw-tooth law's events, one at a time (sequentially linear analysis)
  continuous,  ///< the envelope the teeth approximate (LinearSoftening), by secant iterations at each
               ///< volume: the teeth's limit of infinitely many, infinitely small steps
};

struct CrackGrowthSpec {
  long long n_particles = 15000;  ///< disk of radius 1
  std::uint64_t lattice_seed = 1, strength_seed = 1;
  double notch_half_length = 0.05;    ///< notch |x| < this on y = 0
  double fracture_energy = 0.0;       ///< G_f / (E R); 0: the brittle law (crack-tip factor on)
  hm::lattice2d::SawtoothSpec teeth;  ///< the saw-tooth's shape
  /// The saw-tooth law's f_t over the drawn strength (SawtoothLawOptions): by default the calibrated one a
  /// run of the law uses.
  double strength_factor = hm::lattice2d::calibrated_sawtooth_strength_factor();
  PressurisedFaces faces = PressurisedFaces::broken;
  SofteningPath path = SofteningPath::teeth;  ///< (the saw-tooth law only)
  /// continuous path: the volume's relative step once the crack grows, and the strain past its history
  /// (relative) up to which a beam counts as on it: the secant iterations at a volume end when no beam
  /// is strained further than that. At N = 1.5e4 (kappa = 1.36) a tolerance of 1e-3 gives K within 1e-4
  /// of 1e-4's in 56% of the solves, and a step of 0.01 moves K by 0.2%.
  double volume_step = 0.005, history_tolerance = 1e-3;
  double max_half_length = 0.3;  ///< stop once the crack's half length c passes this
  int max_events = 200000;
};

/// A state at which the crack grows: the event's pressure and volume, before it happens.
struct GrowthPoint {
  double volume = 0.0;       ///< D = f_1 . u: the crack's volume per unit thickness (normal openings x facets x
                             ///< weights; over R^2)
  double pressure = 0.0;     ///< p / E at which the next event happens
  double half_length = 0.0;  ///< c: half the x-span of the broken beams' faces (their Voronoi segments)
  double booked = 0.0;       ///< energy the teeth booked so far (G_f d per beam through all its teeth; over E R^2)
  double work = 0.0;         ///< work of the pressure so far, the integral of p dV (over E R^2)
  /// the pressure's work on the solid so far, the integral of f . du along the solved states (trapezoids;
  /// exact where the state does not change). Less than `work` by what the faces' growing weights take
  /// in at the opening they already have (fluid entering a facet that opened before it was wetted).
  double mechanical_work = 0.0;
  int n_broken = 0;
};

struct CrackGrowthRun {
  std::vector<GrowthPoint> points;
  /// Per tooth index: the energy the events of that tooth released (the drop of (1/2) p V at fixed V),
  /// and what the law booked for them. A beam's last tooth includes its break.
  std::vector<double> released_by_tooth, booked_by_tooth;
  int n_events = 0, n_broken = 0, n_solves = 0;  ///< events: teeth and breaks, or damage updates (continuous)
  double seconds = 0.0;
  bool reached = false;  ///< c passed max_half_length
};

/// The growth of spec.path (the teeth path for the brittle law).
CrackGrowthRun grow_pressurised_crack(const CrackGrowthSpec& spec);

/// The growth benchmarks' l_ch = E G_f / T_u^2 (over R): 0.04, so that the fit's shortest crack, c = 0.1,
/// is 2.5 l_ch (c >= 2 l_ch) and the beams (mean length 0.016 R at N = 1.5e4) are 2.5 times shorter.
constexpr double kGrowthCharacteristicLength = 0.04;

/// The growth over which the toughness and energies are fitted: c from 0.1 to 0.3 (the notch's 0.05 left
/// behind).
constexpr double kGrowthFitFrom = 0.1, kGrowthFitTo = 0.3;

/// Griffith's constants of the calibrated continuum for fracture energy g_f (over E R): the plane-strain
/// modulus E' = E / (1 - nu^2) and K_c = sqrt(E' G_f).
struct GriffithConstants {
  double e_prime, k_c;
};
GriffithConstants griffith_constants(double g_f);
/// Griffith's crack of volume V per unit thickness (over R^2) growing at K_c: V = 2 pi p c^2 / E' with
/// p sqrt(pi c) = K_c gives c = (E' V / (2 sqrt(pi) K_c))^(2/3).
double griffith_half_length(double volume, const GriffithConstants& g);

/// The least-squares line y = intercept + slope x (slope 0 for fewer than two distinct x).
struct LineFit {
  double intercept, slope;
};
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y);

/// What a growth shows over c in [kGrowthFitFrom, kGrowthFitTo]; energies per unit crack length are
/// least-squares slopes against the crack's length 2c.
struct GrowthMeasures {
  int n = 0;               ///< growth points in the range
  double toughness = 0.0;  ///< median of p sqrt(pi c) over them
  double booked = 0.0;     ///< what the law booked: G_f times the crack's facets, and the process zone's share
  double released = 0.0;   ///< W - (1/2) p V: what the growth cost, the fluid's filling of opened facets included
  double rock = 0.0;       ///< (the pressure's work on the solid) - (1/2) p V: what the rock dissipated
};
GrowthMeasures measure_growth(const CrackGrowthRun& run);

/// A crack's half length c: half the x-span of the circumcentres of its triangles (`triangles`, indices
/// into `dual`), where its faces (the broken beams' Voronoi segments) end. 0 for none.
double crack_half_length(const hm::lattice2d::DualGraph& dual, const std::vector<int>& triangles);

}  // namespace hm::verification
