#pragma once
// A dry crack grown from a notch (the Griffith benchmark of the saw-tooth law), loaded by a pressure p
// on its faces, under the control of the load's work-conjugate displacement D = f_1 . u (f_1 the load
// at p = 1), the crack's volume V. (A remote tension is no substitute: the disk's own stretch dominates
// its conjugate displacement, so the crack runs away at fixed D as under load control.) For a fixed set of broken and softened beams the response is linear in p, so one solve at p = 1
// gives D_1 and the largest failure ratio r_1, and the next event (a tooth or a break) comes at
// p = 1 / r_1, D = D_1 / r_1. Events are taken one at a time; after each, the load at the same D is
// D / D_1 of the new state, and further events at that D follow until none is due (an unstable jump),
// then D is raised to the next event's. No work is done at fixed D, so the drop of pD/2 there is the
// energy the event released.
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

struct CrackGrowthSpec {
  long long n_particles = 15000;  ///< disk of radius 1
  std::uint64_t lattice_seed = 1, strength_seed = 1;
  double notch_half_length = 0.05;  ///< notch |x| < this on y = 0
  double fracture_energy = 0.0;     ///< G_f / (E R); 0: the brittle law (crack-tip factor on)
  hm::lattice2d::SawtoothSpec teeth;  ///< the saw-tooth's shape
  /// The saw-tooth law's f_t over the drawn strength (SawtoothLawOptions): by default the calibrated one a
  /// run of the law uses.
  double strength_factor = hm::lattice2d::calibrated_sawtooth_strength_factor();
  PressurisedFaces faces = PressurisedFaces::broken;
  double max_half_length = 0.3;     ///< stop once the crack's half length c passes this
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
  int n_broken = 0;
};

struct CrackGrowthRun {
  std::vector<GrowthPoint> points;
  /// Per tooth index: the energy the events of that tooth released (the drop of (1/2) p V at fixed V),
  /// and what the law booked for them. A beam's last tooth includes its break.
  std::vector<double> released_by_tooth, booked_by_tooth;
  int n_events = 0, n_broken = 0, n_solves = 0;
  double seconds = 0.0;
  bool reached = false;  ///< c passed max_half_length
};

CrackGrowthRun grow_pressurised_crack(const CrackGrowthSpec& spec);

/// A crack's half length c: half the x-span of the circumcentres of its triangles (`triangles`, indices
/// into `dual`), where its faces (the broken beams' Voronoi segments) end. 0 for none.
double crack_half_length(const hm::lattice2d::DualGraph& dual, const std::vector<int>& triangles);

}  // namespace hm::verification
