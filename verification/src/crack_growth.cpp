#include "crack_growth.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

#include "hm/lattice2d/fracture/notch.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"

namespace hm::verification {

namespace l2 = hm::lattice2d;

namespace {

// The triangles on either side of the broken beams.
std::vector<int> crack_triangles(const l2::Lattice& lattice, const std::vector<int>& crack) {
  std::vector<int> triangles;
  for (int e : crack)
    for (int t : lattice.beam_triangles[static_cast<std::size_t>(e)])
      if (t >= 0) triangles.push_back(t);
  return triangles;
}

}  // namespace

double crack_half_length(const l2::DualGraph& dual, const std::vector<int>& triangles) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int t : triangles) lo = std::min(lo, dual.dual_point(0, t)), hi = std::max(hi, dual.dual_point(0, t));
  return triangles.empty() ? 0.0 : 0.5 * (hi - lo);
}

CrackGrowthRun grow_pressurised_crack(const CrackGrowthSpec& spec) {
  const auto start = std::chrono::steady_clock::now();
  l2::LatticeSpec ls;
  ls.domain = l2::DomainShape::disk;
  ls.n_particles = spec.n_particles;
  ls.seed = spec.lattice_seed;
  const l2::Lattice lattice = l2::generate_lattice(ls);
  const l2::DualGraph dual = l2::build_dual_graph(lattice);
  const l2::BeamParameters parameters = l2::calibrated_beam_parameters();
  l2::BeamMechanics m(lattice, parameters, l2::BoundaryConditions{});
  l2::StrengthSpec strength_spec;  // Table 1's T_u, C_u, mu_i; uniform +-5%
  strength_spec.seed = spec.strength_seed;
  const l2::BeamStrengths strengths = l2::draw_beam_strengths(strength_spec, lattice.n_beams());
  std::unique_ptr<l2::SawtoothLaw> law;
  if (spec.fracture_energy > 0.0) {
    l2::SawtoothLawOptions o;
    o.fracture_energy = spec.fracture_energy;
    o.teeth = spec.teeth;
    o.strength_factor = spec.strength_factor;
    law = std::make_unique<l2::SawtoothLaw>(lattice, dual, parameters, strengths, o);
  }
  std::vector<int> crack = l2::beams_crossing(lattice, l2::NotchSegment{{-spec.notch_half_length, 0.0},
                                                                         {spec.notch_half_length, 0.0}});
  for (int e : crack) m.break_beam(e);

  CrackGrowthRun run;
  const std::size_t n_teeth = static_cast<std::size_t>(spec.teeth.n_teeth);
  run.released_by_tooth.assign(n_teeth, 0.0);
  run.booked_by_tooth.assign(n_teeth, 0.0);
  std::vector<l2::BreakEvent> breaks;
  std::vector<l2::ToothEvent> teeth;
  l2::BreakLoopOptions one_event;
  one_event.max_breaks = 1;
  // One solve (stress scale 0: nothing fails) or one event at `pressure`: the break loop of the law.
  const auto break_loop = [&](double pressure, double volume) {
    const std::size_t broken_before = breaks.size();
    const l2::BreakLoopSummary s =
        law ? l2::break_until_stable(m, dual, strengths, *law, one_event, volume, breaks, teeth, pressure)
            : l2::break_until_stable(m, dual, strengths, one_event, volume, breaks, pressure);
    run.n_solves += s.n_solves;
    for (std::size_t k = broken_before; k < breaks.size(); ++k) crack.push_back(breaks[k].beam);
    return s;
  };
  double volume = 0.0, work = 0.0;
  int last_tooth = -1;  // tooth of the last event, until the next solve shows what it released
  double pressure_before = 0.0, booked_last = 0.0;
  std::vector<int> faces;
  std::vector<double> weights;
  while (run.n_events < spec.max_events) {
    faces = crack;
    weights.assign(crack.size(), 1.0);
    if (law && spec.faces == PressurisedFaces::with_softening)
      for (int e = 0; e < lattice.n_beams(); ++e)
        if (law->tooth(e) > 0 && m.states()[static_cast<std::size_t>(e)] == l2::BeamState::intact) {
          faces.push_back(e);
          weights.push_back(1.0 - m.stiffness_factor(e));
        }
    m.set_external_forces(l2::crack_face_forces(lattice, dual, faces, 1.0, weights));
    const l2::BreakLoopSummary probe = break_loop(0.0, volume);
    // V_1 = f_1 . u_1 (= the faces' openings x facets x weights); the self-equilibrated load does no
    // work on the gauge's rigid motion.
    const double v_1 = m.loads().dot(m.displacement()), r_1 = probe.max_reference_ratio;
    if (!(v_1 > 0.0 && r_1 > 0.0)) break;
    if (last_tooth >= 0) {  // the last event's release at fixed V: (1/2) V (p before - p after)
      run.released_by_tooth[static_cast<std::size_t>(last_tooth)] += 0.5 * volume * (pressure_before - volume / v_1);
      run.booked_by_tooth[static_cast<std::size_t>(last_tooth)] += booked_last;
      last_tooth = -1;
    }
    const double c = crack_half_length(dual, crack_triangles(lattice, crack));
    if (c > spec.max_half_length) {
      run.reached = true;
      break;
    }
    double pressure = volume / v_1;
    if (pressure * r_1 < 1.0) {  // no event due at this volume: raise it to the next event's
      pressure = (1.0 / r_1) * (1.0 + 1e-9);
      const double next_volume = pressure * v_1;
      work += 0.5 * (volume / v_1 + pressure) * (next_volume - volume);  // p linear in V on this state
      volume = next_volume;
      run.points.push_back({volume, pressure, c, law ? law->dissipated_energy() : 0.0, work,
                            static_cast<int>(crack.size())});
    }
    const std::size_t teeth_before = teeth.size();
    const l2::BreakLoopSummary s = break_loop(pressure, volume);
    if (s.n_breaks + s.n_teeth == 0) break;  // cannot happen: a ratio >= 1 was due
    ++run.n_events;
    if (teeth.size() > teeth_before) {
      last_tooth = teeth.back().tooth;
      pressure_before = pressure;
      booked_last = teeth.back().energy;
    }
  }
  run.n_broken = static_cast<int>(crack.size());
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

}  // namespace hm::verification
