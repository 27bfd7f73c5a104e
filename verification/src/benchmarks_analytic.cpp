// Benchmarks of analytic/: each closed form is checked against its own governing equation,
// boundary conditions and conservation law by independent numerics (4th-order finite
// differences, GSL quadrature), so a wrong derivation shows up here whatever the formula says.
#include <gsl/gsl_integration.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <numbers>
#include <stdexcept>

#include "finite_difference.hpp"
#include "hm/analytic/biot_modulus.hpp"
#include "hm/analytic/lame.hpp"
#include "hm/analytic/rudnicki.hpp"
#include "hm/analytic/sneddon.hpp"
#include "hm/analytic/steady_borehole.hpp"
#include "hm/core/csv_writer.hpp"
#include "hm/core/file_output.hpp"
#include "hm/verification/benchmark.hpp"

namespace hm::verification {

using core::CsvWriter;

namespace {

using namespace hm::analytic;
using std::numbers::pi;

/// Adaptive GSL quadrature of f on [a, b] to relative 1e-10; throws if GSL cannot reach it.
double integrate(const std::function<double(double)>& f, double a, double b) {
  gsl_integration_workspace* w = gsl_integration_workspace_alloc(1000);
  gsl_function g{[](double x, void* p) { return (*static_cast<const std::function<double(double)>*>(p))(x); },
                 const_cast<std::function<double(double)>*>(&f)};
  double result = 0.0, error = 0.0;
  const int status = gsl_integration_qags(&g, a, b, 0.0, 1e-10, 1000, w, &result, &error);
  gsl_integration_workspace_free(w);
  if (status) throw std::runtime_error("GSL quadrature did not converge");
  return result;
}

std::vector<double> linspace(double a, double b, int n) {
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) x[i] = a + (b - a) * i / (n - 1);
  return x;
}

// Finite-difference steps below are chosen where the O(h^4) truncation and the O(eps/h^2)
// round-off of the stencils are both below 1e-9 of the checked terms; halving h changes the
// residuals by less than the tolerances (checked when the benchmark was written).
constexpr const char* fd_reason =
    "4th-order central differences (h = 1e-3 r): truncation + round-off of the check itself ~1e-9";

BenchmarkResult steady_borehole(const BenchmarkContext& ctx) {
  BenchmarkResult res;
  const double Q = 0.01, nu = 0.25, R_i = 0.138;
  double worst_b2 = 0, worst_inner = 0, worst_outer = 0, worst_hooke = 0, worst_flux = 0;
  for (double b : {0.0, 0.2, 0.5, 0.8, 1.0}) {
    const SteadyBorehole sol(Q, b, nu, R_i);
    const double p_h = sol.borehole_pressure();
    const double eta = b * oedometric_compliance(nu);
    auto u = [&](double r) { return sol.state(r).u_r; };
    auto p = [&](double r) { return sol.state(r).p; };
    double scale = 0, b2 = 0, hooke = 0;
    for (double r : linspace(R_i * 1.05, 0.98, 60)) {
      const double h = 1e-3 * r;
      const double lhs = d2(u, r, h) + d1(u, r, h) / r - u(r) / (r * r);
      b2 = std::max(b2, std::abs(lhs - eta * d1(p, r, h)));
      scale = std::max(scale, std::abs(d2(u, r, h)));
      RadialState expected;
      set_plane_strain_stresses(expected, nu, d1(u, r, h), u(r) / r);
      const RadialState got = sol.state(r);
      hooke = std::max({hooke, std::abs(got.sigma_r - expected.sigma_r),
                        std::abs(got.sigma_theta - expected.sigma_theta), std::abs(got.sigma_z - expected.sigma_z)});
    }
    worst_b2 = std::max(worst_b2, b2 / scale);
    worst_hooke = std::max(worst_hooke, hooke / p_h);
    worst_inner = std::max(worst_inner, std::abs(sol.state(R_i).sigma_r + (1 - b) * p_h) / p_h);
    worst_outer = std::max(worst_outer, std::abs(sol.state(1.0).sigma_r) / p_h);
    for (double r : {R_i, 0.5, 1.0})
      worst_flux = std::max(worst_flux, std::abs(-2 * pi * r * d1(p, r, 1e-4 * r) - Q) / Q);
    res.metrics.push_back({.name = "Eq. 23: p_h, b = " + std::to_string(b).substr(0, 3),
                           .value = p_h,
                           .reference = -Q / (2 * pi) * std::log(R_i),
                           .tolerance = 1e-12,
                           .comparison = Comparison::rel_error,
                           .justification = "round-off"});
  }
  res.metrics.push_back({.name = "B2 residual (max over r and b = 0..1), relative to max |u''|",
                         .value = worst_b2,
                         .tolerance = 1e-7,
                         .comparison = Comparison::at_most,
                         .justification = fd_reason});
  res.metrics.push_back({.name = "inner BC: |sigma_mr(R_i) + (1-b) p_h| / p_h",
                         .value = worst_inner,
                         .tolerance = 1e-12,
                         .comparison = Comparison::at_most,
                         .justification = "round-off"});
  res.metrics.push_back({.name = "outer BC: |sigma_mr(1)| / p_h",
                         .value = worst_outer,
                         .tolerance = 1e-12,
                         .comparison = Comparison::at_most,
                         .justification = "round-off"});
  res.metrics.push_back({.name = "stresses = plane-strain Hooke of u (max error / p_h)",
                         .value = worst_hooke,
                         .tolerance = 1e-7,
                         .comparison = Comparison::at_most,
                         .justification = fd_reason});
  res.metrics.push_back({.name = "flux -2 pi r dp/dr = Q at R_i, 0.5, 1 (rel.)",
                         .value = worst_flux,
                         .tolerance = 1e-8,
                         .comparison = Comparison::at_most,
                         .justification = fd_reason});

  const std::filesystem::path csv_path = ctx.data_dir / "analytic_steady_borehole.csv";
  std::ofstream csv = core::open_for_writing(csv_path);
  CsvWriter w(csv, {"b", "r", "p", "u_r", "sigma_r", "sigma_theta", "sigma_z"});
  for (double b : {0.2, 0.5, 0.8}) {
    const SteadyBorehole sol(Q, b, nu, R_i);
    for (double r : linspace(R_i, 1.0, 200)) {
      const RadialState s = sol.state(r);
      w.row({b, r, s.p, s.u_r, s.sigma_r, s.sigma_theta, s.sigma_z});
    }
  }
  res.figures.push_back({"verify_steady_borehole.py", "verify_steady_borehole.png",
                         "Steady borehole (corrected Appendix B), Q = 0.01, nu = 0.25, R_i = 0.138: p, u_r and "
                         "effective stresses for b = 0.2, 0.5, 0.8."});
  core::close_checked(csv, csv_path);
  return res;
}

BenchmarkResult rudnicki(const BenchmarkContext& ctx) {
  BenchmarkResult res;
  const double Q = 0.1, t = 3e-4;
  const std::filesystem::path csv_path = ctx.data_dir / "analytic_rudnicki.csv";
  std::ofstream csv = core::open_for_writing(csv_path);
  CsvWriter w(csv, {"vol_strain", "r", "p", "u_r"});
  for (VolStrain vs : {VolStrain::plane_strain, VolStrain::appendix_a}) {
    PoroelasticParameters m;
    m.b = 0.5;
    m.nu = 0.25;
    m.E_over_M = E_over_M_table1(m.b, m.nu);
    m.vol_strain = vs;
    const RudnickiLineSource sol(Q, m);
    const double S = sol.storage(), eta = m.b * oedometric_compliance(m.nu);
    const std::string tag = " (" + core::name_of(vs) + ")";

    double diffusion = 0, diffusion_scale = 0, mech = 0, mech_scale = 0;
    for (double r : linspace(0.002, 0.1, 50)) {
      auto p_r = [&](double x) { return sol.pressure(x, t); };
      auto p_t = [&](double s) { return sol.pressure(r, s); };
      auto u_r = [&](double x) { return sol.radial_displacement(x, t); };
      const double h = 1e-3 * r;
      const double lap = d2(p_r, r, h) + d1(p_r, r, h) / r;
      const double storage = S * d1(p_t, t, 1e-3 * t);
      diffusion = std::max(diffusion, std::abs(storage - lap));
      diffusion_scale = std::max(diffusion_scale, std::abs(lap));
      const double lhs = d2(u_r, r, h) + d1(u_r, r, h) / r - u_r(r) / (r * r);
      mech = std::max(mech, std::abs(lhs - eta * d1(p_r, r, h)));
      mech_scale = std::max(mech_scale, std::abs(eta * d1(p_r, r, h)));
    }
    res.metrics.push_back({.name = "diffusion residual S p_t - lap p (max / max |lap p|)" + tag,
                           .value = diffusion / diffusion_scale,
                           .tolerance = 1e-6,
                           .comparison = Comparison::at_most,
                           .justification = fd_reason});
    res.metrics.push_back({.name = "mechanics residual of Eq. A3 (max / max |eta p'|)" + tag,
                           .value = mech / mech_scale,
                           .tolerance = 1e-6,
                           .comparison = Comparison::at_most,
                           .justification = fd_reason});
    // Near the source the flux through a circle of radius r is Q exp(-S r^2/4t) -> Q.
    const double r0 = 1e-5 * std::sqrt(t / S);
    auto p_r = [&](double x) { return sol.pressure(x, t); };
    res.metrics.push_back({.name = "near-source flux -2 pi r p_r at r = 1e-5 sqrt(t/S)" + tag,
                           .value = -2 * pi * r0 * d1(p_r, r0, 1e-3 * r0),
                           .reference = Q,
                           .tolerance = 1e-6,
                           .comparison = Comparison::rel_error,
                           .justification = "exact flux is Q exp(-S r^2/4t) = Q (1 - 2.5e-11) here; FD error ~1e-10"});
    // Fluid content: E/M p + f b eps_v integrated over the plane equals the injected volume Q t.
    const double f = vol_strain_factor(vs);
    auto content = [&](double r) {
      auto u = [&](double x) { return sol.radial_displacement(x, t); };
      const double eps_v = (r > 1e-6) ? d1(u, r, 1e-4 * r) + u(r) / r : eta * sol.pressure(r, t);
      return (m.E_over_M * sol.pressure(r, t) + f * m.b * eps_v) * 2 * pi * r;
    };
    const double r_max = std::sqrt(4 * t * 60 / S);  // exp(-60): the rest of the plane holds nothing
    res.metrics.push_back({.name = "fluid content over the plane = Q t" + tag,
                           .value = integrate(content, 0, r_max),
                           .reference = Q * t,
                           .tolerance = 1e-6,
                           .comparison = Comparison::rel_error,
                           .justification = "GSL qags to 1e-10 of an integrand with FD strain (~1e-8)"});
    for (double r : linspace(1e-3, 0.08, 160)) w.row({f, r, sol.pressure(r, t), sol.radial_displacement(r, t)});
    (void)eta;
  }
  res.figures.push_back({"verify_rudnicki.py", "verify_rudnicki.png",
                         "Rudnicki line source, Q = 0.1, b = 0.5, t = 3e-4 (the paper's Fig. 7 setting): p and u_r "
                         "for both volumetric-strain variants."});
  core::close_checked(csv, csv_path);
  return res;
}

BenchmarkResult sneddon_closed_form(const BenchmarkContext&) {
  BenchmarkResult res;
  const SneddonCrack crack{1e-3, 0.1, 0.25};
  const double volume = integrate([&](double x) { return 2 * crack.half_aperture(x); }, -crack.c, crack.c);
  res.metrics.push_back({.name = "crack volume: integral of 2w = pi c eps",
                         .value = volume,
                         .reference = crack.crack_volume(),
                         .tolerance = 1e-9,
                         .comparison = Comparison::rel_error,
                         .justification = "GSL qags to 1e-10 relative (square-root endpoint singularities)"});
  res.metrics.push_back({.name = "max half aperture w(0) = 2(1-nu^2) p c (Sneddon 1946, plane strain)",
                         .value = crack.half_aperture(0),
                         .reference = 2 * (1 - 0.25 * 0.25) * 1e-3 * 0.1,
                         .tolerance = 1e-12,
                         .comparison = Comparison::rel_error,
                         .justification = "round-off"});
  return res;
}

BenchmarkResult lame_closed_form(const BenchmarkContext&) {
  BenchmarkResult res;
  const double R_i = 0.138, nu = 0.25, p_i = 1e-3;
  auto check = [&](const std::string& label, const std::function<RadialState(double)>& state, double outer_expected,
                   bool outer_is_displacement) {
    double equilibrium = 0;
    for (double r : linspace(R_i * 1.05, 0.97, 50)) {
      auto sr = [&](double x) { return state(x).sigma_r; };
      const RadialState s = state(r);
      equilibrium = std::max(equilibrium, std::abs(d1(sr, r, 1e-3 * r) + (s.sigma_r - s.sigma_theta) / r));
    }
    res.metrics.push_back({.name = label + ": equilibrium residual / p_i",
                           .value = equilibrium / p_i,
                           .tolerance = 1e-7,
                           .comparison = Comparison::at_most,
                           .justification = fd_reason});
    res.metrics.push_back({.name = label + ": sigma_r(R_i) = -p_i",
                           .value = state(R_i).sigma_r,
                           .reference = -p_i,
                           .tolerance = 1e-12,
                           .comparison = Comparison::rel_error,
                           .justification = "round-off"});
    const double outer = outer_is_displacement ? state(1.0).u_r : state(1.0).sigma_r;
    res.metrics.push_back(
        {.name = label + (outer_is_displacement ? ": u_r(1) = 0" : ": sigma_r(1) = -p_o") + " (/ p_i)",
         .value = (outer - outer_expected) / p_i,
         .tolerance = 1e-12,
         .comparison = Comparison::abs_error,
         .justification = "round-off"});
  };
  const LameCylinder free_outer(p_i, 0.0, R_i, 1.0, nu);
  const LameCylinderFixedOuter fixed_outer(p_i, R_i, 1.0, nu);
  check(
      "free outer surface", [&](double r) { return free_outer.state(r); }, 0.0, false);
  check(
      "fixed outer surface", [&](double r) { return fixed_outer.state(r); }, 0.0, true);
  return res;
}

}  // namespace

void add_analytic_benchmarks(std::vector<Benchmark>& into) {
  into.push_back({"analytic.steady_borehole", "Steady-state borehole (Appendix B)",
                  "The implemented steady state (B3 and the corrected B6-B9) against its own governing equation "
                  "B2, both stress boundary conditions, plane-strain Hooke's law and the injected flux, "
                  "for b = 0, 0.2, 0.5, 0.8, 1.",
                  Tier::quick, steady_borehole});
  into.push_back({"analytic.rudnicki", "Rudnicki's continuous line source (Section 3.1)",
                  "p and u_r of the line source against the diffusion equation, the radial equilibrium (A3), "
                  "the near-source flux Q and the injected volume Q t, for both volumetric-strain variants.",
                  Tier::quick, rudnicki});
  into.push_back({"analytic.sneddon", "Sneddon's pressurised crack (Appendix C)",
                  "Eq. C1's ellipse: its opened area against quadrature, its maximum against Sneddon (1946).",
                  Tier::quick, sneddon_closed_form});
  into.push_back({"analytic.lame", "Lamé thick-walled cylinder, plane strain",
                  "Free and fixed outer surface: radial equilibrium and boundary conditions.", Tier::quick,
                  lame_closed_form});
}

}  // namespace hm::verification
