// Study (an executable, not a test; it asserts nothing): where the dry lattice's ~1.4x over-stress at
// the borehole wall comes from (annulus R_i = 0.138, internal pressure, free outer boundary; Lame).
// Per option and seed it prints: (a) wall-beam axial strain vs Lame's hoop strain u_r(R_i)/R_i;
// (b) wall particles' polar stress vs Lame at the clipped cell's centroid radius and averaged over the
// cell, split into wall-beam / inward-beam and normal-force / shear-force parts; (c) sigma_tt with other
// normalisations; (d) wall scatter (mean, sd, max); (e) candidate boundary stress measures and the
// first-break ratio p_first/p_crit = 1 / max_beams(sigma_1(p) / sigma_theta^Lame(R_i, p)) each would give
// (no strength heterogeneity, one linear solve). A second case evaluates the particle-stress formula on a
// regular triangular lattice with a straight free edge (the analytic check). Also: imposed exact Lame
// displacement, uniform affine strains and the wall cells' fabric (measure vs relaxation), the second row,
// and 1-ring smoothed variants.
// Run: build/studies/study_wall_stress (markdown-ish tables on stdout; ~1.6 s for all at N = 1e4).
// Knobs (environment): HM_WALL_N particles (default 10000), HM_WALL_SEEDS seeds 1..n (default 3),
// HM_WALL_ELL the non-local averaging length (default 0.01).
// Findings: docs/lattice.md, "Why the wall over-reads, and why 10% is out of reach".
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Cholesky>

#include "hm/analytic/lame.hpp"
#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/mechanics/beam_stiffness.hpp"
#include "hm/lattice2d/mechanics/mechanics.hpp"
#include "hm/lattice2d/mechanics/particle_stress.hpp"
#include "lattice2d/lattice_fixtures.hpp"

using namespace hm::lattice2d;
using hm::test::regular_triangular_lattice;

namespace {

struct WallOption {
  const char* name;
  double k_n;
  double aspect;
  StiffnessScaling scaling;
  double boundary_factor;
  double nu;  // the option's calibrated continuum (E = 1)
};

struct Stats {
  std::vector<double> v;
  void add(double x) { v.push_back(x); }
  double mean() const { return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size()); }
  double sd() const {
    const double m = mean();
    double s = 0;
    for (double x : v) s += (x - m) * (x - m);
    return std::sqrt(s / static_cast<double>(v.size()));
  }
  double max() const { return *std::max_element(v.begin(), v.end()); }
  double min() const { return *std::min_element(v.begin(), v.end()); }
};

// Polar components (rr, tt, rt) of a Voigt (xx, yy, xy) stress at direction er.
Eigen::Vector3d polar(const Eigen::Vector3d& s, const Eigen::Vector2d& er) {
  const Eigen::Vector2d et(-er.y(), er.x());
  Eigen::Matrix2d S;
  S << s[0], s[2], s[2], s[1];
  return {er.dot(S * er), et.dot(S * et), er.dot(S * et)};
}

// Accumulates per-option results over seeds (printed as means at the end).
std::map<std::string, std::vector<double>> g_summary;
void note(const std::string& key, double x) { g_summary[key].push_back(x); }

void study(const WallOption& o, long long n, std::uint64_t seed) {
  const double r_i = 0.138, p = 1.0;
  LatticeSpec spec;
  spec.domain = DomainShape::annulus;
  spec.inner_radius = r_i;
  spec.n_particles = n;
  spec.seed = seed;
  spec.boundary_spacing_factor = o.boundary_factor;
  const Lattice l = generate_lattice(spec);
  const DualGraph dual = build_dual_graph(l);
  BeamParameters bp;
  bp.normal_stiffness = o.k_n;
  bp.aspect = o.aspect;
  bp.beam_poisson = 0.25;
  bp.stiffness_scaling = o.scaling;
  BoundaryConditions bc;
  bc.inner_pressure = p;
  BeamMechanics m(l, bp, bc);
  m.solve();
  const Eigen::VectorXd& u = m.displacement();
  const BeamForces f = compute_beam_forces(l, bp, u);
  const ParticleStress ps = compute_particle_stress(l, dual, f);
  const hm::analytic::LameCylinder lame(p, 0.0, r_i, 1.0, o.nu);
  const double hoop = lame.state(r_i).sigma_theta;  // (1 + R_i^2)/(1 - R_i^2) p
  const double eps_lame = lame.state(r_i).u_r / r_i;
  const double e_prime = 1.0 / (1.0 - o.nu * o.nu), nu_ratio = o.nu / (1.0 - o.nu);
  const int np = l.n_particles(), nb = l.n_beams();
  auto is_wall_p = [&](int i) { return l.boundary[static_cast<std::size_t>(i)] == BoundaryTag::inner; };
  auto is_wall_b = [&](int e) { return l.beam_boundary[static_cast<std::size_t>(e)] == BoundaryTag::inner; };

  // Beams per particle.
  std::vector<std::vector<int>> beams_of(static_cast<std::size_t>(np));
  for (int e = 0; e < nb; ++e)
    for (int q : l.beams[static_cast<std::size_t>(e)]) beams_of[static_cast<std::size_t>(q)].push_back(e);

  // Clipped Voronoi cell pieces of particle q: (x_q, c_s, c_t) or (x_q, c_s, beam midpoint), area L d / 4.
  auto cell_pieces = [&](int q, std::vector<std::pair<double, Eigen::Vector2d>>& pieces) {
    pieces.clear();
    for (int e : beams_of[static_cast<std::size_t>(q)]) {
      const auto [i, j] = l.beams[static_cast<std::size_t>(e)];
      const auto [s, t] = l.beam_triangles[static_cast<std::size_t>(e)];
      const Eigen::Vector2d cs = dual.dual_point.col(s);
      const Eigen::Vector2d ct =
          t >= 0 ? Eigen::Vector2d(dual.dual_point.col(t)) : Eigen::Vector2d(0.5 * (l.points.col(i) + l.points.col(j)));
      pieces.emplace_back(0.25 * l.length[e] * dual.dual_length[e], (l.points.col(q) + cs + ct) / 3.0);
    }
  };

  // (a) wall beams' axial strain.
  Stats strain_ratio, ur_ratio;
  for (int e = 0; e < nb; ++e) {
    if (!is_wall_b(e)) continue;
    const auto [i, j] = l.beams[static_cast<std::size_t>(e)];
    const double eb =
        (u.segment<2>(dof_index(j, 0)) - u.segment<2>(dof_index(i, 0))).dot(l.direction.col(e)) / l.length[e];
    strain_ratio.add(eb / eps_lame);
  }
  for (int i = 0; i < np; ++i)
    if (is_wall_p(i))
      ur_ratio.add(u.segment<2>(dof_index(i, 0)).dot(l.points.col(i).normalized()) / lame.state(r_i).u_r);

  // (b), (c), (e): per wall particle. Alternative particle stresses for the wall particles (columns
  // replaced; every other particle keeps the library's stress).
  enum { cur, mirror_v, half_wall_virial, traction, edge_const, edge_const_dl, fit_const, fit_edge, n_alt };
  const char* alt_name[n_alt] = {"current 1/(2V) sum F(x)L",
                                 "V + mirrored wall half-diamonds",
                                 "wall-beam virial x 1/2",
                                 "+ boundary traction term",
                                 "edge: s_rr=-p, s_tt=E'eps+nu/(1-nu)s_rr",
                                 "edge, eps = dL-weighted mean of the 2 wall beams",
                                 "LS strain fit (w = dL), s = C eps",
                                 "LS fit eps_tt, s_rr=-p, s_tt=E'eps_tt+nu/(1-nu)s_rr"};
  const double lam = o.nu / ((1 + o.nu) * (1 - 2 * o.nu)), mu = 0.5 / (1 + o.nu);  // E = 1, plane strain
  std::vector<Eigen::Matrix3Xd> alt(n_alt, ps.stress);
  Stats tt_ratio_ri, tt_ratio_cen, tt_ratio_cell, rr_over_p, rt_over_p, r_cent_over_h, v_over_hl;
  Stats c_wall_n, c_wall_s, c_in_n, c_in_s;  // contributions to sigma_tt / Lame(R_i)
  Stats rr_wall, rr_in;                      // contributions to sigma_rr / p
  Stats lame_cen_over_ri, lame_cell_over_ri;
  // Central-force fabric of the wall cell with piece weights w_j = (L_j d_j / 4) / V_i (sum 1): tangential
  // weight (wall beams), hoop fabric under eps = I: sum w (n.t)^2 (isotropic 1/2) and under the polar pure
  // shear eps_tt = 1, eps_rr = -1: sum w (n.t)^2 ((n.t)^2 - (n.r)^2) (isotropic 1/4; regular edge exact).
  // For facet-scaled central beams s_tt / s_tt(isotropic) equals these ratios exactly.
  Stats fab_wt, fab_iso, fab_dev, n_inward;
  std::vector<Stats> alt_tt(n_alt);
  double mean_wall_beam_len = 0;
  int n_wall_beams = 0;
  for (int e = 0; e < nb; ++e)
    if (is_wall_b(e)) mean_wall_beam_len += l.length[e], ++n_wall_beams;
  mean_wall_beam_len /= n_wall_beams;
  std::vector<std::pair<double, Eigen::Vector2d>> pieces;
  for (int q = 0; q < np; ++q) {
    if (!is_wall_p(q)) continue;
    const Eigen::Vector2d xq = l.points.col(q), er = xq.normalized(), et(-er.y(), er.x());
    const double vq = dual.particle_area[q];
    cell_pieces(q, pieces);
    double area = 0;
    Eigen::Vector2d cen = Eigen::Vector2d::Zero();
    double cell_tt = 0;
    for (const auto& [a, c] : pieces) {
      area += a;
      cen += a * c;
      cell_tt += a * lame.state(c.norm()).sigma_theta;
    }
    cen /= area;
    cell_tt /= area;
    const double r_c = cen.norm();
    r_cent_over_h.add((r_c - r_i) / mean_wall_beam_len);
    v_over_hl.add(vq / (mean_wall_beam_len * mean_wall_beam_len));
    const Eigen::Vector3d pol = polar(ps.stress.col(q), er);
    tt_ratio_ri.add(pol[1] / hoop);
    tt_ratio_cen.add(pol[1] / lame.state(r_c).sigma_theta);
    tt_ratio_cell.add(pol[1] / cell_tt);
    lame_cen_over_ri.add(lame.state(r_c).sigma_theta / hoop);
    lame_cell_over_ri.add(cell_tt / hoop);
    rr_over_p.add(pol[0] / p);
    rt_over_p.add(pol[2] / p);
    // Contributions (raw virial, both ends give the same outer product).
    double wn = 0, ws = 0, in_n = 0, in_s = 0, rw = 0, rin = 0, extra_v = 0;
    Eigen::Matrix2d S_all = Eigen::Matrix2d::Zero(), S_wall = Eigen::Matrix2d::Zero(), T = Eigen::Matrix2d::Zero();
    std::vector<double> wall_strains;
    double eps_dl = 0, w_dl = 0;
    double fw = 0, fi = 0, fd = 0;
    int ninw = 0;
    for (int e : beams_of[static_cast<std::size_t>(q)]) {
      const double w = 0.25 * l.length[e] * dual.dual_length[e] / vq, ct = l.direction.col(e).dot(et),
                   cr = l.direction.col(e).dot(er);
      if (is_wall_b(e))
        fw += w;
      else
        ++ninw;
      fi += w * ct * ct, fd += w * ct * ct * (ct * ct - cr * cr);
    }
    fab_wt.add(fw), fab_iso.add(fi / 0.5), fab_dev.add(fd / 0.25), n_inward.add(ninw);
    for (int e : beams_of[static_cast<std::size_t>(q)]) {
      const Eigen::Vector2d nn = l.direction.col(e), ss(-nn.y(), nn.x());
      const Eigen::Vector2d F = f.force.col(e), Lv = l.length[e] * nn;
      const double Fn = F.dot(nn), Fs = F.dot(ss);
      const double ctn = l.length[e] * nn.dot(et) * nn.dot(et) * Fn / (2 * vq),
                   cts = l.length[e] * nn.dot(et) * ss.dot(et) * Fs / (2 * vq);
      const double crr = l.length[e] * nn.dot(er) * (Fn * nn.dot(er) + Fs * ss.dot(er)) / (2 * vq);
      const Eigen::Matrix2d outer = F * Lv.transpose();
      S_all += outer;
      if (is_wall_b(e)) {
        wn += ctn, ws += cts, rw += crr;
        S_wall += outer;
        extra_v += 0.25 * l.length[e] * dual.dual_length[e];
        const auto [i, j] = l.beams[static_cast<std::size_t>(e)];
        wall_strains.push_back((u.segment<2>(dof_index(j, 0)) - u.segment<2>(dof_index(i, 0))).dot(nn) / l.length[e]);
        eps_dl += dual.dual_length[e] * l.length[e] * wall_strains.back(), w_dl += dual.dual_length[e] * l.length[e];
        // Boundary traction on the half chord next to q: t = p m (m into the solid), arm (x - x_q) = s c,
        // c the chord direction from q: int_0^{L/2} s ds c (x) t = L^2/8 c (x) t (Cauchy average term).
        const int other = i == q ? j : i;
        const Eigen::Vector2d c = (l.points.col(other) - xq).normalized();
        Eigen::Vector2d mn(-c.y(), c.x());
        if (mn.dot(er) < 0) mn = -mn;  // into the solid = away from the hole's centre
        T += l.length[e] * l.length[e] / 8.0 * c * (p * mn).transpose();
      } else {
        in_n += ctn, in_s += cts, rin += crr;
      }
    }
    c_wall_n.add(wn / hoop), c_wall_s.add(ws / hoop), c_in_n.add(in_n / hoop), c_in_s.add(in_s / hoop);
    rr_wall.add(rw / p), rr_in.add(rin / p);
    auto voigt = [](const Eigen::Matrix2d& S) { return Eigen::Vector3d(S(0, 0), S(1, 1), 0.5 * (S(0, 1) + S(1, 0))); };
    alt[mirror_v].col(q) = voigt(S_all) / (2 * (vq + extra_v));
    alt[half_wall_virial].col(q) = voigt(S_all - 0.5 * S_wall) / (2 * vq);
    alt[traction].col(q) = voigt(0.5 * S_all + T) / vq;
    const double eps_t = wall_strains.empty() ? 0.0
                                              : std::accumulate(wall_strains.begin(), wall_strains.end(), 0.0) /
                                                    static_cast<double>(wall_strains.size());
    {
      const double srr = -p, stt = e_prime * eps_t + nu_ratio * srr;
      Eigen::Matrix2d P;  // polar -> Cartesian: sigma = srr er er + stt et et
      P = srr * er * er.transpose() + stt * et * et.transpose();
      alt[edge_const].col(q) = voigt(P);
      const double stt2 = e_prime * (eps_dl / w_dl) + nu_ratio * srr;
      alt[edge_const_dl].col(q) = voigt(Eigen::Matrix2d(srr * er * er.transpose() + stt2 * et * et.transpose()));
    }
    {
      // Least-squares strain of the particle's beams: min sum_j w_j ((u_j - u_q).n_j / L_j - n_j.eps.n_j)^2,
      // w_j = d_j L_j (the beam's diamond), unknowns (eps_xx, eps_yy, eps_xy).
      Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
      Eigen::Vector3d b = Eigen::Vector3d::Zero();
      for (int e : beams_of[static_cast<std::size_t>(q)]) {
        const auto [i, j] = l.beams[static_cast<std::size_t>(e)];
        const Eigen::Vector2d nn = l.direction.col(e);
        const double en = (u.segment<2>(dof_index(j, 0)) - u.segment<2>(dof_index(i, 0))).dot(nn) / l.length[e];
        const Eigen::Vector3d row(nn.x() * nn.x(), nn.y() * nn.y(), 2 * nn.x() * nn.y());
        const double w = std::max(dual.dual_length[e], 0.0) * l.length[e];
        A += w * row * row.transpose();
        b += w * en * row;
      }
      const Eigen::Vector3d ev = A.ldlt().solve(b);
      Eigen::Matrix2d E2;
      E2 << ev[0], ev[2], ev[2], ev[1];
      const Eigen::Matrix2d S = lam * E2.trace() * Eigen::Matrix2d::Identity() + 2 * mu * E2;
      alt[fit_const].col(q) = voigt(S);
      const double ett = et.dot(E2 * et), srr = -p, stt = e_prime * ett + nu_ratio * srr;
      alt[fit_edge].col(q) = voigt(Eigen::Matrix2d(srr * er * er.transpose() + stt * et * et.transpose()));
    }
    for (int k = 0; k < n_alt; ++k) alt_tt[static_cast<std::size_t>(k)].add(polar(alt[k].col(q), er)[1] / hoop);
  }

  std::printf("\n### %s, N = %lld, seed %llu: %d wall particles, %d wall beams, mean wall beam %.4f (r_min %.4f)\n",
              o.name, n, static_cast<unsigned long long>(seed), static_cast<int>(ur_ratio.v.size()), n_wall_beams,
              mean_wall_beam_len, l.min_spacing);
  std::printf(
      "(a) wall-beam axial strain / Lame u_r(R_i)/R_i: mean %.3f sd %.3f min %.3f max %.3f; wall u_r / Lame: mean %.3f "
      "sd %.3f max %.3f\n",
      strain_ratio.mean(), strain_ratio.sd(), strain_ratio.min(), strain_ratio.max(), ur_ratio.mean(), ur_ratio.sd(),
      ur_ratio.max());
  std::printf(
      "(b) wall particle s_tt / Lame(R_i): mean %.3f sd %.3f max %.3f; / Lame(centroid r) %.3f; / Lame cell avg %.3f\n",
      tt_ratio_ri.mean(), tt_ratio_ri.sd(), tt_ratio_ri.max(), tt_ratio_cen.mean(), tt_ratio_cell.mean());
  std::printf(
      "    Lame(centroid)/Lame(R_i) %.3f, Lame cell avg/Lame(R_i) %.3f, centroid depth (r_c - R_i)/L_wall %.3f, "
      "V/L_wall^2 %.3f\n",
      lame_cen_over_ri.mean(), lame_cell_over_ri.mean(), r_cent_over_h.mean(), v_over_hl.mean());
  std::printf("    s_tt/Lame(R_i) parts: wall beams normal %.3f shear %.3f | inward beams normal %.3f shear %.3f\n",
              c_wall_n.mean(), c_wall_s.mean(), c_in_n.mean(), c_in_s.mean());
  std::printf("    s_rr/p: mean %.3f sd %.3f (wall beams %.3f, inward %.3f); s_rt/p mean %.3f sd %.3f\n",
              rr_over_p.mean(), rr_over_p.sd(), rr_wall.mean(), rr_in.mean(), rt_over_p.mean(), rt_over_p.sd());
  std::printf(
      "    wall-cell fabric: tangential weight %.3f (regular edge 1/3), hoop gain eps=I %.3f, polar pure shear %.3f; "
      "inward beams per wall particle %.2f\n",
      fab_wt.mean(), fab_iso.mean(), fab_dev.mean(), n_inward.mean());
  note(std::string(o.name) + " fabric tangential weight", fab_wt.mean());
  note(std::string(o.name) + " fabric hoop gain eps=I", fab_iso.mean());
  note(std::string(o.name) + " fabric hoop gain polar pure shear", fab_dev.mean());
  note(std::string(o.name) + " (a) strain ratio mean", strain_ratio.mean());
  note(std::string(o.name) + " (a) strain ratio max", strain_ratio.max());
  note(std::string(o.name) + " (b) s_tt/Lame(R_i) particle mean", tt_ratio_ri.mean());
  note(std::string(o.name) + " (b) s_tt/Lame(centroid) mean", tt_ratio_cen.mean());
  note(std::string(o.name) + " (b) s_tt/Lame(cell avg) mean", tt_ratio_cell.mean());
  note(std::string(o.name) + " (b) Lame(centroid)/Lame(R_i)", lame_cen_over_ri.mean());
  note(std::string(o.name) + " (b) part wall-beam normal", c_wall_n.mean());
  note(std::string(o.name) + " (b) part wall-beam shear", c_wall_s.mean());
  note(std::string(o.name) + " (b) part inward normal", c_in_n.mean());
  note(std::string(o.name) + " (b) part inward shear", c_in_s.mean());
  note(std::string(o.name) + " (b) s_rr/p", rr_over_p.mean());

  // (d), (e): beam sigma_1 / Lame(R_i) for every alternative; first break = 1 / max over all beams.
  // Smoothed variants (scatter reduction, a conjectured remedy for the extreme): every particle's stress
  // replaced by the V-weighted mean over itself and its beam neighbours (1-ring), applied on top of the
  // current measure and of the edge measure.
  auto smooth = [&](const Eigen::Matrix3Xd& in) {
    Eigen::Matrix3Xd out(3, np);
    for (int q = 0; q < np; ++q) {
      Eigen::Vector3d acc = dual.particle_area[q] * in.col(q);
      double w = dual.particle_area[q];
      for (int e : beams_of[static_cast<std::size_t>(q)]) {
        const auto [i, j] = l.beams[static_cast<std::size_t>(e)];
        const int o2 = i == q ? j : i;
        acc += dual.particle_area[o2] * in.col(o2), w += dual.particle_area[o2];
      }
      out.col(q) = acc / w;
    }
    return out;
  };
  // Non-local variant with a fixed physical length: V-weighted mean over the particles within ell of x_i
  // (bucket grid), ell from env HM_WALL_ELL (default 0.01, ~0.7 spacing at N = 1e4, ~2.3 at N = 1e5).
  const char* ell_env = std::getenv("HM_WALL_ELL");
  const double ell = ell_env ? std::atof(ell_env) : 0.01;
  auto nonlocal = [&](const Eigen::Matrix3Xd& in) {
    const int ng = static_cast<int>(std::ceil(2.0 / ell));
    std::vector<std::vector<int>> grid(static_cast<std::size_t>(ng) * ng);
    auto cell_of = [&](double v) { return std::clamp(static_cast<int>((v + 1.0) / ell), 0, ng - 1); };
    for (int q = 0; q < np; ++q)
      grid[static_cast<std::size_t>(cell_of(l.points(1, q))) * ng + cell_of(l.points(0, q))].push_back(q);
    Eigen::Matrix3Xd out(3, np);
    for (int q = 0; q < np; ++q) {
      const int cx = cell_of(l.points(0, q)), cy = cell_of(l.points(1, q));
      Eigen::Vector3d acc = Eigen::Vector3d::Zero();
      double w = 0;
      for (int gy = std::max(cy - 1, 0); gy <= std::min(cy + 1, ng - 1); ++gy)
        for (int gx = std::max(cx - 1, 0); gx <= std::min(cx + 1, ng - 1); ++gx)
          for (int o2 : grid[static_cast<std::size_t>(gy) * ng + gx])
            if ((l.points.col(o2) - l.points.col(q)).norm() <= ell)
              acc += dual.particle_area[o2] * in.col(o2), w += dual.particle_area[o2];
      out.col(q) = acc / w;
    }
    return out;
  };
  std::vector<Eigen::Matrix3Xd> smoothed = {smooth(alt[cur]), smooth(alt[edge_const]), nonlocal(alt[cur]),
                                            nonlocal(alt[edge_const])};
  const std::string ell_s = "ell = " + std::to_string(ell).substr(0, 6);
  const std::string smooth_name[4] = {"1-ring smoothed current", "1-ring smoothed edge measure",
                                      "non-local " + ell_s + " current", "non-local " + ell_s + " edge measure"};
  for (int k = 0; k < 4; ++k) {
    const BeamStress bs = compute_beam_stress(l, ParticleStress{smoothed[static_cast<std::size_t>(k)], ps.skew});
    Stats wall;
    double best = -1, best_off = -1;
    for (int e = 0; e < nb; ++e) {
      const double r = bs.sigma_1[e] / hoop;
      const auto [i, j] = l.beams[static_cast<std::size_t>(e)];
      if (is_wall_b(e)) wall.add(r);
      best = std::max(best, r);
      if (!is_wall_p(i) && !is_wall_p(j)) best_off = std::max(best_off, r);
    }
    std::printf(
        "    %s: wall beams s1/Lame mean %.3f max %.3f (max/mean %.3f); off-wall max %.3f; p_first/p_crit %.3f\n",
        smooth_name[k].c_str(), wall.mean(), wall.max(), wall.max() / wall.mean(), best_off, 1.0 / best);
    note(std::string(o.name) + " (e) " + smooth_name[k] + ": wall mean", wall.mean());
    note(std::string(o.name) + " (e) " + smooth_name[k] + ": max/mean", wall.max() / wall.mean());
    note(std::string(o.name) + " (e) " + smooth_name[k] + ": off-wall max", best_off);
    note(std::string(o.name) + " (e) " + smooth_name[k] + ": p_first/p_crit", 1.0 / best);
  }
  std::printf(
      "(c-e) | wall-particle stress | particle s_tt/Lame mean | wall beams s1/Lame mean | sd | max | max/mean | max "
      "over all beams (where) | p_first/p_crit |\n");
  for (int k = 0; k < n_alt; ++k) {
    const BeamStress bs = compute_beam_stress(l, ParticleStress{alt[k], ps.skew});
    Stats wall;
    double best = -1;
    int where = -1;
    double best_not_wall_touching = -1, off_r = 0, off_local = 0;
    for (int e = 0; e < nb; ++e) {
      const double r = bs.sigma_1[e] / hoop;
      const auto [i, j] = l.beams[static_cast<std::size_t>(e)];
      const int touches = (is_wall_p(i) ? 1 : 0) + (is_wall_p(j) ? 1 : 0);
      if (is_wall_b(e)) wall.add(r);
      if (r > best) best = r, where = is_wall_b(e) ? 2 : touches;
      if (touches == 0 && r > best_not_wall_touching) {
        best_not_wall_touching = r;
        off_r = 0.5 * (l.points.col(i) + l.points.col(j)).norm();
        off_local = bs.sigma_1[e] / lame.state(off_r).sigma_theta;
      }
    }
    const char* wname = where == 2   ? "wall beam"
                        : where == 1 ? "beam with one end on wall"
                        : where == 0 ? "off-wall"
                                     : "both ends on wall, not a wall beam";
    std::printf(
        "| %s | %.3f | %.3f | %.3f | %.3f | %.3f | %.3f (%s; off-wall max %.3f at r = %.4f, %.2f x Lame there) | %.3f "
        "|\n",
        alt_name[k], alt_tt[static_cast<std::size_t>(k)].mean(), wall.mean(), wall.sd(), wall.max(),
        wall.max() / wall.mean(), best, wname, best_not_wall_touching, off_r, off_local, 1.0 / best);
    const std::string key = std::string(o.name) + " (e) " + alt_name[k];
    note(key + ": wall beam s1 mean", wall.mean());
    note(key + ": wall beam s1 max", wall.max());
    note(key + ": max/mean", wall.max() / wall.mean());
    note(key + ": off-wall max", best_not_wall_touching);
    note(key + ": p_first/p_crit", 1.0 / best);
  }
  // Imposed exact Lame displacement (u = u_r(r) e_r, omega = 0): the stress measure's error without the
  // lattice's non-affine relaxation. Wall particles' s_tt and s_rr; interior shell 0.3 < r < 0.5 check.
  {
    Eigen::VectorXd ul = Eigen::VectorXd::Zero(3 * np);
    for (int i = 0; i < np; ++i) {
      const Eigen::Vector2d x = l.points.col(i);
      ul.segment<2>(dof_index(i, 0)) = lame.state(x.norm()).u_r * x.normalized();
    }
    const ParticleStress pl = compute_particle_stress(l, dual, compute_beam_forces(l, bp, ul));
    const BeamStress bl = compute_beam_stress(l, pl);
    Stats wt, wr, it, ir, wb, tt_lat_vs_imposed;
    for (int i = 0; i < np; ++i) {
      const Eigen::Vector2d x = l.points.col(i);
      const Eigen::Vector3d pol = polar(pl.stress.col(i), x.normalized());
      if (is_wall_p(i)) {
        wt.add(pol[1] / hoop), wr.add(pol[0] / p);
        tt_lat_vs_imposed.add(polar(ps.stress.col(i), x.normalized())[1] / pol[1]);
      } else if (l.boundary[static_cast<std::size_t>(i)] == BoundaryTag::interior && x.norm() > 0.3 && x.norm() < 0.5) {
        it.add(pol[1] / lame.state(x.norm()).sigma_theta), ir.add(pol[0] / lame.state(x.norm()).sigma_r);
      }
    }
    for (int e = 0; e < nb; ++e)
      if (is_wall_b(e)) wb.add(bl.sigma_1[e] / hoop);
    std::printf(
        "    imposed Lame u: wall particle s_tt/Lame(R_i) %.3f (sd %.3f), s_rr/p %.3f; wall beams s1 mean %.3f max "
        "%.3f; "
        "interior 0.3<r<0.5 s_tt/Lame %.3f s_rr/Lame %.3f; relaxed/imposed wall s_tt %.3f\n",
        wt.mean(), wt.sd(), wr.mean(), wb.mean(), wb.max(), it.mean(), ir.mean(), tt_lat_vs_imposed.mean());
    note(std::string(o.name) + " imposed Lame: wall particle s_tt/Lame(R_i)", wt.mean());
    note(std::string(o.name) + " imposed Lame: wall beam s1 mean", wb.mean());
    note(std::string(o.name) + " imposed Lame: wall beam s1 max", wb.max());
    note(std::string(o.name) + " imposed Lame: interior s_tt/Lame", it.mean());
    note(std::string(o.name) + " imposed Lame: relaxed/imposed wall s_tt", tt_lat_vs_imposed.mean());
  }
  // Uniform affine strains (u = eps x, omega = 0), no field gradient: wall particles' s_tt and s_rr against
  // the interior's mean affine stress (0.3 < r < 0.9) in the same polar frame, as a least-squares gain
  // sum(s_wall s_int)/sum(s_int^2): the boundary cell's fabric error alone.
  for (int k = 0; k < 2; ++k) {
    Eigen::Matrix2d eps =
        k == 0 ? Eigen::Matrix2d::Identity() : Eigen::Matrix2d(Eigen::Vector2d(1.0, -1.0).asDiagonal());
    Eigen::VectorXd ua = Eigen::VectorXd::Zero(3 * np);
    for (int i = 0; i < np; ++i) ua.segment<2>(dof_index(i, 0)) = eps * l.points.col(i);
    const ParticleStress pa = compute_particle_stress(l, dual, compute_beam_forces(l, bp, ua));
    Eigen::Vector3d mean_int = Eigen::Vector3d::Zero();
    double a_int = 0;
    for (int i = 0; i < np; ++i)
      if (l.boundary[static_cast<std::size_t>(i)] == BoundaryTag::interior && l.points.col(i).norm() > 0.3 &&
          l.points.col(i).norm() < 0.9)
        mean_int += dual.particle_area[i] * pa.stress.col(i), a_int += dual.particle_area[i];
    mean_int /= a_int;
    double stt = 0, itt = 0, srr = 0, irr = 0;
    for (int i = 0; i < np; ++i)
      if (is_wall_p(i)) {
        const Eigen::Vector2d er = l.points.col(i).normalized();
        const Eigen::Vector3d w = polar(pa.stress.col(i), er), c = polar(mean_int, er);
        stt += w[1] * c[1], itt += c[1] * c[1], srr += w[0] * c[0], irr += c[0] * c[0];
      }
    std::printf("    affine uniform eps = %s: wall s_tt gain %.3f, s_rr gain %.3f (vs interior mean affine stress)\n",
                k == 0 ? "I" : "diag(1,-1)", stt / itt, srr / irr);
    note(std::string(o.name) + (k == 0 ? " affine eps=I" : " affine eps=diag(1,-1)") + ": wall s_tt gain", stt / itt);
    note(std::string(o.name) + (k == 0 ? " affine eps=I" : " affine eps=diag(1,-1)") + ": wall s_rr gain", srr / irr);
  }
  // Second row: interior particles sharing a beam with a wall particle. Their s_tt against Lame at their
  // radius (systematic?), and the beams between two second-row particles (sigma_1 / Lame(R_i), mean, max).
  {
    std::vector<bool> row2(static_cast<std::size_t>(np), false);
    for (int e = 0; e < nb; ++e) {
      const auto [i, j] = l.beams[static_cast<std::size_t>(e)];
      if (is_wall_p(i) && !is_wall_p(j)) row2[static_cast<std::size_t>(j)] = true;
      if (is_wall_p(j) && !is_wall_p(i)) row2[static_cast<std::size_t>(i)] = true;
    }
    const BeamStress bs = compute_beam_stress(l, ps);
    Stats tt_local, depth, b_ri, b_local, all_r2, tt_interior;
    for (int i = 0; i < np; ++i) {
      const Eigen::Vector2d x = l.points.col(i);
      const double r = x.norm();
      if (row2[static_cast<std::size_t>(i)]) {
        tt_local.add(polar(ps.stress.col(i), x.normalized())[1] / lame.state(r).sigma_theta);
        depth.add((r - r_i) / mean_wall_beam_len);
      } else if (l.boundary[static_cast<std::size_t>(i)] == BoundaryTag::interior && r > 0.3 && r < 0.5) {
        tt_interior.add(polar(ps.stress.col(i), x.normalized())[1] / lame.state(r).sigma_theta);
      }
    }
    for (int e = 0; e < nb; ++e) {
      const auto [i, j] = l.beams[static_cast<std::size_t>(e)];
      if (row2[static_cast<std::size_t>(i)] && row2[static_cast<std::size_t>(j)]) {
        const double rm = 0.5 * (l.points.col(i) + l.points.col(j)).norm();
        b_ri.add(bs.sigma_1[e] / hoop), b_local.add(bs.sigma_1[e] / lame.state(rm).sigma_theta);
      }
    }
    std::printf(
        "    second row (%d particles, depth %.2f L_wall): s_tt/Lame(r) mean %.3f sd %.3f max %.3f [interior "
        "0.3<r<0.5: mean %.3f sd %.3f]; "
        "row-2 beams s1/Lame(R_i) mean %.3f max %.3f, s1/Lame(r) mean %.3f\n",
        static_cast<int>(tt_local.v.size()), depth.mean(), tt_local.mean(), tt_local.sd(), tt_local.max(),
        tt_interior.mean(), tt_interior.sd(), b_ri.mean(), b_ri.max(), b_local.mean());
    note(std::string(o.name) + " row 2: s_tt/Lame(r) mean", tt_local.mean());
    note(std::string(o.name) + " row 2: beams s1/Lame(R_i) max", b_ri.max());
    note(std::string(o.name) + " interior 0.3<r<0.5 s_tt/Lame(r) mean", tt_interior.mean());
    note(std::string(o.name) + " interior 0.3<r<0.5 s_tt/Lame(r) sd", tt_interior.sd());
  }
  // Per-beam facet stress of the wall beams: F_n / d_su (and its value if the continuum were exact).
  Stats fn_d;
  for (int e = 0; e < nb; ++e)
    if (is_wall_b(e)) {
      const double Fn = f.force.col(e).dot(l.direction.col(e));
      // F_ij = +|F| n_ij in tension (force on i towards j).
      fn_d.add(Fn / dual.dual_length[e] / hoop);
    }
  std::printf("    per-beam F_n/d_su on wall beams / Lame(R_i): mean %.3f sd %.3f max %.3f\n", fn_d.mean(), fn_d.sd(),
              fn_d.max());
  note(std::string(o.name) + " (e) wall beam F_n/d_su mean", fn_d.mean());
  note(std::string(o.name) + " (e) wall beam F_n/d_su max", fn_d.max());
}

// The particle-stress formula on a regular triangular lattice with a straight free edge.
void regular_lattice_free_edge() {
  const int n = 21;
  const Lattice l = regular_triangular_lattice(n, 1.0 / 20.0);
  const DualGraph dual = build_dual_graph(l);
  const int edge = 10, inner = 10 * n + 5;  // bottom-row middle particle; an interior particle
  const double hoop = (1 + 0.138 * 0.138) / (1 - 0.138 * 0.138);
  std::printf("\n## Regular triangular lattice, affine u = eps x (omega = 0), edge particle vs interior particle\n");
  std::printf(
      "| beams | a | strain (eps_xx, eps_yy) | edge s_xx / interior s_xx | edge s_yy / interior s_yy | interior (s_xx, "
      "s_yy) |\n");
  for (StiffnessScaling sc : {StiffnessScaling::uniform, StiffnessScaling::voronoi_facet})
    for (double a : {1e-3, 0.5061}) {
      BeamParameters bp;
      bp.aspect = a;
      bp.stiffness_scaling = sc;
      const double kn = 1.0, kw = bp.rotational_stiffness();
      // Regular lattice affine C (docs/lattice.md): C11 = 2 sqrt3 (3k/8 + kw/4), C12 = 2 sqrt3 (k/8 - kw/4).
      const double c11 = 2 * std::sqrt(3.0) * (3 * kn / 8 + kw / 4), c12 = 2 * std::sqrt(3.0) * (kn / 8 - kw / 4);
      // Lame wall state s_xx = hoop, s_yy = -1 (x = tangent, y = normal).
      const double det = c11 * c11 - c12 * c12;
      const double ex_l = (c11 * hoop + c12) / det, ey_l = (-c11 - c12 * hoop) / det;
      const std::pair<double, double> strains[] = {{1.0, -c12 / c11}, {1.0, 0.0}, {ex_l, ey_l}};
      const char* names[] = {"free edge (s_yy = 0)", "eps_yy = 0", "Lame wall (s_xx = 1.039 p, s_yy = -p)"};
      for (int k = 0; k < 3; ++k) {
        Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * l.n_particles());
        for (int i = 0; i < l.n_particles(); ++i) {
          const Eigen::Vector2d x = l.points.col(i);
          u[dof_index(i, 0)] = strains[k].first * x.x();
          u[dof_index(i, 1)] = strains[k].second * x.y();
        }
        const ParticleStress ps = compute_particle_stress(l, dual, compute_beam_forces(l, bp, u));
        std::printf("| %s | %g | %s (%.4f, %.4f) | %.4f | %.4f | (%.4f, %.4f) |\n",
                    sc == StiffnessScaling::uniform ? "uniform" : "facet", a, names[k], strains[k].first,
                    strains[k].second, ps.stress(0, edge) / ps.stress(0, inner),
                    ps.stress(1, edge) / ps.stress(1, inner), ps.stress(0, inner), ps.stress(1, inner));
      }
    }
}

// The borehole wall of the random lattice, per option and seed, and the means over seeds.
void random_lattice_borehole_wall() {
  const char* env = std::getenv("HM_WALL_N");
  const long long n = env ? std::atoll(env) : 10000;
  const char* seeds_env = std::getenv("HM_WALL_SEEDS");
  const int n_seeds = seeds_env ? std::atoi(seeds_env) : 3;
  const WallOption options[] = {
      {"uniform (a = 0.05)", 0.9332262824164865, 0.05, StiffnessScaling::uniform, 1.0, 0.2236},
      {"facet calibrated + boundary 1.3", 0.9237809571070129, 0.5061, StiffnessScaling::voronoi_facet, 1.3, 0.2500},
  };
  g_summary.clear();
  for (const WallOption& o : options)
    for (int s = 1; s <= n_seeds; ++s) study(o, n, static_cast<std::uint64_t>(s));
  std::printf("\n## Means over seeds (per-seed values in brackets)\n");
  for (const auto& [key, values] : g_summary) {
    const double mean = std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
    std::printf("%-110s %.3f [", key.c_str(), mean);
    for (double v : values) std::printf(" %.3f", v);
    std::printf(" ]\n");
  }
}

}  // namespace

int main() {
  regular_lattice_free_edge();
  random_lattice_borehole_wall();
  return 0;
}
