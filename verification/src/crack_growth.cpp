#include "crack_growth.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

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

l2::Lattice disk_lattice(const CrackGrowthSpec& spec) {
  l2::LatticeSpec ls;
  ls.domain = l2::DomainShape::disk;
  ls.n_particles = spec.n_particles;
  ls.seed = spec.lattice_seed;
  return l2::generate_lattice(ls);
}

l2::BeamStrengths drawn_strengths(const CrackGrowthSpec& spec, int n_beams) {
  l2::StrengthSpec strength_spec;  // Table 1's T_u, C_u, mu_i; uniform +-5%
  strength_spec.seed = spec.strength_seed;
  return l2::draw_beam_strengths(strength_spec, n_beams);
}

// What both paths grow: the disk with its notch cut, the law, the crack's faces and the run's books.
struct Growth {
  const CrackGrowthSpec& spec;
  const std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  const l2::Lattice lattice;
  const l2::DualGraph dual;
  const l2::BeamParameters parameters = l2::calibrated_beam_parameters();
  l2::BeamMechanics m;
  const l2::BeamStrengths strengths;
  std::unique_ptr<l2::SawtoothLaw> law;
  std::vector<int> crack;  // the broken beams, the notch's first
  CrackGrowthRun run;
  double volume = 0.0, work = 0.0, mechanical_work = 0.0;
  Eigen::VectorXd f_before, u_before;  // the last accounted state's load and displacement

  explicit Growth(const CrackGrowthSpec& s)
      : spec(s),
        lattice(disk_lattice(s)),
        dual(l2::build_dual_graph(lattice)),
        m(lattice, parameters, l2::BoundaryConditions{}),
        strengths(drawn_strengths(s, lattice.n_beams())) {
    if (spec.fracture_energy > 0.0) {
      l2::SawtoothLawOptions o;
      o.fracture_energy = spec.fracture_energy;
      o.teeth = spec.teeth;
      o.strength_factor = spec.strength_factor;
      law = std::make_unique<l2::SawtoothLaw>(lattice, dual, parameters, strengths, o);
    }
    crack =
        l2::beams_crossing(lattice, l2::NotchSegment{{-spec.notch_half_length, 0.0}, {spec.notch_half_length, 0.0}});
    for (int e : crack) m.break_beam(e);
    f_before = u_before = Eigen::VectorXd::Zero(3 * lattice.n_particles());
  }

  // The load at p = 1 on the crack's faces: the broken beams', and the softening beams' by their damage
  // 1 - s where spec.faces says so.
  void load_faces() {
    std::vector<int> faces = crack;
    std::vector<double> weights(crack.size(), 1.0);
    if (spec.faces == PressurisedFaces::with_softening)
      for (int e = 0; e < lattice.n_beams(); ++e)
        if (m.stiffness_factor(e) < 1.0 && m.states()[static_cast<std::size_t>(e)] == l2::BeamState::intact) {
          faces.push_back(e);
          weights.push_back(1.0 - m.stiffness_factor(e));
        }
    m.set_external_forces(l2::crack_face_forces(lattice, dual, faces, 1.0, weights));
  }

  // The pressure's work on the solid up to the solved state (at p = 1) held at `pressure`: the
  // trapezoid from the last accounted state, exact when the state is the same (f and u both in p).
  void account_mechanical_work(double pressure) {
    const Eigen::VectorXd f = pressure * m.loads(), u = pressure * m.displacement();
    mechanical_work += 0.5 * (f_before + f).dot(u - u_before);
    f_before = f;
    u_before = u;
  }

  double half_length() const { return crack_half_length(dual, crack_triangles(lattice, crack)); }

  void record(double pressure, double booked) {
    run.points.push_back({.volume = volume,
                          .pressure = pressure,
                          .half_length = half_length(),
                          .booked = booked,
                          .work = work,
                          .mechanical_work = mechanical_work,
                          .n_broken = static_cast<int>(crack.size())});
  }

  CrackGrowthRun finish() {
    run.n_broken = static_cast<int>(crack.size());
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return std::move(run);
  }
};

CrackGrowthRun grow_by_events(const CrackGrowthSpec& spec) {
  Growth g(spec);
  l2::BeamMechanics& m = g.m;
  CrackGrowthRun& run = g.run;
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
        g.law ? l2::break_until_stable(m, g.dual, g.strengths, *g.law, one_event, volume, breaks, teeth, pressure)
              : l2::break_until_stable(m, g.dual, g.strengths, one_event, volume, breaks, pressure);
    run.n_solves += s.n_solves;
    for (std::size_t k = broken_before; k < breaks.size(); ++k) g.crack.push_back(breaks[k].beam);
    return s;
  };
  double& volume = g.volume;
  int last_tooth = -1;  // tooth of the last event, until the next solve shows what it released
  double pressure_before = 0.0, booked_last = 0.0;
  while (run.n_events < spec.max_events) {
    g.load_faces();
    const l2::BreakLoopSummary probe = break_loop(0.0, volume);
    // V_1 = f_1 . u_1 (= the faces' openings x facets x weights); the self-equilibrated load does no
    // work on the gauge's rigid motion.
    const double v_1 = m.loads().dot(m.displacement()), r_1 = probe.max_reference_ratio;
    if (!(v_1 > 0.0 && r_1 > 0.0)) break;
    g.account_mechanical_work(volume / v_1);
    if (last_tooth >= 0) {  // the last event's release at fixed V: (1/2) V (p before - p after)
      run.released_by_tooth[static_cast<std::size_t>(last_tooth)] += 0.5 * volume * (pressure_before - volume / v_1);
      run.booked_by_tooth[static_cast<std::size_t>(last_tooth)] += booked_last;
      last_tooth = -1;
    }
    if (g.half_length() > spec.max_half_length) {
      run.reached = true;
      break;
    }
    double pressure = volume / v_1;
    if (pressure * r_1 < 1.0) {  // no event due at this volume: raise it to the next event's
      pressure = (1.0 / r_1) * (1.0 + 1e-9);
      const double next_volume = pressure * v_1;
      g.work += 0.5 * (volume / v_1 + pressure) * (next_volume - volume);  // p linear in V on this state
      volume = next_volume;
      g.account_mechanical_work(pressure);
      g.record(pressure, g.law ? g.law->dissipated_energy() : 0.0);
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
  return g.finish();
}

// Shear (Eq. 11) is not checked on this path: the crack opens in tension, and the teeth path's Griffith
// growth breaks no beam in shear.
CrackGrowthRun grow_continuously(const CrackGrowthSpec& spec) {
  Growth g(spec);
  l2::BeamMechanics& m = g.m;
  const l2::Lattice& lattice = g.lattice;
  const int n_beams = lattice.n_beams();
  std::vector<l2::LinearSoftening> envelope;
  std::vector<double> beam_volume;  // d L
  for (int e = 0; e < n_beams; ++e) {
    envelope.push_back(g.law->envelope(e));
    beam_volume.push_back(g.law->section(e) * lattice.length[e]);
  }
  std::vector<double> history(static_cast<std::size_t>(n_beams), 0.0);  // largest strain past the peak; 0: none
  Eigen::VectorXd strain(n_beams);  // axial strain (elongation over L) of each intact beam at p = 1
  const auto probe = [&]() {
    g.load_faces();
    m.solve(false);
    ++g.run.n_solves;
    const Eigen::VectorXd& u = m.displacement();
    for (int e = 0; e < n_beams; ++e)
      strain[e] = m.states()[static_cast<std::size_t>(e)] == l2::BeamState::intact
                      ? l2::normal_elongation(lattice, u, e) / lattice.length[e]
                      : 0.0;
    return m.loads().dot(u);  // V_1, as on the teeth path
  };
  // The strain from which beam e's damage grows.
  const auto threshold = [&](int e) {
    return std::max(history[static_cast<std::size_t>(e)], envelope[static_cast<std::size_t>(e)].peak_strain());
  };
  double v_1 = probe();
  while (g.run.n_events < spec.max_events && v_1 > 0.0) {
    // The next volume: a step up, or the first beam reaching its threshold if that is further.
    double ratio = 0.0;
    for (int e = 0; e < n_beams; ++e)
      if (strain[e] > 0.0) ratio = std::max(ratio, strain[e] / threshold(e));
    if (!(ratio > 0.0)) break;
    const double target = std::max(g.volume * (1.0 + spec.volume_step), v_1 / ratio);
    g.work += 0.5 * (g.volume + target) / v_1 * (target - g.volume);  // p linear in V on this state
    g.volume = target;
    g.account_mechanical_work(target / v_1);
    // Secant iterations at this volume: damage only grows, so they end.
    for (int changed = 1; changed > 0;) {
      changed = 0;
      const double pressure = g.volume / v_1;
      for (int e = 0; e < n_beams; ++e) {
        const auto k = static_cast<std::size_t>(e);
        const double eps = pressure * strain[e];
        if (m.states()[k] != l2::BeamState::intact || eps <= threshold(e) * (1.0 + spec.history_tolerance)) continue;
        ++changed;
        history[k] = eps;
        if (envelope[k].is_spent(eps)) {
          m.break_beam(e);
          g.crack.push_back(e);
        } else if (const double s = envelope[k].secant_factor(eps); s < m.stiffness_factor(e)) {
          m.soften_beam(e, s);
        }
      }
      g.run.n_events += changed;
      if (changed == 0) break;
      v_1 = probe();
      g.account_mechanical_work(g.volume / v_1);
    }
    double booked = 0.0;  // every beam's envelope up to its history
    for (int e = 0; e < n_beams; ++e)
      if (history[static_cast<std::size_t>(e)] > 0.0)
        booked += envelope[static_cast<std::size_t>(e)].dissipated_density(history[static_cast<std::size_t>(e)]) *
                  beam_volume[static_cast<std::size_t>(e)];
    g.record(g.volume / v_1, booked);
    if (g.run.points.back().half_length > spec.max_half_length) {
      g.run.reached = true;
      break;
    }
  }
  return g.finish();
}

}  // namespace

double crack_half_length(const l2::DualGraph& dual, const std::vector<int>& triangles) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int t : triangles) lo = std::min(lo, dual.dual_point(0, t)), hi = std::max(hi, dual.dual_point(0, t));
  return triangles.empty() ? 0.0 : 0.5 * (hi - lo);
}

GriffithConstants griffith_constants(double g_f) {
  const l2::ElasticConstants continuum = l2::calibrated_continuum();
  const double e_prime = continuum.youngs_modulus / (1 - continuum.poisson_ratio * continuum.poisson_ratio);
  return {e_prime, std::sqrt(e_prime * g_f)};
}

double griffith_half_length(double volume, const GriffithConstants& g) {
  return std::pow(g.e_prime * volume / (2 * std::sqrt(std::numbers::pi) * g.k_c), 2.0 / 3.0);
}

LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double mx = 0, my = 0;
  for (std::size_t k = 0; k < x.size(); ++k) mx += x[k] / n, my += y[k] / n;
  double sxy = 0, sxx = 0;
  for (std::size_t k = 0; k < x.size(); ++k) sxy += (x[k] - mx) * (y[k] - my), sxx += (x[k] - mx) * (x[k] - mx);
  const double slope = sxx > 0 ? sxy / sxx : 0.0;
  return {my - slope * mx, slope};
}

GrowthMeasures measure_growth(const CrackGrowthRun& run) {
  GrowthMeasures g;
  std::vector<double> k, length, booked, released, rock;
  for (const GrowthPoint& p : run.points) {
    if (p.half_length < kGrowthFitFrom || p.half_length > kGrowthFitTo) continue;
    k.push_back(p.pressure * std::sqrt(std::numbers::pi * p.half_length));
    length.push_back(2 * p.half_length);
    booked.push_back(p.booked);
    released.push_back(p.work - 0.5 * p.pressure * p.volume);
    rock.push_back(p.mechanical_work - 0.5 * p.pressure * p.volume);
  }
  g.n = static_cast<int>(k.size());
  if (k.size() < 2) return g;
  std::sort(k.begin(), k.end());
  g.toughness = k[k.size() / 2];
  g.booked = fit_line(length, booked).slope;
  g.released = fit_line(length, released).slope;
  g.rock = fit_line(length, rock).slope;
  return g;
}

CrackGrowthRun grow_pressurised_crack(const CrackGrowthSpec& spec) {
  if (spec.path == SofteningPath::continuous && spec.fracture_energy > 0.0) return grow_continuously(spec);
  return grow_by_events(spec);
}

}  // namespace hm::verification
