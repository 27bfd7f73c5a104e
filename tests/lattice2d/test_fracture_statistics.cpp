#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

#include "approx.hpp"
#include "hm/core/input_error.hpp"
#include "hm/lattice2d/fracture/fracture.hpp"
#include "hm/lattice2d/fracture/fracture_statistics.hpp"
#include "hm/lattice2d/io/fracture_tables.hpp"
#include "lattice_fixtures.hpp"

using namespace hm::lattice2d;

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double R_i = 0.138;  // LatticeSpec's default borehole radius (Table 1)

// The annulus of every test: 4000 particles, mean beam ~0.03, about 30 particles on the wall.
const Lattice& annulus() {
  static const Lattice lattice = hm::test::make_lattice(DomainShape::annulus, 4000, 3);
  return lattice;
}

double mean_beam(const Lattice& lattice) { return lattice.length.mean(); }

Eigen::Vector2d polar(double r, double deg) {
  return r * Eigen::Vector2d(std::cos(deg * pi / 180), std::sin(deg * pi / 180));
}

// Breaks the beams crossing the segment a-b. A segment through a particle would leave a gap in the
// crack (beams_crossing_segment needs a proper crossing), so the ray must clear every particle.
void break_segment(const Lattice& lattice, std::vector<bool>& broken, const Eigen::Vector2d& a,
                   const Eigen::Vector2d& b) {
  const Eigen::Vector2d t = (b - a).normalized();
  double clearance = 1e300;
  for (int i = 0; i < lattice.n_particles(); ++i) {
    const Eigen::Vector2d p = lattice.points.col(i) - a;
    const double s = std::clamp(p.dot(t), 0.0, (b - a).norm());
    clearance = std::min(clearance, (p - s * t).norm());
  }
  REQUIRE(clearance > 1e-3 * mean_beam(lattice));
  for (int e : beams_crossing_segment(lattice, a, b)) broken[static_cast<std::size_t>(e)] = true;
}

// A radial ray at angle deg from just inside the borehole (so it cuts the wall chord) to radius r1.
void break_ray(const Lattice& lattice, std::vector<bool>& broken, double deg, double r1) {
  break_segment(lattice, broken, polar(0.9 * R_i, deg), polar(r1, deg));
}

double angle_difference(double a_deg, double b_deg) {
  const double d = std::fmod(std::abs(a_deg - b_deg), 360.0);
  return std::min(d, 360.0 - d);
}

// The fracture whose angle is closest to deg.
const Fracture& fracture_near(const FractureStatistics& stats, double deg) {
  REQUIRE(!stats.fractures.empty());
  return *std::min_element(stats.fractures.begin(), stats.fractures.end(), [&](const Fracture& a, const Fracture& b) {
    return angle_difference(a.angle_deg, deg) < angle_difference(b.angle_deg, deg);
  });
}

// Four straight radial cracks from the borehole through the outer boundary. The rays avoid the exact
// axes by 0.37 deg so that they do not pass through an evenly spaced boundary particle.
const std::vector<double> four_rays{0.37, 90.37, 180.37, 270.37};
std::vector<bool> four_cracks(const Lattice& lattice) {
  std::vector<bool> broken(static_cast<std::size_t>(lattice.n_beams()), false);
  for (double deg : four_rays) break_ray(lattice, broken, deg, 1.1);
  return broken;
}

}  // namespace

TEST_CASE("Four radial cracks through the lattice are four radial fractures reaching the outer boundary",
          "[lattice2d][fracture_statistics]") {
  const Lattice& lattice = annulus();
  const double L = mean_beam(lattice);
  const std::vector<bool> broken = four_cracks(lattice);
  const FractureStatistics s = compute_fracture_statistics(lattice, broken);
  CHECK(s.n_broken == std::count(broken.begin(), broken.end(), true));
  CHECK(s.n_broken > 4 * 20);  // each ray crosses ~0.97 / L > 25 beams
  CHECK(s.n_fractures == 4);
  CHECK(s.n_radial == 4);
  CHECK(s.n_radial_reaching_outer == 4);
  CHECK(s.n_secondary == 0);
  CHECK(s.n_arms == 4);
  CHECK(s.arm_radius == hm::test::roundoff(R_i + 0.25 * (1 - R_i)));
  CHECK(s.n_tensile == 0);
  CHECK(s.n_shear == 0);
  REQUIRE(s.fractures.size() == 4);
  for (double deg : four_rays) {
    const Fracture& f = fracture_near(s, deg);
    INFO("ray at " << deg << " deg, fracture " << f.id << " at " << f.angle_deg << " deg");
    // The broken beams zig-zag about the ray by under a beam length; their mean direction is within
    // a few degrees of it (3 deg ~ 0.8 L at r = 0.5).
    CHECK(angle_difference(f.angle_deg, deg) < 3.0);
    CHECK(f.kind == FractureKind::radial);
    CHECK(f.connected_to_borehole);
    CHECK(f.reaches_outer);
    CHECK(f.r_min < R_i);  // the broken wall chord's midpoint lies inside the wall circle
    CHECK(f.r_min > R_i - L);
    CHECK(f.r_max > 1.0 - L);  // the broken outer chord
    CHECK(f.r_max < 1.0);
    CHECK(f.length == hm::test::roundoff(f.r_max - f.r_min));
    CHECK(f.angle_deg >= 0.0);
    CHECK(f.angle_deg < 360.0);
  }
  CHECK(s.max_radial_extent == std::max_element(s.fractures.begin(), s.fractures.end(), [](auto& a, auto& b) {
                                 return a.r_max < b.r_max;
                               })->r_max);
}

TEST_CASE("Half-length radial cracks stop where the rays end", "[lattice2d][fracture_statistics]") {
  const Lattice& lattice = annulus();
  const double L = mean_beam(lattice);
  const double r_end = R_i + 0.5 * (1.0 - R_i);
  std::vector<bool> broken(static_cast<std::size_t>(lattice.n_beams()), false);
  for (double deg : {30.21, 150.21, 270.21}) break_ray(lattice, broken, deg, r_end);
  const FractureStatistics s = compute_fracture_statistics(lattice, broken);
  CHECK(s.n_fractures == 3);
  CHECK(s.n_radial == 3);
  CHECK(s.n_radial_reaching_outer == 0);
  CHECK(s.n_secondary == 0);
  CHECK(s.n_arms == 3);  // the arm circle r = 0.35 lies inside the cracks (they end at 0.57)
  for (const Fracture& f : s.fractures) {
    CHECK_FALSE(f.reaches_outer);
    // The last broken beam crosses the ray within a beam length of its end; its midpoint is within
    // half a beam length more.
    CHECK(std::abs(f.r_max - r_end) < 2.0 * L);
    CHECK(f.length == Approx(r_end - R_i).margin(2.0 * L));
  }
  CHECK(std::abs(s.max_radial_extent - r_end) < 2.0 * L);
}

TEST_CASE("A crack away from the borehole is one secondary fracture", "[lattice2d][fracture_statistics]") {
  const Lattice& lattice = annulus();
  const double L = mean_beam(lattice);
  std::vector<bool> broken(static_cast<std::size_t>(lattice.n_beams()), false);
  break_segment(lattice, broken, polar(0.5, 45.1), polar(0.7, 45.1));
  const FractureStatistics s = compute_fracture_statistics(lattice, broken);
  CHECK(s.n_fractures == 1);
  CHECK(s.n_radial == 0);
  CHECK(s.n_secondary == 1);
  CHECK(s.n_arms == 0);  // nothing crosses r = 0.35
  CHECK(s.max_radial_extent == 0.0);
  REQUIRE(s.fractures.size() == 1);
  const Fracture& f = s.fractures[0];
  CHECK(f.kind == FractureKind::secondary);
  CHECK(hm::core::name_of(f.kind) == "secondary");
  CHECK_FALSE(f.connected_to_borehole);
  CHECK_FALSE(f.reaches_outer);
  CHECK(f.r_min == Approx(0.5).margin(L));  // midpoints within L/2 of the segment, which ends at 0.5 and 0.7
  CHECK(f.r_max == Approx(0.7).margin(L));
  CHECK(f.length == Approx(0.2).margin(2.0 * L));
  CHECK(angle_difference(f.angle_deg, 45.1) < 3.0);
  // A straight crack: its bounding box's diagonal is its length, 0.2 (midpoints within L/2 of the ends).
  CHECK(f.extent == Approx(0.2).margin(2.0 * L));
  CHECK(s.n_secondary_sizable == 1);  // 0.2 >= 0.05
  FractureStatisticsOptions strict;
  strict.sizable_extent = 0.3;
  CHECK(compute_fracture_statistics(lattice, broken, {}, strict).n_secondary_sizable == 0);
  // One broken beam alone is a secondary fracture, too short to be sizable.
  std::vector<bool> one(broken.size(), false);
  one[static_cast<std::size_t>(s.fractures[0].beams[0])] = true;
  const FractureStatistics single = compute_fracture_statistics(lattice, one);
  CHECK(single.n_secondary == 1);
  CHECK(single.n_secondary_sizable == 0);
  CHECK(single.fractures[0].extent == 0.0);
}

TEST_CASE("No broken beam gives empty statistics", "[lattice2d][fracture_statistics]") {
  const Lattice& lattice = annulus();
  const std::vector<BeamState> states(static_cast<std::size_t>(lattice.n_beams()), BeamState::intact);
  const FractureStatistics s = compute_fracture_statistics(lattice, states);
  CHECK(s.fractures.empty());
  CHECK(s.n_broken == 0);
  CHECK(s.n_fractures == 0);
  CHECK(s.n_radial == 0);
  CHECK(s.n_radial_reaching_outer == 0);
  CHECK(s.n_secondary == 0);
  CHECK(s.n_arms == 0);
  CHECK(s.n_tensile == 0);
  CHECK(s.n_shear == 0);
  CHECK(s.max_radial_extent == 0.0);
}

TEST_CASE("Two cracks from one wall point are one fracture with two arms away from the wall",
          "[lattice2d][fracture_statistics]") {
  // Both rays start at the same point just inside the midpoint of the wall chord nearest angle 0, so
  // they cut that chord and its triangle: one cluster. Away from the wall they are 28 deg apart, two arms.
  const Lattice& lattice = annulus();
  std::vector<bool> broken(static_cast<std::size_t>(lattice.n_beams()), false);
  Eigen::Vector2d chord_midpoint(0.0, 0.0);
  for (int e = 0; e < lattice.n_beams(); ++e) {
    if (lattice.beam_boundary[static_cast<std::size_t>(e)] != BoundaryTag::inner) continue;
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    const Eigen::Vector2d m = 0.5 * (lattice.points.col(i) + lattice.points.col(j));
    if (m.x() > 0 && (chord_midpoint.isZero() || std::abs(m.y()) < std::abs(chord_midpoint.y()))) chord_midpoint = m;
  }
  const Eigen::Vector2d wall = 0.995 * chord_midpoint;
  break_segment(lattice, broken, wall, polar(1.1, 14.0));
  break_segment(lattice, broken, wall, polar(1.1, -14.0));

  FractureStatisticsOptions far;
  far.arm_radius_fraction = 0.75;  // r = 0.79: the rays are ~0.3 = 10 L apart
  const FractureStatistics s = compute_fracture_statistics(lattice, broken, {}, far);
  CHECK(s.n_fractures == 1);
  CHECK(s.n_radial == 1);
  CHECK(s.n_radial_reaching_outer == 1);
  CHECK(s.n_arms == 2);
  REQUIRE(s.fractures.size() == 1);
  CHECK(angle_difference(s.fractures[0].angle_deg, 0.0) < 3.0);  // symmetric pair: mean direction 0

  // Next to the wall (r = 0.155) the rays are under a beam length apart: one arm.
  FractureStatisticsOptions near;
  near.arm_radius_fraction = 0.02;
  CHECK(compute_fracture_statistics(lattice, broken, {}, near).n_arms == 1);
  const double three_beams = arm_gap_of_beams(lattice);
  CHECK(count_crossings(lattice, broken, arm_radius(lattice, near), three_beams) == 1);
  CHECK(count_crossings(lattice, broken, arm_radius(lattice, far), three_beams) == 2);
  // A gap wider than the rays' separation at r = 0.79 merges the two arms.
  CHECK(count_crossings(lattice, broken, arm_radius(lattice, far), 20.0 * three_beams / 3.0) == 1);
  CHECK(count_crossings(lattice, broken, 1.5, three_beams) == 0);  // outside the domain
}

TEST_CASE("The fixed gap counts arms by their distance in R, whatever the beam length",
          "[lattice2d][fracture_statistics]") {
  // Two straight radial cracks from r = 0.3 out to the surface, 6 degrees apart (off the
  // boundary particles' angles): 0.083 apart along
  // the arm circle r = 0.79.
  for (long long n : {3000LL, 12000LL}) {
    const Lattice lattice = hm::test::make_lattice(DomainShape::annulus, n);
    std::vector<bool> broken(static_cast<std::size_t>(lattice.n_beams()), false);
    break_segment(lattice, broken, polar(0.3, 87.1), polar(1.1, 87.1));
    break_segment(lattice, broken, polar(0.3, 93.1), polar(1.1, 93.1));
    FractureStatisticsOptions options;
    options.arm_radius_fraction = 0.75;
    INFO("N = " << n << ", mean beam length " << lattice.length.mean());
    const FractureStatistics s = compute_fracture_statistics(lattice, broken, {}, options);
    CHECK(s.n_arms_fixed_gap == 2);  // 0.083 apart > the 0.03 gap at both N
    options.arm_gap = 0.1;
    CHECK(compute_fracture_statistics(lattice, broken, {}, options).n_arms_fixed_gap == 1);
    // The beam-length gap merges them at N = 3000 (3 beams ~ 0.1) but not at 12000 (~0.05): the count
    // that depends on N.
    CHECK(s.n_arms == (n == 3000 ? 1 : 2));
  }
}

TEST_CASE("Beams are connected through a shared particle, or only through a shared triangle when asked",
          "[lattice2d][fracture_statistics]") {
  const Lattice& lattice = annulus();
  // An interior particle and its beams; two beams of one triangle at it are adjacent in its fan.
  int centre = -1;
  std::vector<int> fan;
  for (int i = 0; i < lattice.n_particles() && centre < 0; ++i) {
    if (lattice.boundary[static_cast<std::size_t>(i)] != BoundaryTag::interior) continue;
    fan.clear();
    for (int e = 0; e < lattice.n_beams(); ++e)
      if (lattice.beams[static_cast<std::size_t>(e)][0] == i || lattice.beams[static_cast<std::size_t>(e)][1] == i)
        fan.push_back(e);
    if (fan.size() >= 5) centre = i;
  }
  REQUIRE(centre >= 0);
  const auto share_triangle = [&](int a, int b) {
    for (int ta : lattice.beam_triangles[static_cast<std::size_t>(a)])
      for (int tb : lattice.beam_triangles[static_cast<std::size_t>(b)])
        if (ta >= 0 && ta == tb) return true;
    return false;
  };
  int adjacent = -1, opposite = -1;
  for (std::size_t k = 1; k < fan.size(); ++k) {
    if (share_triangle(fan[0], fan[k]) && adjacent < 0) adjacent = fan[k];
    if (!share_triangle(fan[0], fan[k]) && opposite < 0) opposite = fan[k];
  }
  REQUIRE(adjacent >= 0);
  REQUIRE(opposite >= 0);
  // A beam at opposite's far end that touches neither fan[0] nor the centre.
  const auto far_end = [&](int e) {
    const auto& b = lattice.beams[static_cast<std::size_t>(e)];
    return b[0] == centre ? b[1] : b[0];
  };
  const int step_out = far_end(opposite);
  int beyond = -1;
  for (int e = 0; e < lattice.n_beams() && beyond < 0; ++e) {
    const auto& b = lattice.beams[static_cast<std::size_t>(e)];
    const auto touches = [&](int i) { return b[0] == i || b[1] == i; };
    if (touches(step_out) && !touches(centre) && !touches(far_end(fan[0]))) beyond = e;
  }
  REQUIRE(beyond >= 0);

  FractureStatisticsOptions triangle;
  triangle.link = FractureLink::shared_triangle;
  const FractureStatisticsOptions particle{};
  REQUIRE(particle.link == FractureLink::shared_particle);  // the default
  std::vector<bool> broken(static_cast<std::size_t>(lattice.n_beams()), false);
  const auto count = [&](const FractureStatisticsOptions& o) {
    return compute_fracture_statistics(lattice, broken, {}, o).n_fractures;
  };
  // Two beams at one particle in no common triangle: an en-echelon step, one fracture by particle.
  broken[static_cast<std::size_t>(fan[0])] = broken[static_cast<std::size_t>(opposite)] = true;
  CHECK(count(triangle) == 2);
  CHECK(count(particle) == 1);
  // A chain fan[0] - opposite - beyond is linked particle to particle; beyond shares no triangle with fan[0].
  broken[static_cast<std::size_t>(beyond)] = true;
  CHECK(count(particle) == 1);
  CHECK(count(triangle) == (share_triangle(opposite, beyond) ? 2 : 3));
  // Without the middle beam nothing joins fan[0] and beyond under either rule.
  broken[static_cast<std::size_t>(opposite)] = false;
  CHECK(count(particle) == 2);
  CHECK(count(triangle) == 2);
  // Two edges of one triangle are one fracture under both rules.
  broken.assign(broken.size(), false);
  broken[static_cast<std::size_t>(fan[0])] = broken[static_cast<std::size_t>(adjacent)] = true;
  CHECK(count(particle) == 1);
  CHECK(count(triangle) == 1);

  CHECK(hm::core::name_of(FractureLink::shared_particle) == "particle");
  CHECK(hm::core::name_of(FractureLink::shared_triangle) == "triangle");
}

TEST_CASE("Softened beams link the broken parts of one crack but are not counted as broken",
          "[lattice2d][fracture_statistics]") {
  const Lattice& lattice = annulus();
  // One crack from the borehole through the outer boundary, with a ligament of two beam lengths at
  // r = 0.5 ... 0.56 left on its teeth: softened, not broken.
  std::vector<bool> broken(static_cast<std::size_t>(lattice.n_beams()), false);
  break_ray(lattice, broken, 0.37, 1.1);
  std::vector<bool> ligament(broken.size(), false);
  break_segment(lattice, ligament, polar(0.5, 0.37), polar(0.56, 0.37));
  std::vector<bool> softened(broken.size(), false);
  for (std::size_t e = 0; e < broken.size(); ++e)
    if (ligament[e]) {
      broken[e] = false;
      softened[e] = true;
    }
  // A patch of softened beams away from the crack, and softened flags on broken beams: neither is a fracture.
  break_segment(lattice, softened, polar(0.5, 200.37), polar(0.6, 200.37));
  for (std::size_t e = 0; e < broken.size(); ++e)
    if (broken[e] && e % 3 == 0) softened[e] = true;
  const int n_broken = static_cast<int>(std::count(broken.begin(), broken.end(), true));

  FractureStatisticsOptions ignore;
  ignore.softened = SoftenedBeams::ignore;
  const FractureStatistics apart = compute_fracture_statistics(lattice, broken, {}, ignore, softened);
  REQUIRE(apart.n_fractures == 2);  // the ligament splits the crack into a radial part and a secondary
  CHECK(apart.n_radial == 1);
  CHECK(apart.n_radial_reaching_outer == 0);
  CHECK(apart.max_radial_extent < 0.5);

  const FractureStatisticsOptions link{};
  REQUIRE(link.softened == SoftenedBeams::link);  // the default
  const FractureStatistics joined = compute_fracture_statistics(lattice, broken, {}, link, softened);
  CHECK(joined.n_fractures == 1);
  CHECK(joined.n_radial == 1);
  CHECK(joined.n_radial_reaching_outer == 1);
  CHECK(joined.max_radial_extent > 0.95);
  // Only broken beams are members: the same beams, broken count and arms as without the link.
  CHECK(joined.n_broken == n_broken);
  CHECK(joined.n_broken == apart.n_broken);
  CHECK(joined.fractures[0].n_beams() == n_broken);
  CHECK(joined.n_arms == apart.n_arms);
  // Without softened flags, link is ignore.
  CHECK(compute_fracture_statistics(lattice, broken, {}, link).n_fractures == 2);
  CHECK_THROWS_AS(compute_fracture_statistics(lattice, broken, {}, link, std::vector<bool>(3, false)), hm::InputError);

  CHECK(hm::core::name_of(SoftenedBeams::link) == "link");
  CHECK(hm::core::name_of(SoftenedBeams::ignore) == "ignore");
}

TEST_CASE("The tooth log gives the beams softened by a time", "[lattice2d][fracture_statistics]") {
  std::vector<ToothEvent> teeth(3);
  teeth[0].beam = 4, teeth[0].load = 1.0;
  teeth[1].beam = 2, teeth[1].load = 2.0;
  teeth[2].beam = 4, teeth[2].load = 3.0;  // a later tooth of the same beam
  CHECK(softened_flags(teeth, 6, 0.5) == std::vector<bool>(6, false));
  CHECK(softened_flags(teeth, 6, 1.0) == std::vector<bool>{false, false, false, false, true, false});
  CHECK(softened_flags(teeth, 6, 2.5) == std::vector<bool>{false, false, true, false, true, false});
  teeth[1].beam = 6;
  CHECK_THROWS_AS(softened_flags(teeth, 6, 2.5), hm::InputError);
}

TEST_CASE("The break log gives each fracture's tensile and shear counts", "[lattice2d][fracture_statistics]") {
  const Lattice& lattice = annulus();
  const std::vector<bool> broken = four_cracks(lattice);
  const FractureStatistics plain = compute_fracture_statistics(lattice, broken);
  REQUIRE(plain.n_fractures == 4);
  const Fracture& f0 = fracture_near(plain, 0.0);
  const Fracture& f90 = fracture_near(plain, 90.0);
  const Fracture& f180 = fracture_near(plain, 180.0);

  // f0 all tensile, f90 all shear, f180 alternating (first tensile), the fourth not logged.
  std::vector<BreakEvent> log;
  const auto add = [&](int beam, FailureMode mode) {
    BreakEvent ev;
    ev.sequence = static_cast<int>(log.size());
    ev.beam = beam;
    ev.mode = mode;
    log.push_back(ev);
  };
  for (int e : f0.beams) add(e, FailureMode::tensile);
  for (int e : f90.beams) add(e, FailureMode::shear);
  for (std::size_t k = 0; k < f180.beams.size(); ++k)
    add(f180.beams[k], k % 2 == 0 ? FailureMode::tensile : FailureMode::shear);
  add(f0.beams.front(), FailureMode::shear);  // a beam logged twice counts once, by its first event
  const auto intact = std::find(broken.begin(), broken.end(), false) - broken.begin();
  add(static_cast<int>(intact), FailureMode::shear);  // a later break, not in this snapshot: ignored

  const FractureStatistics s = compute_fracture_statistics(lattice, broken, log);
  const int n180 = f180.n_beams();
  CHECK(fracture_near(s, 0.0).n_tensile == f0.n_beams());
  CHECK(fracture_near(s, 0.0).n_shear == 0);
  CHECK(fracture_near(s, 90.0).n_tensile == 0);
  CHECK(fracture_near(s, 90.0).n_shear == f90.n_beams());
  CHECK(fracture_near(s, 180.0).n_tensile == (n180 + 1) / 2);
  CHECK(fracture_near(s, 180.0).n_shear == n180 / 2);
  CHECK(fracture_near(s, 270.0).n_tensile == 0);
  CHECK(fracture_near(s, 270.0).n_shear == 0);
  CHECK(s.n_tensile == f0.n_beams() + (n180 + 1) / 2);
  CHECK(s.n_shear == f90.n_beams() + n180 / 2);

  log.back().beam = lattice.n_beams();
  CHECK_THROWS_AS(compute_fracture_statistics(lattice, broken, log), hm::InputError);
}

TEST_CASE("Fracture tables are written as CSV and bad options are rejected", "[lattice2d][fracture_statistics]") {
  const Lattice& lattice = annulus();
  const std::vector<bool> none(static_cast<std::size_t>(lattice.n_beams()), false);
  const std::vector<bool> four = four_cracks(lattice);
  const std::vector<FractureSnapshot> snaps{{0.0, compute_fracture_statistics(lattice, none)},
                                            {1.5, compute_fracture_statistics(lattice, four)}};
  const auto dir = std::filesystem::temp_directory_path() / ("hm_fstat_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);

  write_fracture_table(dir / "fractures.csv", snaps);
  const auto table = hm::test::lines_of(dir / "fractures.csv");
  REQUIRE(table.size() == 1 + 4);  // the empty snapshot has no rows
  CHECK(table[0] ==
        "t,fracture,kind,n_beams,connected_to_borehole,reaches_outer,r_min,r_max,length,angle_deg,n_tensile,n_shear,"
        "extent");
  const Fracture& first = snaps[1].stats.fractures[0];
  CHECK(table[1].rfind("1.5,0,radial," + std::to_string(first.n_beams()) + ",1,1,", 0) == 0);
  const std::string tail = table[1].substr(table[1].rfind(',') + 1);  // extent, after n_tensile, n_shear = 0, 0
  CHECK(std::stod(tail) == Approx(first.extent).epsilon(1e-9));
  CHECK(table[1].substr(table[1].size() - tail.size() - 5, 5) == ",0,0,");

  write_fracture_summary(dir / "summary.csv", snaps);
  const auto summary = hm::test::lines_of(dir / "summary.csv");
  REQUIRE(summary.size() == 1 + 2);
  CHECK(summary[0] ==
        "t,n_broken,n_fractures,n_radial,n_radial_reaching_outer,n_secondary,n_arms,n_tensile,n_shear,"
        "max_radial_extent,n_secondary_sizable,n_arms_fixed_gap");
  CHECK(summary[1] == "0,0,0,0,0,0,0,0,0,0,0,0");
  CHECK(summary[2].rfind("1.5," + std::to_string(snaps[1].stats.n_broken) + ",4,4,4,0,4,0,0,", 0) == 0);
  CHECK_FALSE(std::filesystem::exists(dir / "summary.csv.partial"));
  CHECK_THROWS_AS(write_fracture_summary(dir / "no_such_dir" / "summary.csv", snaps), std::runtime_error);
  std::filesystem::remove_all(dir);

  auto message = [&](const FractureStatisticsOptions& o) {
    try {
      compute_fracture_statistics(lattice, none, {}, o);
    } catch (const hm::InputError& e) {
      return std::string(e.what());
    }
    return std::string("no throw");
  };
  CHECK_NOTHROW(FractureStatisticsOptions{}.validate());
  FractureStatisticsOptions o;
  o.arm_radius_fraction = 0.0;
  CHECK(message(o) ==
        "fracture_statistics.arm_radius_fraction = 0, allowed: 0 < fracture_statistics.arm_radius_fraction < 1");
  o.arm_radius_fraction = 1.0;
  CHECK(message(o).rfind("fracture_statistics.arm_radius_fraction = 1, allowed:", 0) == 0);
  o = {};
  o.arm_gap_beams = -1.0;
  CHECK(message(o) == "fracture_statistics.arm_gap_beams = -1, allowed: fracture_statistics.arm_gap_beams > 0");
  o = {};
  o.sizable_extent = -0.1;
  CHECK(message(o).rfind("fracture_statistics.sizable_extent = -0.1, allowed:", 0) == 0);
  CHECK_THROWS_AS(compute_fracture_statistics(lattice, std::vector<bool>(3, false)), hm::InputError);
  o = {};
  o.arm_gap = 0.0;
  CHECK(message(o) == "fracture_statistics.arm_gap = 0, allowed: fracture_statistics.arm_gap > 0");
  CHECK_THROWS_AS(count_crossings(lattice, none, 0.0, 0.03), hm::InputError);
}

TEST_CASE("Fracture statistics are deterministic and ordered by smallest beam", "[lattice2d][fracture_statistics]") {
  const Lattice& lattice = annulus();
  std::vector<bool> broken = four_cracks(lattice);
  break_segment(lattice, broken, polar(0.5, 45.1), polar(0.7, 45.1));
  // The same pattern as beam states (open and contact both count as broken) on a regenerated lattice.
  const Lattice again = hm::test::make_lattice(DomainShape::annulus, 4000, 3);
  std::vector<BeamState> states(broken.size(), BeamState::intact);
  for (std::size_t e = 0; e < broken.size(); ++e)
    if (broken[e]) states[e] = e % 2 ? BeamState::open : BeamState::contact;
  CHECK(broken_flags(states) == broken);

  const FractureStatistics a = compute_fracture_statistics(lattice, broken);
  const FractureStatistics b = compute_fracture_statistics(again, states);
  REQUIRE(a.n_fractures == 5);
  CHECK(a.n_secondary == 1);
  REQUIRE(b.fractures.size() == a.fractures.size());
  for (std::size_t k = 0; k < a.fractures.size(); ++k) {
    const Fracture &fa = a.fractures[k], &fb = b.fractures[k];
    CHECK(fa.id == static_cast<int>(k));
    CHECK(fb.id == fa.id);
    CHECK(fb.beams == fa.beams);
    CHECK(std::is_sorted(fa.beams.begin(), fa.beams.end()));
    if (k > 0) CHECK(fa.beams.front() > a.fractures[k - 1].beams.front());
    CHECK(fb.kind == fa.kind);
    CHECK(fb.r_min == fa.r_min);
    CHECK(fb.r_max == fa.r_max);
    CHECK(fb.angle_deg == fa.angle_deg);
  }
  CHECK(b.n_arms == a.n_arms);
  CHECK(b.n_broken == a.n_broken);
}
