// Benchmarks of the coupled 2D lattice (Sections 2.1-2.3): Rudnicki's fluid line source (Section 3.1,
// Fig. 7) — point injection at the centre of a disk, Q = 0.1, b = 0.5, t* = 3e-4 — with the undrained
// split iterated to convergence, with one pass per step, and with the drained split; free and fixed
// outer boundary. Radially averaged p and u_r against analytic/rudnicki.hpp, plus the volume balance.
//
// Which continuum: the lattice's triangle areas are plane-strain volumetric strains (eps_xx + eps_yy),
// so the analytic solution is taken with vol_strain = plane-strain; its nu is the calibrated lattice's
// (calibrated_continuum(): 0.25 as Table 1, 0.2236 with uniform beams), its E/M the model's own (Eq. 22 at nu = 0.25,
// as in the case file). Rudnicki is for an unbounded plane: the disk's outer boundary (free or fixed) shifts u_r by an
// amount that grows with r (the paper's Fig. 7 shows it), so the comparison is restricted to r* in [0.01, 0.05], where
// the pressure plume has not reached r = 1.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include "hm/analytic/rudnicki.hpp"
#include "hm/case/coupled_model_of_case.hpp"
#include "hm/case/provenance.hpp"
#include "hm/case/run_case.hpp"
#include "hm/case/run_output.hpp"
#include "hm/core/csv_writer.hpp"
#include "hm/core/file_output.hpp"
#include "hm/lattice2d/coupled/coupled_model.hpp"
#include "hm/lattice2d/io/radial_average.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"
#include "hm/verification/benchmark.hpp"
#include "report_writer.hpp"

namespace hm::verification {

using cases::radial_fields;
using cases::RadialFields;
using cases::RunCase;
using cases::RunRecorder;
using core::CsvWriter;

namespace {

namespace lt = hm::lattice2d;

/// One lattice run of the Fig. 7 setting.
struct RudnickiVariant {
  std::string label;  // also the data sub-folder
  long long n_particles = 10000;
  lt::BoundarySupport outer = lt::BoundarySupport::free;
  lt::CouplingSplit split = lt::CouplingSplit::undrained;
  double psi = 1.3;
  bool one_pass = false;
};

RunCase rudnicki_case(const RudnickiVariant& v) {
  RunCase c;
  c.physics.parameters.Q = 0.1;
  c.physics.parameters.R_i = 0.0;
  c.physics.parameters.material.b = 0.5;
  c.physics.parameters.material.nu = 0.25;
  c.physics.parameters.material.E_over_M = analytic::E_over_M_table1(0.5, 0.25);
  c.lattice.domain = lt::DomainShape::disk;
  c.lattice.n_particles = v.n_particles;
  c.lattice.seed = 1;
  c.boundary.outer = v.outer;
  c.coupling.split = v.split;
  c.coupling.terms.psi = v.psi;  // 0 with the drained split (CouplingOptions::validate)
  if (v.one_pass) {
    c.coupling.max_iterations = 1;
    c.coupling.accept_unconverged = true;
  }
  // The paper does not give dt: our choice, as in cases/fig07_rudnicki_free.toml (halving dt_max
  // moves the profiles by < 1%, measured at N = 1e4).
  c.stepping.dt_initial = 1e-6;
  c.stepping.dt_growth = 1.2;
  c.stepping.dt_max = 2e-5;
  c.stepping.t_end = 3e-4;
  c.stepping.output_times = {3e-4};
  c.output.vtk = false;
  c.output.radial_bins = 20;  // shells 0.01 wide: centres 0.015 ... 0.045 in [0.01, 0.05]
  c.output.radial_max = 0.2;
  return c;
}

struct RudnickiOutcome {
  RadialFields fields;       // at t_end
  double max_error_p = 0.0;  // max over shells with r_mean in [0.01, 0.05] of |p - p_a| / p_a
  double max_error_u = 0.0;  // same for u_r
  double max_balance = 0.0;
  int n_steps = 0, total_iterations = 0;
  double seconds = 0.0;
  bool ok = false;
  std::string message;
};

RudnickiOutcome run_variant(const RudnickiVariant& v, const BenchmarkContext& ctx, Table& table) {
  const RunCase c = rudnicki_case(v);
  const auto model = cases::make_coupled_model(c);
  const std::filesystem::path dir = ctx.data_dir / ("rudnicki_" + v.label);
  std::filesystem::create_directories(dir);
  RunRecorder recorder(dir, c);
  const auto run = model->run(c.stepping, [&](const lt::CoupledModel& m, const lt::CoupledStepSummary& s, bool out) {
    recorder.record(m, s, out);
  });
  recorder.finish();
  // The resolved case beside the results, as `hmlattice run` writes it: the figure reads its setting.
  core::write_file_atomically(dir / "config.toml", [&](std::ostream& out) {
    out << cases::run_case_to_toml(c, cases::to_toml(cases::make_provenance("hmlattice verify, run " + v.label)));
  });
  RudnickiOutcome o;
  o.ok = run.is_ok();
  o.message = run.message;
  o.max_balance = run.max_balance_error;
  o.n_steps = run.n_steps;
  o.total_iterations = run.total_iterations;
  o.seconds = run.seconds;
  o.fields = radial_fields(*model, lt::uniform_shell_edges(0.0, c.output.radial_max, c.output.radial_bins));
  analytic::PoroelasticParameters continuum = c.physics.parameters.material;
  continuum.nu = lt::calibrated_continuum().poisson_ratio;
  continuum.vol_strain = analytic::VolStrain::plane_strain;
  const analytic::RudnickiLineSource exact(c.physics.parameters.Q, continuum);
  // The reference beside the run, for figures/fig07_rudnicki.py (which computes nothing itself).
  core::write_file_atomically(dir / "analytic.csv", [&](std::ostream& file) {
    CsvWriter w(file, {"t", "r", "p", "u_r"});
    const double t = c.stepping.t_end;
    for (int k = 1; k <= 400; ++k) {  // r* = 0.0005 ... radial_max, fine enough for a smooth line
      const double r = c.output.radial_max * k / 400.0;
      w.row({t, r, exact.pressure(r, t), exact.radial_displacement(r, t)});
    }
  });
  for (std::size_t k = 0; k < o.fields.r_mean.size(); ++k) {
    const double r = o.fields.r_mean[k];
    if (!(r >= 0.01 && r <= 0.05)) continue;
    const double p_a = exact.pressure(r, c.stepping.t_end), u_a = exact.radial_displacement(r, c.stepping.t_end);
    o.max_error_p = std::max(o.max_error_p, std::abs(o.fields.p[k] - p_a) / p_a);
    o.max_error_u = std::max(o.max_error_u, std::abs(o.fields.u_r[k] - u_a) / u_a);
    table.rows.push_back({v.label, std::to_string(model->lattice().n_particles()), fmt(r), fmt(o.fields.p[k]), fmt(p_a),
                          fmt(o.fields.u_r[k]), fmt(u_a)});
  }
  return o;
}

Metric error_metric(const std::string& what, double value, bool gating, const std::string& why,
                    double tolerance = 0.10) {
  return at_most_metric(what, value, tolerance, gating, why);
}

Metric flow_balance_metric(const std::string& label, double worst) {
  return {.name = "volume balance, max relative error per step (" + label + ")",
          .value = worst,
          .tolerance = 1e-8,
          .comparison = Comparison::at_most,
          .justification =
              "the flow scheme is conservative by construction: round-off of the sparse solve "
              "(measured ~1e-15 per step at N = 1e4; 1e-8 leaves margin)"};
}

Table profile_table() {
  return {
      "Radially averaged p and u_r at t* = 3e-4 against Rudnicki (shells 0.01 wide, r = area-weighted mean "
      "centroid radius of the shell)",
      {"run", "N", "r*", "p (lattice)", "p (Rudnicki)", "u_r (lattice)", "u_r (Rudnicki)"},
      {}};
}

Table run_table() {
  return {"Runs: steps, coupling passes, wall time, max errors on r* in [0.01, 0.05]",
          {"run", "steps", "passes", "seconds", "max |p - p_a|/p_a", "max |u_r - u_a|/u_a", "balance"},
          {}};
}

void add_run_row(Table& t, const std::string& label, const RudnickiOutcome& o) {
  t.rows.push_back({label, std::to_string(o.n_steps), std::to_string(o.total_iterations), fmt(o.seconds),
                    fmt(o.max_error_p), fmt(o.max_error_u), fmt(o.max_balance)});
}

// --- quick tier: N = 1e4, free, iterated undrained ---------------------------------------------

BenchmarkResult rudnicki_quick(const BenchmarkContext& ctx) {
  BenchmarkResult res;
  Table profiles = profile_table(), runs = run_table();
  const RudnickiVariant v{.label = "free_N1e4"};
  const RudnickiOutcome o = run_variant(v, ctx, profiles);
  add_run_row(runs, v.label, o);
  res.metrics.push_back({.name = "run completed (every step converged)",
                         .value = o.ok ? 1.0 : 0.0,
                         .reference = 1.0,
                         .tolerance = 0.0,
                         .comparison = Comparison::abs_error,
                         .justification = "a numerical failure is a failure: " + o.message});
  res.metrics.push_back(error_metric("max relative error of radially averaged u_r, r* in [0.01, 0.05], N = 1e4",
                                     o.max_error_u, true,
                                     "a coarse-resolution sanity bound (measured 2.8%, the lattice 2-3% low; 8.6% "
                                     "with uniform beams); the 10% near-source bound is checked at N = 3e4 in the "
                                     "paper tier",
                                     0.15));
  res.metrics.push_back(
      error_metric("max relative error of radially averaged p, r* in [0.01, 0.05], N = 1e4", o.max_error_p, false,
                   "not gating at N = 1e4: the plume at t* = 3e-4 spans ~2 particle spacings "
                   "(h ~ 0.019), the innermost shell is under-predicted (measured 19% at r* = 0.017; 27% "
                   "with uniform beams); the "
                   "paper tier checks it at N = 3e4"));
  res.metrics.push_back(flow_balance_metric("N = 1e4", o.max_balance));
  res.tables = {runs, profiles};
  res.figures.push_back({"fig07_rudnicki.py", "fig07_rudnicki_free_N1e4.png",
                         "Fig. 7 at N = 1e4 (free disk, Q = 0.1, b = 0.5, t* = 3e-4): radially averaged u_r and p "
                         "(markers) against Rudnicki (line; plane strain, the calibrated lattice's nu); below, the "
                         "deviation in %. Shaded: the compared range r* in [0.01, 0.05].",
                         "rudnicki_" + v.label});
  return res;
}

// --- paper tier: two resolutions, both boundaries, three split variants -----------------------

// The largest relative difference of p and of u_r between two runs' shells in the compared range
// r* in [0.01, 0.05].
double max_profile_difference(const RudnickiOutcome& o, const RudnickiOutcome& reference) {
  double d = 0.0;
  for (std::size_t k = 0; k < reference.fields.r_mean.size(); ++k) {
    const double r = reference.fields.r_mean[k];
    if (!(r >= 0.01 && r <= 0.05)) continue;
    d = std::max(d, std::abs(o.fields.p[k] - reference.fields.p[k]) / std::abs(reference.fields.p[k]));
    d = std::max(d, std::abs(o.fields.u_r[k] - reference.fields.u_r[k]) / std::abs(reference.fields.u_r[k]));
  }
  return d;
}

BenchmarkResult rudnicki_paper(const BenchmarkContext& ctx) {
  BenchmarkResult res;
  Table profiles = profile_table(), runs = run_table();
  auto run = [&](const RudnickiVariant& v) {
    const RudnickiOutcome o = run_variant(v, ctx, profiles);
    add_run_row(runs, v.label, o);
    res.metrics.push_back(flow_balance_metric(v.label, o.max_balance));
    if (!o.ok)
      res.metrics.push_back({.name = v.label + ": run completed",
                             .value = 0.0,
                             .reference = 1.0,
                             .tolerance = 0.0,
                             .comparison = Comparison::abs_error,
                             .justification = o.message});
    return o;
  };
  for (lt::BoundarySupport outer : {lt::BoundarySupport::free, lt::BoundarySupport::fixed}) {
    const std::string b = core::name_of(outer);
    const RudnickiOutcome coarse = run({.label = b + "_N1e4", .n_particles = 10000, .outer = outer});
    const RudnickiOutcome fine = run({.label = b + "_N3e4", .n_particles = 30000, .outer = outer});
    const std::string why =
        "the lattice's discretisation error near the source, where the plume spans a few "
        "spacings: within 10% for r* in [0.01, 0.05] at N = 3e4";
    res.metrics.push_back(error_metric(b + ": max relative error of p, N = 3e4", fine.max_error_p, true, why));
    res.metrics.push_back(error_metric(b + ": max relative error of u_r, N = 3e4", fine.max_error_u, true, why));
    res.metrics.push_back({.name = b + ": error of p, N = 1e4 over N = 3e4",
                           .value = coarse.max_error_p / fine.max_error_p,
                           .reference = 1.0,
                           .tolerance = 1.0,
                           .comparison = Comparison::at_least,
                           .justification = "a discretisation error shrinks under refinement",
                           .gating = true});
    res.metrics.push_back({.name = b + ": error of u_r, N = 1e4 over N = 3e4",
                           .value = coarse.max_error_u / fine.max_error_u,
                           .reference = 1.0,
                           .tolerance = 1.0,
                           .comparison = Comparison::at_least,
                           .justification = "information: measured 2.8% -> 3.9% (free) with the facet-scaled "
                                            "lattice, the lattice 1-4% low in both: within the 10% near-source bound "
                                            "at both "
                                            "resolutions and not in an asymptotic range (the innermost compared shell "
                                            "moves towards the source with N); p's error, 19% -> 9.2%, is gated",
                           .gating = false});
    if (outer == lt::BoundarySupport::free) {
      // The paper's other two variants at the fine resolution: same profiles within a few percent.
      const RudnickiOutcome one = run({.label = "free_N3e4_one_pass", .n_particles = 30000, .one_pass = true});
      const RudnickiOutcome drained =
          run({.label = "free_N3e4_drained", .n_particles = 30000, .split = lt::CouplingSplit::drained, .psi = 0.0});
      for (const auto& [label, o] : {std::pair{"one pass", &one}, std::pair{"drained", &drained}}) {
        res.metrics.push_back({.name = std::string("free, N = 3e4: max relative difference of p and u_r, ") + label +
                                       " vs iterated undrained",
                               .value = max_profile_difference(*o, fine),
                               .reference = 0.0,
                               .tolerance = 0.05,
                               .comparison = Comparison::at_most,
                               .justification = "the paper's Fig. 7: 'no significant differences'; not gating "
                                                "(our reading of a figure)",
                               .gating = false});
      }
    }
  }
  res.tables = {runs, profiles};
  res.notes.push_back(
      "The analytic solution uses the calibrated lattice's nu = " + fmt(lt::calibrated_continuum().poisson_ratio) +
      ", the model's E/M and vol_strain = plane-strain (the lattice's volumetric strain is the triangle-area change, "
      "eps_xx + eps_yy). Rudnicki's plane is unbounded; at t* = 3e-4 the disk's outer boundary hardly matters for "
      "r* <= 0.05 (free and fixed differ by < 0.5% there). "
      "The CSV of every run is in rudnicki_<run>/ (series.csv, radial.csv, and analytic.csv: Rudnicki at t* = 3e-4).");
  res.figures.push_back({"fig07_rudnicki.py", "fig07_rudnicki.png",
                         "Fig. 7 (Q = 0.1, b = 0.5, t* = 3e-4): radially averaged u_r and p of every run (markers; "
                         "colour = outer boundary, marker = resolution and split) against Rudnicki (line); below, "
                         "the deviation in %. Shaded: the compared range r* in [0.01, 0.05]."});
  return res;
}

// --- the Psi study (Fig. 8) -----------------------------------------------------------------------

// The shell Gamma of Fig. 6: the triangles with centroid radius in (0.02, 0.03), and their area.
struct Shell {
  std::vector<int> triangles;
  double area = 0.0;
};
Shell fig6_shell(const lt::DualGraph& dual) {
  Shell shell;
  for (int s = 0; s < static_cast<int>(dual.triangle_area.size()); ++s) {
    const double r = dual.centroid.col(s).norm();
    if (r > 0.02 && r < 0.03) {
      shell.triangles.push_back(s);
      shell.area += dual.triangle_area[s];
    }
  }
  return shell;
}

// Section 3.1's claims on the passes of each Psi (in the order 0, 1, 1.3, 2, 10): every split converges,
// 1 <= Psi <= 2 beats both ends, the drained split overshoots and the undrained does not, and the
// paper's factors 2 and 5 (shown).
void add_psi_metrics(const std::vector<int>& run_passes, const std::vector<int>& step_passes,
                     const std::vector<int>& sign_changes, std::vector<Metric>& metrics) {
  const bool all_ok = std::all_of(run_passes.begin(), run_passes.end(), [](int p) { return p > 0; }) &&
                      std::all_of(step_passes.begin(), step_passes.end(), [](int p) { return p > 0; });
  metrics.push_back({.name = "every Psi converges in every step",
                     .value = all_ok ? 1.0 : 0.0,
                     .reference = 1.0,
                     .tolerance = 0.0,
                     .comparison = Comparison::abs_error,
                     .justification = "all splits must converge (max_iterations 100 per step, 500 for the one step)"});
  const double p13 = run_passes[2];
  const double best_band = std::max({run_passes[1], run_passes[2], run_passes[3]});
  metrics.push_back({.name = "ranking: min(passes(Psi = 0), passes(Psi = 10)) / max over 1 <= Psi <= 2",
                     .value = std::min(run_passes[0], run_passes[4]) / best_band,
                     .reference = 1.0,
                     .tolerance = 1.0,
                     .comparison = Comparison::at_least,
                     .justification = "the paper's ranking (Section 3.1): 1 <= Psi <= 2 beats both Psi = 10 and the "
                                      "drained split"});
  metrics.push_back({.name = "drained split (Psi = 0): overshoots of the shell pressure in the first 5 passes",
                     .value = static_cast<double>(sign_changes[0]),
                     .reference = 1.0,
                     .tolerance = 1.0,
                     .comparison = Comparison::at_least,
                     .justification = "Fig. 8: the drained split oscillates (measured: 4 of 4 at N = 3e4)"});
  metrics.push_back({.name = "undrained split, Psi = 1.3 and 10: overshoots in the first 5 passes",
                     .value = static_cast<double>(sign_changes[2] + sign_changes[4]),
                     .reference = 0.0,
                     .tolerance = 0.0,
                     .comparison = Comparison::abs_error,
                     .justification = "Fig. 8: the undrained split approaches monotonically (no oscillation)"});
  metrics.push_back({.name = "passes(Psi = 10) / passes(Psi = 1.3)",
                     .value = run_passes[4] / p13,
                     .reference = 2.0,
                     .tolerance = 0.5,
                     .comparison = Comparison::rel_error,
                     .justification = "the paper's 'approximately doubled' (wall time, tolerances not given); "
                                      "shown, not gating",
                     .gating = false});
  metrics.push_back({.name = "passes(drained) / passes(Psi = 1.3)",
                     .value = run_passes[0] / p13,
                     .reference = 5.0,
                     .tolerance = 0.5,
                     .comparison = Comparison::rel_error,
                     .justification = "the paper's 'a factor about 5' (wall time); shown, not gating",
                     .gating = false});
}

BenchmarkResult psi_study(const BenchmarkContext& ctx) {
  BenchmarkResult res;
  const std::vector<double> psis = {0.0, 1.0, 1.3, 2.0, 10.0};
  const long long n = ctx.tier == Tier::paper ? 30000 : 10000;
  const std::filesystem::path dir = ctx.data_dir / "psi_study";
  std::filesystem::create_directories(dir);
  const std::filesystem::path pass_file_path = dir / "passes.csv";
  std::ofstream pass_file = core::open_for_writing(pass_file_path);
  CsvWriter passes(pass_file, {"psi", "pass", "p_shell"});
  Table table{
      "Psi study at N = " + fmt(static_cast<double>(n)) +
          ": the Fig. 7 run to t* = 3e-4 (27 steps) with each Psi, and one step dt = 3e-4 from rest",
      {"Psi", "passes (run)", "passes / passes(1.3)", "seconds (run)", "seconds / seconds(1.3)", "passes (one step)"},
      {}};
  const lt::Lattice lattice = lt::generate_lattice(rudnicki_case({.label = "psi", .n_particles = n}).lattice);
  const lt::DualGraph dual = lt::build_dual_graph(lattice);
  const Shell shell = fig6_shell(dual);
  std::vector<int> run_passes, step_passes, sign_changes;
  std::vector<double> run_seconds;
  for (double psi : psis) {
    const RudnickiVariant v{.label = "psi",
                            .n_particles = n,
                            .split = psi == 0.0 ? lt::CouplingSplit::drained : lt::CouplingSplit::undrained,
                            .psi = psi};
    const RunCase c = rudnicki_case(v);
    {  // the whole run
      const auto model = cases::make_coupled_model(c, lattice);
      const auto run = model->run(c.stepping);
      run_passes.push_back(run.is_ok() ? run.total_iterations : -1);
      run_seconds.push_back(run.seconds);
    }
    {  // one step from rest: the shell pressure against the pass number (Fig. 8)
      RunCase long_passes = c;
      long_passes.coupling.max_iterations = 500;
      const auto model = cases::make_coupled_model(long_passes, lattice);
      std::vector<double> history;
      model->set_pass_observer([&](int pass, const Eigen::VectorXd& p, const Eigen::VectorXd&) {
        double sum = 0.0;
        for (int s : shell.triangles) sum += p[s] * dual.triangle_area[s];
        history.push_back(sum / shell.area);
        passes.row({psi, static_cast<double>(pass), sum / shell.area});
      });
      const auto step = model->step(3e-4);
      step_passes.push_back(step.is_ok() ? step.iterations : -1);
      // Overshoots: sign changes of the pass-to-pass change over the first 5 passes, counting only
      // changes above 1e-4 of the shell pressure (visible in Fig. 8; the drained split's are 2e-4 to
      // 30%, while a converged undrained step wiggles at ~3e-6, measured with Psi = 1.3 at N = 3e4).
      int flips = 0;
      for (std::size_t k = 2; k < std::min<std::size_t>(history.size(), 6); ++k) {
        const double d1 = history[k] - history[k - 1], d0 = history[k - 1] - history[k - 2];
        const double visible = 1e-4 * std::abs(history[k]);
        flips += d1 * d0 < 0.0 && std::abs(d1) > visible && std::abs(d0) > visible ? 1 : 0;
      }
      sign_changes.push_back(flips);
    }
  }
  const double p13 = run_passes[2], s13 = run_seconds[2];
  for (std::size_t k = 0; k < psis.size(); ++k)
    table.rows.push_back({fmt(psis[k]), std::to_string(run_passes[k]), fmt(run_passes[k] / p13), fmt(run_seconds[k]),
                          fmt(run_seconds[k] / s13), std::to_string(step_passes[k])});
  res.tables.push_back(table);
  add_psi_metrics(run_passes, step_passes, sign_changes, res.metrics);
  res.figures.push_back({"fig08_psi_study.py", "fig08_psi_study.png",
                         "Fig. 8: mean pressure in the shell 0.02 < r* < 0.03 against the coupling pass, one implicit "
                         "step dt = 3e-4 from rest, for each Psi (Psi = 0: the drained split); right, its relative "
                         "distance from the same Psi's last (converged) pass.",
                         "psi_study"});
  core::close_checked(pass_file, pass_file_path);
  return res;
}

}  // namespace

void add_lattice2d_coupled_benchmarks(std::vector<Benchmark>& into) {
  into.push_back({.id = "lattice2d.rudnicki_quick",
                  .title = "Coupled lattice: Rudnicki's line source at N = 1e4 (Fig. 7, free boundary)",
                  .description = "Point injection into a free disk, Q = 0.1, b = 0.5, undrained split (Psi = 1.3) "
                                 "iterated to 1e-6; radially averaged u_r and p at t* = 3e-4 against "
                                 "analytic/rudnicki.hpp on r* in [0.01, 0.05]; fluid-volume balance per step.",
                  .tier = Tier::quick,
                  .run = rudnicki_quick,
                  .paper_figures = {"7"}});
  into.push_back({.id = "lattice2d.rudnicki",
                  .title = "Coupled lattice: Rudnicki's line source, two resolutions, free and fixed (Fig. 7)",
                  .description = "As the quick benchmark at N = 1e4 and 3e4, free and fixed outer boundary; at N = 3e4 "
                                 "also the undrained split with one pass per step and the drained split.",
                  .tier = Tier::paper,
                  .run = rudnicki_paper,
                  .paper_figures = {"7"}});
  into.push_back({.id = "lattice2d.psi_study",
                  .title = "Coupled lattice: the undrained split's Psi against iterations and time (Fig. 8)",
                  .description = "The Fig. 7 run with Psi = 0 (drained), 1, 1.3, 2, 10: coupling passes and wall time "
                                 "to t* = 3e-4, and the shell pressure against the pass number in one step.",
                  .tier = Tier::paper,
                  .run = psi_study,
                  .paper_figures = {"8"}});
}

}  // namespace hm::verification
