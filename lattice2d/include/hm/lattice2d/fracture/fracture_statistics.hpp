#pragma once
/// \file
/// Fracture statistics of a broken-beam pattern: the broken beams grouped into fractures
/// (clusters of beams connected through shared particles, or only through shared triangles), each
/// described by its size, radial extent, direction and failure modes, a per-snapshot summary (radial
/// vs secondary fractures, radial arms crossing a circle) and CSV writers. Dimensionless lengths
/// (over R), undeformed geometry, radii measured from the origin (the domain centre).
/// Definitions, choices and limits: docs/fracture_statistics.md.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "hm/core/enum_names.hpp"
#include "hm/lattice2d/fracture/failure.hpp"
#include "hm/lattice2d/fracture/sawtooth_law.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/mechanics/beam_stiffness.hpp"

namespace hm::lattice2d {

/// When two broken beams belong to one fracture.
enum class FractureLink {
  /// They share a particle. Default: an en-echelon crack, whose broken beams step across a particle
  /// with one intact beam between them, is one fracture, as it looks in a picture of broken beams
  /// (at N = 1e5 the triangle rule cut the long radial cracks into thousands of pieces).
  shared_particle,
  /// They are edges of one Delaunay triangle: their Voronoi segments meet, a continuous crack face.
  shared_triangle,
};
constexpr auto enum_names(FractureLink) {
  return core::enum_table<FractureLink>(
      {{FractureLink::shared_particle, "particle"}, {FractureLink::shared_triangle, "triangle"}});
}

/// Whether softened beams (past their strength, on the saw-tooth law's teeth: a crack's process zone)
/// join the broken beams they touch into one fracture.
enum class SoftenedBeams {
  /// They link, by the same rule as broken beams, but are not members: a crack whose broken parts are
  /// held together by a ligament still on its teeth is one fracture, as the flow network sees it (a
  /// softened facet conducts as crack by its damage). Default: otherwise one beam left on its teeth
  /// splits a fracture that crosses the annulus into a radial part and a secondary.
  link,
  /// Only broken beams link (the brittle law has no softened beams, so its fractures are the same).
  ignore,
};
constexpr auto enum_names(SoftenedBeams) {
  return core::enum_table<SoftenedBeams>({{SoftenedBeams::link, "link"}, {SoftenedBeams::ignore, "ignore"}});
}

/// Options of compute_fracture_statistics.
struct FractureStatisticsOptions {
  /// Which broken beams are connected (docs/fracture_statistics.md compares the two rules).
  FractureLink link = FractureLink::shared_particle;
  /// Whether softened beams connect broken ones.
  SoftenedBeams softened = SoftenedBeams::link;
  /// Radius of the arm-counting circle as a fraction of the way from the borehole wall to the outer
  /// boundary: r = R_i + f (R_o - R_i) (R_i = 0 without a borehole; R_o = 1, or min(width, height)/2
  /// for a rectangle). Our choice 0.25: close enough to the wall that short radial cracks reach it,
  /// far enough (several beam lengths at 1e3-1e5 particles) that cracks merged at the wall separate.
  /// Allowed: 0 < arm_radius_fraction < 1.
  double arm_radius_fraction = 0.25;
  /// Two crossings of the circle belong to the same arm when their arc distance is at most this many
  /// mean beam lengths. Our choice 3: one crack crosses the circle with a zig-zag of broken beams
  /// about one beam length wide; 3 absorbs that and a slight crack inclination without merging cracks
  /// a few beams apart. Allowed: arm_gap_beams > 0.
  double arm_gap_beams = 3.0;
  /// The same gap as an arc length over R, for n_arms_fixed_gap: a count whose merging distance does
  /// not shrink with the beams (3 beam lengths are 36 degrees of the arm circle at N = 700, 3 at 1e5).
  /// Our choice 0.03: 3 beam lengths at N ~ 1e4, the resolution the saw-tooth law's l_ch needs.
  /// Allowed: arm_gap > 0, finite.
  double arm_gap = 0.03;
  /// Secondary fractures at least this long (Fracture::extent, over R) are counted in
  /// n_secondary_sizable. Our choice 0.05: visible in a picture of the whole domain (1/40 of its
  /// width), whatever N; most secondary clusters at N = 1e5 are single broken beams (~0.005 long).
  /// Allowed: sizable_extent >= 0.
  double sizable_extent = 0.05;

  /// Throws hm::InputError "fracture_statistics.field = value, allowed: rule".
  void validate() const;
};

/// The rule a user's arm gap (a case's [output] arm_gap, `fractures --arm-gap`) must meet: a gap wider
/// than R merges every crossing of the arm circle (radius < 1) into one arm.
inline constexpr const char* kArmGapRule = "0 < arm_gap <= 1";
inline bool is_allowed_arm_gap(double gap) { return gap > 0.0 && gap <= 1.0; }

/// "radial" (connected to the borehole) or "secondary" (everything else).
enum class FractureKind { radial, secondary };
constexpr auto enum_names(FractureKind) {
  return core::enum_table<FractureKind>({{FractureKind::radial, "radial"}, {FractureKind::secondary, "secondary"}});
}

/// One fracture: a connected cluster of broken beams (FractureStatisticsOptions::link).
struct Fracture {
  int id = 0;                                   ///< 0, 1, ... in order of the smallest beam index
  FractureKind kind = FractureKind::secondary;  ///< radial iff connected_to_borehole
  std::vector<int> beams;                       ///< beam indices, ascending
  bool connected_to_borehole = false;           ///< contains a broken borehole-wall beam (BoundaryTag::inner)
  bool reaches_outer = false;                   ///< contains a broken outer-boundary beam (BoundaryTag::outer)
  double r_min = 0.0;                           ///< smallest radius of a beam midpoint (undeformed, over R)
  double r_max = 0.0;                           ///< largest radius of a beam midpoint
  double length = 0.0;                          ///< radial extent r_max - r_min (not the path length)
  double angle_deg = 0.0;                       ///< atan2 of the mean unit midpoint direction, in [0, 360)
  double extent = 0.0;                          ///< diagonal of the bounding box of the beam midpoints
  int n_tensile = 0;                            ///< beams whose break-log mode is tensile (0 without a log)
  int n_shear = 0;                              ///< beams whose break-log mode is shear (0 without a log)

  int n_beams() const { return static_cast<int>(beams.size()); }
};

/// All fractures of one broken pattern and their summary.
struct FractureStatistics {
  std::vector<Fracture> fractures;  ///< ordered by id
  int n_broken = 0;                 ///< broken beams (= sum of the fractures' n_beams)
  int n_fractures = 0;
  int n_radial = 0;                 ///< fractures connected to the borehole
  int n_radial_reaching_outer = 0;  ///< radial fractures that also reach the outer boundary
  int n_secondary = 0;
  int n_secondary_sizable = 0;  ///< secondary fractures with extent >= options.sizable_extent
  int n_tensile = 0;            ///< summed over the fractures
  int n_shear = 0;
  double arm_radius = 0.0;         ///< radius of the arm-counting circle (options.arm_radius_fraction)
  int n_arms = 0;                  ///< count_crossings at arm_radius, gap arm_gap_beams mean beam lengths
  int n_arms_fixed_gap = 0;        ///< count_crossings at arm_radius, gap arm_gap (over R)
  double max_radial_extent = 0.0;  ///< largest r_max of a radial fracture, 0 if none
};

/// The radius r = R_i + arm_radius_fraction (R_o - R_i) of the arm-counting circle of `lattice`.
double arm_radius(const Lattice& lattice, const FractureStatisticsOptions& options = {});

/// Number of arms crossing the circle r = radius: the broken beams whose segment (particle i to j,
/// undeformed) straddles the circle (one end at r < radius, the other at r >= radius), grouped by the
/// angle where they cross it; crossings whose arc distance (circularly) is at most max_gap (over R)
/// form one arm. 0 if no broken beam straddles the circle. Limits: an arm that crosses the circle
/// twice (a crack curling back) counts twice; arms closer than the gap count once.
/// Throws hm::InputError if broken is not one flag per beam or radius/max_gap is not > 0.
int count_crossings(const Lattice& lattice, const std::vector<bool>& broken, double radius, double max_gap);

/// The gap of n_arms: arm_gap_beams mean beam lengths of `lattice`, over R.
double arm_gap_of_beams(const Lattice& lattice, const FractureStatisticsOptions& options = {});

/// Fractures of the broken pattern `broken` (one flag per beam) and their summary. `log` (optional)
/// gives each broken beam's failure mode; events of beams not broken in `broken` are ignored (so a
/// whole run's log may be passed with an earlier snapshot), and a beam logged twice counts once, by
/// its first event. `softened` (one flag per beam, or empty for none) marks the beams on their teeth;
/// with options.softened = link they join broken beams into one fracture but are not counted in it
/// (beams, n_broken, radii, kinds and arms are those of its broken beams). A flag on a broken beam is
/// ignored. Deterministic: fractures are numbered by their smallest beam index.
/// Throws hm::InputError for invalid options, broken or a non-empty softened not sized n_beams, or a
/// logged beam out of range.
FractureStatistics compute_fracture_statistics(const Lattice& lattice, const std::vector<bool>& broken,
                                               const std::vector<BreakEvent>& log = {},
                                               const FractureStatisticsOptions& options = {},
                                               const std::vector<bool>& softened = {});
/// The same with broken = broken_flags(states).
FractureStatistics compute_fracture_statistics(const Lattice& lattice, const std::vector<BeamState>& states,
                                               const std::vector<BreakEvent>& log = {},
                                               const FractureStatisticsOptions& options = {});

/// The beams on their teeth at `until` (one flag per beam): those with an event in the saw-tooth law's
/// tooth log at a load <= until. Damage never heals, so a beam once softened stays so (a broken one
/// too; compute_fracture_statistics ignores the flag there). Throws hm::InputError for an event's beam
/// outside 0 <= beam < n_beams.
std::vector<bool> softened_flags(const std::vector<ToothEvent>& teeth, int n_beams, double until);

/// The statistics of one output time.
struct FractureSnapshot {
  double t = 0.0;  ///< time or load of the snapshot; the caller's choice
  FractureStatistics stats;
};

}  // namespace hm::lattice2d
