#include "fracture/failure_scan.hpp"

#include <cassert>
#include <cmath>

namespace hm::lattice2d {

FailureScan::FailureScan(const Lattice& lattice, const DualGraph& dual, const CrackTipOptions& crack_tip,
                         const std::vector<BeamState>& states, const SawtoothLaw* law)
    : lattice_(lattice),
      dual_(dual),
      crack_tip_(crack_tip),
      law_(law),
      triangle_broken_(lattice.triangle_beams.size(), 0),
      tip_triangles_(static_cast<std::size_t>(lattice.n_beams()), 0) {
  if (law_) crack_tip_.enabled = false;  // the saw-tooth's G_f, not a tip factor, gives the crack its length scale
  assert(dual.particle_area.size() == lattice.n_particles() && "dual graph of another lattice");
  assert(static_cast<int>(states.size()) == lattice.n_beams() && "one state per beam");
  for (std::size_t t = 0; t < triangle_broken_.size(); ++t) {
    for (int e : lattice.triangle_beams[t])
      triangle_broken_[t] += states[static_cast<std::size_t>(e)] != BeamState::intact;
    if (triangle_broken_[t] == 1)
      for (int e : lattice.triangle_beams[t]) ++tip_triangles_[static_cast<std::size_t>(e)];
  }
}

void FailureScan::beam_broken(int beam) {
  for (int t : lattice_.beam_triangles[static_cast<std::size_t>(beam)]) {
    if (t < 0) continue;
    const int before = triangle_broken_[static_cast<std::size_t>(t)]++;
    for (int e : lattice_.triangle_beams[static_cast<std::size_t>(t)]) {
      if (before == 1) --tip_triangles_[static_cast<std::size_t>(e)];
      if (before == 0) ++tip_triangles_[static_cast<std::size_t>(e)];
    }
  }
}

double FailureScan::crack_tip_factor(int beam) const {
  return crack_tip_.enabled && tip_triangles_[static_cast<std::size_t>(beam)] > 0
             ? crack_tip_.factor(lattice_.length[beam])
             : 1.0;
}

FailureScan::Result FailureScan::run(const std::vector<BeamForce>& forces, const BeamStrengths& strengths,
                                     const std::vector<BeamState>& states, double stress_scale) {
  compute_particle_stress(lattice_, dual_, forces, particle_);
  // Beam stresses of the intact beams, principal stresses, failure ratios, the candidate: two fixed
  // halves of the beams on the threads, combined in order (the lower half wins a tie, as the lowest
  // index does in one pass), so the same bits on any number of threads.
  const int n_beams = lattice_.n_beams();
  std::array<Result, kChunks> part;
  std::array<bool, kChunks> any_intact{};
#pragma omp parallel for schedule(static) if (n_beams >= kParallelBeams)
  for (int c = 0; c < kChunks; ++c)
    scan_beams(c * n_beams / kChunks, (c + 1) * n_beams / kChunks, forces, strengths, states, stress_scale,
               part[static_cast<std::size_t>(c)], any_intact[static_cast<std::size_t>(c)]);
  Result out;
  bool any = false;
  for (std::size_t c = 0; c < part.size(); ++c) {
    if (!any_intact[c]) continue;
    const Result& r = part[c];
    if (!any || r.max_reference_ratio > out.max_reference_ratio) out.max_reference_ratio = r.max_reference_ratio;
    if (!any || r.judged.max_ratio > out.judged.max_ratio) out.judged.max_ratio = r.judged.max_ratio;
    any = true;
    if (r.judged.found() && (!out.judged.found() || r.judged.ratio > out.judged.ratio)) {
      const double max_ratio = out.judged.max_ratio;
      out.judged = r.judged;
      out.judged.max_ratio = max_ratio;
      out.sigma_1 = r.sigma_1;
      out.sigma_3 = r.sigma_3;
      out.crack_tip_factor = r.crack_tip_factor;
      out.axial_stress = r.axial_stress;
    }
  }
  return out;
}

void FailureScan::scan_beams(int first, int last, const std::vector<BeamForce>& forces, const BeamStrengths& strengths,
                             const std::vector<BeamState>& states, double stress_scale, Result& out,
                             bool& any_intact) const {
  const FailureCriterion criterion(strengths.friction);
  BreakCandidate& best = out.judged;
  for (int e = first; e < last; ++e) {
    if (states[static_cast<std::size_t>(e)] != BeamState::intact) continue;
    const double factor = crack_tip_factor(e);
    const Eigen::Vector3d sigma = beam_stress(lattice_, particle_, e, factor);
    const PrincipalPair principal = principal_pair(sigma[0], sigma[1], sigma[2]);
    const double s1 = principal.sigma_1, s3 = principal.sigma_3;
    const double T = strengths.tensile[e], C = strengths.compressive[e];
    hm::analytic::FailureCheck reference, judged;
    double axial = 0.0;
    if (law_) {
      axial = law_->axial_stress(e, forces[static_cast<std::size_t>(e)].normal);
      const double f = law_->strength(e);
      reference = FailureCriterion::combine(axial / f, criterion.shear_ratio(s1, s3, C));
      judged = stress_scale == 1.0
                   ? reference
                   : FailureCriterion::combine(axial * stress_scale / f,
                                               criterion.shear_ratio(s1 * stress_scale, s3 * stress_scale, C));
    } else {
      reference = criterion.check(s1, s3, T, C);
      judged = stress_scale == 1.0 ? reference : criterion.check(s1 * stress_scale, s3 * stress_scale, T, C);
    }
    assert(!std::isnan(judged.ratio) && "failure ratio is NaN: non-finite stress");
    if (!any_intact || reference.ratio > out.max_reference_ratio) out.max_reference_ratio = reference.ratio;
    if (!any_intact || judged.ratio > best.max_ratio) best.max_ratio = judged.ratio;
    any_intact = true;
    // Strictly greater: on equal ratios the lowest index, visited first, stays.
    if (judged.ratio >= 1.0 && (!best.found() || judged.ratio > best.ratio)) {
      best.beam = e;
      best.ratio = judged.ratio;
      best.mode = judged.mode;
      out.sigma_1 = stress_scale == 1.0 ? s1 : s1 * stress_scale;
      out.sigma_3 = stress_scale == 1.0 ? s3 : s3 * stress_scale;
      out.crack_tip_factor = factor;
      out.axial_stress = stress_scale == 1.0 ? axial : axial * stress_scale;
    }
  }
}

}  // namespace hm::lattice2d
