// Reporting the Fig. 12/13 runs: see borehole_fracture_report.hpp.
#include "borehole_fracture_report.hpp"

#include <cmath>
#include <fstream>
#include <numeric>
#include <stdexcept>

#include "hm/core/file_output.hpp"
#include "hm/lattice2d/mechanics/calibration.hpp"
#include "report_writer.hpp"

namespace hm::verification::borehole_fracture {

namespace lt = hm::lattice2d;
namespace fs = std::filesystem;

namespace {

std::string sign_word(double x) { return std::isnan(x) ? "-" : (x < 0.0 ? "negative" : "positive"); }

Metric flag(const std::string& name, bool value, const std::string& why, bool gating = true) {
  return {.name = name,
          .value = value ? 1.0 : 0.0,
          .reference = 1.0,
          .tolerance = 0.0,
          .comparison = Comparison::abs_error,
          .justification = why,
          .gating = gating};
}

/// The largest value of a field of the fluid over the output times (NaN where none is a number).
double largest(const std::vector<Snapshot>& snaps, double FracturePressure::*field) {
  double v = kNaN;
  for (const Snapshot& s : snaps)
    if (!std::isnan(s.fp.*field)) v = std::isnan(v) ? s.fp.*field : std::max(v, s.fp.*field);
  return v;
}

}  // namespace

std::string run_name(const RunOutcome& o) {
  return "b = " + fmt(o.b) + ", N = " + std::to_string(o.n_particles) + ", seed " + std::to_string(o.seed) +
         (o.eq16_node ? ", Eq. 16 node" : "");
}

std::string mean_sd(const std::vector<double>& x) {
  if (x.empty()) return "-";
  if (x.size() == 1) return fmt(x.front());
  const double n = static_cast<double>(x.size());
  const double mean = std::accumulate(x.begin(), x.end(), 0.0) / n;
  double ss = 0.0;
  for (double v : x) ss += (v - mean) * (v - mean);
  return fmt(mean) + " ± " + fmt(std::sqrt(ss / (n - 1.0)));
}

Table snapshot_table(const std::string& paper) {
  return {
      "Per output time: broken beams; radial fractures as clusters (connected to the borehole) and as arms "
      "crossing r = R_i + (1 - R_i)/4; radial clusters reaching r = 1; secondary clusters (all; those at least "
      "0.05 R long, most others are single broken beams; and of those, how many touch r = 1 and how many lie "
      "inside). Paper: " +
          paper,
      {"run", "t*", "n_broken", "radial (clusters)", "arms", "radial at r = 1", "secondary", "secondary >= 0.05",
       "... at r = 1 / inside", "paper: fractures (last time)"},
      {}};
}

void add_snapshot_rows(const RunOutcome& o, Table& t, const PaperReading& paper) {
  for (const auto& s : o.snaps)
    t.rows.push_back({run_name(o), fmt(s.t), std::to_string(s.stats.n_broken), std::to_string(s.stats.n_radial),
                      std::to_string(s.stats.n_arms), std::to_string(s.stats.n_radial_reaching_outer),
                      std::to_string(s.stats.n_secondary), std::to_string(s.stats.n_secondary_sizable),
                      std::to_string(s.secondary_at_outer) + " / " + std::to_string(s.secondary_inside),
                      &s == &o.snaps.back() ? paper.fractures_text() : ""});
}

Table fluid_table(const std::string& paper) {
  return {
      "The fluid per output time: borehole pressure; pressure range over all triangles; mean pressure in the "
      "fracture triangles (area-weighted over triangles with a broken beam, without / with the borehole-wall "
      "triangles), its minimum and sign; backflow into the borehole (wall segments draining into it); inflow "
      "through r = 1 (drawn in by the Mandel-Cryer suction near the free boundary in every run) and its part through "
      "the mouths of fractures at r = 1; each over the injection rate Q. Paper: " +
          paper,
      {"run", "t*", "p_h", "p min", "p max", "p in fractures (no wall tri.)", "with wall tri.", "min p in fractures",
       "sign", "backflow into borehole / Q", "inflow at r = 1 / Q", "... through fracture mouths / Q"},
      {}};
}

void add_fluid_rows(const RunOutcome& o, Table& t) {
  for (const auto& s : o.snaps)
    t.rows.push_back({run_name(o), fmt(s.t), fmt(s.p_h), fmt(s.fp.p_min), fmt(s.fp.p_max),
                      fmt(s.fp.mean_away) + " (" + std::to_string(s.fp.n_away) + " tri.)", fmt(s.fp.mean_all),
                      fmt(s.fp.min_away), sign_word(s.fp.mean_away), fmt(s.fp.borehole_backflow / o.Q),
                      fmt(s.fp.outer_inflow / o.Q), fmt(s.fp.mouth_inflow / o.Q)});
}

Table scatter_table(long long n_particles) {
  return {"Seed scatter at N = " + std::to_string(n_particles) +
              " (seeds 1, 2, 3 of the lattice and the strengths): "
              "mean ± sample standard deviation over the three runs",
          {"b", "t*", "n_broken", "radial (clusters)", "arms", "radial at r = 1", "secondary", "secondary >= 0.05",
           "p in fractures (no wall tri.)", "p_h"},
          {}};
}

Table scatter_breakdown_table(long long n_particles) {
  return {"Seed scatter at N = " + std::to_string(n_particles) + ": breakdown, mean ± sd over seeds 1, 2, 3",
          {"b", "t* first break", "p_h at first break", "t* peak", "p_h peak"},
          {}};
}

void add_scatter_rows(const std::string& b, const std::vector<RunOutcome>& seeds, Table& scatter, Table& breakdown) {
  // Mean ± sd per output time (the runs share the output times; a failed run is left out).
  std::vector<const RunOutcome*> ok;
  for (const auto& s : seeds)
    if (s.ok) ok.push_back(&s);
  if (ok.empty()) return;
  for (std::size_t k = 0; k < ok.front()->snaps.size(); ++k) {
    std::vector<double> nb, nr, na, no, ns, nz, fp, ph;
    for (const RunOutcome* s : ok) {
      if (k >= s->snaps.size()) continue;
      const Snapshot& q = s->snaps[k];
      nb.push_back(q.stats.n_broken), nr.push_back(q.stats.n_radial), na.push_back(q.stats.n_arms);
      no.push_back(q.stats.n_radial_reaching_outer), ns.push_back(q.stats.n_secondary);
      nz.push_back(q.stats.n_secondary_sizable);
      fp.push_back(q.fp.mean_away), ph.push_back(q.p_h);
    }
    scatter.rows.push_back({b, fmt(ok.front()->snaps[k].t), mean_sd(nb), mean_sd(nr), mean_sd(na), mean_sd(no),
                            mean_sd(ns), mean_sd(nz), mean_sd(fp), mean_sd(ph)});
  }
  std::vector<double> tf, pf, tp, pp;
  for (const RunOutcome* s : ok)
    tf.push_back(s->t_first), pf.push_back(s->p_first), tp.push_back(s->t_peak), pp.push_back(s->p_peak);
  breakdown.rows.push_back({b, mean_sd(tf), mean_sd(pf), mean_sd(tp), mean_sd(pp)});
}

Table breakdown_table() {
  return {
      "Breakdown (Section 3.5): the step that broke the first beam (its time, p_h^n before it, its converged "
      "p_h^{n+1}), where and how the first beam broke, the peak borehole pressure; before the first break, the "
      "2D p_h against fdm1d (no fracture, flux-boundary borehole) for t* >= " +
          fmt(kWindow),
      {"run", "t* first break", "p_h before", "p_h at first break", "first break: r (R_i), mode", "t* peak", "p_h peak",
       "max |p_h/p_h,1D - 1| before, t* >= " + fmt(kWindow) + " (at t*)", "p_h/p_h,1D - 1 just before (t*)",
       "max |u_r/u_r,1D - 1| unbroken snapshot",
       "flux-borehole twin: |p_h/p_h,1D - 1| at its end; max for t* >= " + fmt(kWindow) + " (at t*)",
       "twin: max |u_r/u_r,1D - 1| (t*)"},
      {}};
}

void add_breakdown_row(const RunOutcome& o, Table& t) {
  std::string u = "-";
  for (const auto& s : o.snaps)
    if (!std::isnan(s.u_pre)) u = fmt(s.u_pre) + " (t* = " + fmt(s.t) + ")";
  t.rows.push_back({run_name(o), fmt(o.t_first), fmt(o.p_before), fmt(o.p_first),
                    fmt(o.r_first) + " (" + fmt(o.R_i) + "), " + hm::core::name_of(o.mode_first), fmt(o.t_peak),
                    fmt(o.p_peak), fmt(o.pre_max) + " (" + fmt(o.pre_max_t) + ")",
                    fmt(o.pre_signed_last) + " (" + fmt(o.pre_last_t) + ")", u,
                    o.twin_label.empty()
                        ? "-"
                        : fmt(o.twin.end_error) + "; " + fmt(o.twin.max_error) + " (" + fmt(o.twin.max_error_t) + ")",
                    o.twin_label.empty() ? "-" : fmt(o.twin.u_error) + " (" + fmt(o.twin.t_end) + ")"});
}

Table timing_table() {
  return {
      "Runs: steps, coupling passes, step halvings, wall time and its split (sums of CoupledStepSummary's "
      "mechanical solves (break loops' included), stresses + downdates, geometry, flow), max volume-balance error "
      "per step",
      {"run", "steps", "passes", "halvings", "wall s", "mechanics s", "stresses + downdates s", "geometry s", "flow s",
       "balance"},
      {}};
}

void add_timing_row(const RunOutcome& o, Table& t) {
  t.rows.push_back({run_name(o), std::to_string(o.n_steps), std::to_string(o.passes),
                    o.n_halvings < 0 ? std::string("-") : std::to_string(o.n_halvings), fmt(o.seconds),
                    fmt(o.mechanics), fmt(o.fracture), fmt(o.geometry), fmt(o.flow), fmt(o.max_balance)});
}

/// What must hold for every run (gating), and the 1D comparison before the first break (not gating).
void add_gating_metrics(const RunOutcome& o, std::vector<Metric>& m) {
  const std::string tag = run_name(o) + ": ";
  m.push_back(flag(tag + "run completed (every step converged)", o.ok,
                   "a numerical failure is a failure: " + (o.message.empty() ? std::string("ok") : o.message)));
  m.push_back({.name = tag + "volume balance, max relative error per step",
               .value = o.max_balance,
               .reference = 0.0,
               .tolerance = 1e-8,
               .comparison = Comparison::at_most,
               .justification = "the flow scheme is conservative by construction, broken segments included: round-off "
                                "(measured <= 3e-11 per step; 1e-8 leaves margin)"});
  m.push_back(flag(tag + "first break tensile, at the borehole wall (|r - R_i| <= its beam length)",
                   o.mode_first == lt::FailureMode::tensile && std::abs(o.r_first - o.R_i) <= o.length_first,
                   "Section 3.2/3.3: the hoop stress is largest and tensile at the wall, so fractures initiate there "
                   "in tension (measured: r = " +
                       fmt(o.r_first) + ", " + hm::core::name_of(o.mode_first) + ")"));
  m.push_back({.name = tag + "radial fractures at the last output time",
               .value = o.snaps.empty() ? 0.0 : static_cast<double>(o.snaps.back().stats.n_radial),
               .reference = 1.0,
               .tolerance = 1.0,
               .comparison = Comparison::at_least,
               .justification = "Fig. 12: radial fractures initiate at the borehole wall in both cases; how many is "
                                "the non-gating comparison below"});
  m.push_back({.name = tag + "broken beams found intact again, and steps where n_broken fell",
               .value = static_cast<double>(o.n_healed + o.n_broken_decreases),
               .reference = 0.0,
               .tolerance = 0.0,
               .comparison = Comparison::at_most,
               .justification = "Section 2.1: breaking is irreversible (no healing); checked after every step"});
  m.push_back(
      {.name = tag + "|p_h/p_h,1D - 1| at the last step before the first break (t* = " + fmt(o.pre_last_t) + ")",
       .value = o.pre_last,
       .reference = 0.0,
       .tolerance = 0.05,
       .comparison = Comparison::at_most,
       .justification = "information, not gating: the first breaks come in the first steps, where the lattice "
                        "cannot resolve the wall's pressure boundary layer sqrt(t/S) (p_h +73% to +250% above 1D at "
                        "t* = 1e-5, N = 1e4, docs/lattice_vs_fdm1d.md; nan: the first step already broke). Eq. 16's "
                        "borehole node instead holds p_h 75-83% below 1D (errata E15); the unfractured twin below "
                        "is what is gated",
       .gating = false});
  if (o.twin_label.empty()) return;
  // The twin's tolerances. N >= 1e4: 5%, the bound on the lattice's spatial discretisation error against
  // 1D that lattice2d.vs_fdm1d holds at N = 1e4 and 3e4 with the same borehole (measured <= 3.2%).
  // Coarser (the quick tier's N = 3000, h ~ 0.034): regression guards at ~1.5x the values measured on
  // 2026-11-22 (seed 1), each with its reason.
  const bool fine = o.n_particles >= 10000;
  m.push_back(flag(tag + "flux-borehole twin (no fracture) completed", o.twin.ok, "a numerical failure is a failure"));
  m.push_back({.name = tag + "flux-borehole twin: |p_h/p_h,1D - 1| at t* = " + fmt(o.twin.t_end),
               .value = o.twin.end_error,
               .reference = 0.0,
               .tolerance = 0.05,
               .comparison = Comparison::at_most,
               .justification = "the lattice's spatial discretisation error in p_h against 1D, within 5% (measured at "
                                "N = 3000: 0.3% for b = 0.2 at t* = 4.5e-3, 4.6% for b = 0.8 at t* = 2.3e-3)"});
  m.push_back(
      {.name = tag + "flux-borehole twin: max |p_h/p_h,1D - 1|, " + fmt(kWindow) + " <= t* <= " + fmt(o.twin.t_end),
       .value = o.twin.max_error,
       .reference = 0.0,
       .tolerance = fine ? 0.05 : 0.13,
       .comparison = Comparison::at_most,
       .justification = fine ? std::string("the lattice's discretisation error against 1D over t* >= 1e-3: 5%, as "
                                           "lattice2d.vs_fdm1d")
                             : std::string("regression guard at N = 3000: measured 0.7% (b = 0.2), 11.2% (b = 0.8, at "
                                           "t* = 1.06e-3, where the wall boundary layer sqrt(t/S) = 0.024 is under "
                                           "one lattice spacing, 0.034; it decays to 4.6% by t* = 2.3e-3)")});
  m.push_back(
      {.name = tag + "flux-borehole twin: max |u_r/u_r,1D - 1| over shells at t* = " + fmt(o.twin.t_end),
       .value = o.twin.u_error,
       .reference = 0.0,
       .tolerance = fine ? 0.05 : 0.12,
       .comparison = Comparison::at_most,
       .justification = fine ? std::string("the lattice's discretisation error against 1D: 5%, as "
                                           "lattice2d.vs_fdm1d")
                             : std::string("regression guard at N = 3000: the wall row's first-order error, 7.6% "
                                           "at N = 4000 (lattice2d.vs_fdm1d_quick), 2.3-3.2% at N = 1e4; "
                                           "measured 8.1% (b = 0.2), 2.5% (b = 0.8)")});
}

/// The paper's reading of the run's figure, shown beside ours (never gating).
void add_paper_metrics(const RunOutcome& o, std::vector<Metric>& m, const PaperReading& paper) {
  if (o.snaps.empty()) return;
  using Secondary = PaperReading::Secondary;
  using Sign = PaperReading::FracturePressureSign;
  const std::string tag = run_name(o) + ": ";
  const Snapshot& last = o.snaps.back();
  const std::string why =
      "the paper's " + paper.figure + " (N = 1e5, one realisation): \"" + paper.quote + "\"; shown, not tuned";
  const auto shown = [&](const std::string& name, double value, double reference, double tolerance, Comparison c) {
    m.push_back({.name = tag + name,
                 .value = value,
                 .reference = reference,
                 .tolerance = tolerance,
                 .comparison = c,
                 .justification = why,
                 .gating = false});
  };
  if (paper.fractures != PaperReading::not_stated) {
    shown("radial fractures (arms) at t* = " + fmt(last.t), last.stats.n_arms, paper.fractures, 0.0,
          Comparison::abs_error);
    shown("radial fractures (clusters) at t* = " + fmt(last.t), last.stats.n_radial, paper.fractures, 0.0,
          Comparison::abs_error);
  }
  if (paper.reaching_outer == PaperReading::all)
    m.push_back(flag(tag + "every radial fracture reaches r = 1 at t* = " + fmt(last.t),
                     last.stats.n_radial > 0 && last.stats.n_radial_reaching_outer == last.stats.n_radial,
                     why + " (" + std::to_string(last.stats.n_radial_reaching_outer) + " of " +
                         std::to_string(last.stats.n_radial) + ")",
                     false));
  else if (paper.reaching_outer >= 0)
    shown("radial fractures reaching r = 1 at t* = " + fmt(last.t), last.stats.n_radial_reaching_outer,
          paper.reaching_outer, 0.0, Comparison::abs_error);
  const int n_sizable = last.secondary_at_outer + last.secondary_inside;
  if (paper.secondary == Secondary::none)
    shown("secondary fractures >= 0.05 long at t* = " + fmt(last.t), n_sizable, 0.0, 0.0, Comparison::abs_error);
  if (paper.secondary == Secondary::at_outer_boundary || paper.secondary == Secondary::between_primaries) {
    const bool outer = paper.secondary == Secondary::at_outer_boundary;
    shown("share of the secondary fractures >= 0.05 long that touch r = 1 at t* = " + fmt(last.t) + " (" +
              std::to_string(n_sizable) + " of them)",
          n_sizable > 0 ? static_cast<double>(last.secondary_at_outer) / n_sizable : kNaN, outer ? 1.0 : 0.0, 0.5,
          outer ? Comparison::at_least : Comparison::at_most);
  }
  for (const auto& s : o.snaps) {
    if (s.fp.n_away == 0 || paper.pressure == Sign::not_stated) continue;
    if (paper.pressure == Sign::negative_at_last_time && &s != &last) continue;
    shown("mean pressure in the fractures (no wall triangles) at t* = " + fmt(s.t), s.fp.mean_away, 0.0, 0.0,
          Comparison::at_most);
  }
  const double backflow = largest(o.snaps, &FracturePressure::borehole_backflow);
  const double inflow = largest(o.snaps, &FracturePressure::mouth_inflow);
  // 1e-3 Q: a backflow of a thousandth of the injection, far above the flow solve's round-off.
  if (paper.backflow_into_borehole)
    shown("largest backflow into the borehole over the output times, / Q", backflow / o.Q, 1.0, 1e-3,
          Comparison::at_least);
  if (paper.backflow_into_domain)
    shown("largest inflow through fracture mouths at r = 1 over the output times, / Q", inflow / o.Q, 1.0, 1e-3,
          Comparison::at_least);
  if (paper.borehole_pressure_drops)
    shown("p_h at t* = " + fmt(last.t) + " over its peak (" + fmt(o.p_peak) + " at t* = " + fmt(o.t_peak) + ")",
          last.p_h / o.p_peak, 1.0, 0.99, Comparison::at_most);
}

/// runs.csv: which folder is which (text columns; read by the figure scripts with csv.DictReader).
void write_index(const fs::path& root, const std::vector<RunOutcome>& runs, const std::vector<bool>& in_figure,
                 const RunSource& source) {
  std::ofstream f = core::open_for_writing(root / "runs.csv");
  f << "run,b,n_particles,seed,fdm1d,figure,flux_twin,eq16_node\n";
  for (std::size_t k = 0; k < runs.size(); ++k)
    f << source.folder(runs[k].label) << "," << fmt(runs[k].b) << "," << runs[k].n_particles << "," << runs[k].seed
      << ",fdm1d_b" << fmt(runs[k].b) << "," << (in_figure[k] ? 1 : 0) << "," << source.folder(runs[k].twin_label)
      << "," << source.folder(runs[k].eq16_label) << "\n";
  core::close_checked(f, root / "runs.csv");
}

std::vector<Figure> figures(const std::string& subdir, const std::string& what) {
  return {
      {"fig12_fracture_pressure.py", "fig12_fracture_pressure.png",
       "Fig. 12 (" + what +
           "): pressure per triangle (diverging colours centred on 0, limits from each snapshot's "
           "min and max), broken beams in black, the borehole outline, at the case's output times; b = 0.2 (top), "
           "0.8 (bottom).",
       subdir},
      {"fig13_displacement_vs_1d.py", "fig13_displacement_vs_1d.png",
       "Fig. 13 (" + what +
           "): radially averaged u_r of the fracturing lattice (solid, markers) and of fdm1d "
           "without fracture (dashed) at the paper's times; borehole pressure 2D vs 1D with the first break marked.",
       subdir}};
}

std::string notes_common() {
  return "Definitions (docs/borehole_fracture.md): a *fracture* is a cluster of broken beams connected through shared "
         "particles (fracture_statistics.hpp; `hmlattice fractures <run> --link triangle` recomputes a run with the "
         "stricter shared-triangle rule, which cut the N = 1e5 fractures into pieces); *radial* clusters contain a "
         "broken borehole-wall beam. Cracks that "
         "merge at the wall form one cluster, so the count comparable with the paper's figure is the number of "
         "*arms*: groups of broken beams crossing the circle r = R_i + (1 - R_i)/4. The *pressure in the fractures* "
         "is the area-weighted mean over the triangles that have a broken beam, without the triangles on the "
         "borehole wall (their pressure follows p_h through the wall segment); the mean with them is shown beside. "
         "The 1D reference is fdm1d with the calibrated lattice's nu = " +
         fmt(lt::calibrated_continuum().poisson_ratio) +
         ", the case's E/M, plane-strain volumetric strain, n_r = 400, on the case's dt sequence; it has no "
         "fracture and a flux-boundary borehole (no storage), as the cases (errata E15: Eq. 16's borehole node "
         "would hold p_h 75-83% below 1D before the first break). What is gated against 1D is the *unfractured twin* "
         "(same case and lattice, fracture off, to the first output time; folders <case>_flux_borehole/, dotted in "
         "Fig. 13).";
}

namespace {

/// "b = 0.2, N = 20000, seeds 1, 2, 3, Eq. 16 node": a group of runs of one case and one node.
std::string group_name(const std::vector<const RunOutcome*>& g) {
  const RunOutcome& f = *g.front();
  std::string seeds;
  for (const RunOutcome* o : g) seeds += (seeds.empty() ? "" : ", ") + std::to_string(o->seed);
  return "b = " + fmt(f.b) + ", N = " + std::to_string(f.n_particles) + (g.size() > 1 ? ", seeds " : ", seed ") +
         seeds + (f.eq16_node ? ", Eq. 16 node" : ", flux node");
}

/// Of the completed runs in g, a value per run (NaN ones left out).
template <class F>
std::vector<double> values(const std::vector<const RunOutcome*>& g, F of) {
  std::vector<double> v;
  for (const RunOutcome* o : g)
    if (o->ok && !o->snaps.empty() && !std::isnan(of(*o))) v.push_back(of(*o));
  return v;
}

double first_snapshot_unbroken(const RunOutcome& o) { return o.snaps.front().stats.n_broken == 0 ? 1.0 : 0.0; }

double mean_of(const std::vector<double>& v) {
  return v.empty() ? kNaN : std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

}  // namespace

Table borehole_node_table() {
  return {
      "Borehole node (errata E15, E16): the cases' flux boundary (no storage, no b dV_h: fdm1d's borehole) "
      "against Eq. 16 as printed (`[flow] borehole_storage = \"biot-modulus\"`, `borehole_deformation = "
      "\"biot\"`); mean ± sd over seeds. Unbroken at Fig. 13's first time: the fraction of runs with no broken "
      "beam at the case's first output time (the paper: none broken at t* = 4.5e-3 for b = 0.2, 2.3e-3 for "
      "b = 0.8), and there u_r/u_r,1D averaged over the shells (the paper: the lattice fits the 1D model). "
      "Counts at the last output time",
      {"runs", "t* first break", "p_h at first break", "unbroken at first output t*", "u_r/u_r,1D there", "n_broken",
       "arms", "radial (clusters)", "radial at r = 1", "secondary", "p_h peak", "paper: fractures"},
      {}};
}

void add_borehole_node_row(const std::vector<const RunOutcome*>& g, Table& t, const PaperReading& paper) {
  if (g.empty()) return;
  const auto last = [](auto field) {
    return [field](const RunOutcome& o) { return static_cast<double>(field(o.snaps.back().stats)); };
  };
  t.rows.push_back({group_name(g), mean_sd(values(g, [](const RunOutcome& o) { return o.t_first; })),
                    mean_sd(values(g, [](const RunOutcome& o) { return o.p_first; })),
                    mean_sd(values(g, first_snapshot_unbroken)) +
                        " (t* = " + fmt(g.front()->snaps.empty() ? kNaN : g.front()->snaps.front().t) + ")",
                    mean_sd(values(g, [](const RunOutcome& o) { return o.snaps.front().u_ratio_mean; })),
                    mean_sd(values(g, last([](const lt::FractureStatistics& s) { return s.n_broken; }))),
                    mean_sd(values(g, last([](const lt::FractureStatistics& s) { return s.n_arms; }))),
                    mean_sd(values(g, last([](const lt::FractureStatistics& s) { return s.n_radial; }))),
                    mean_sd(values(g, last([](const lt::FractureStatistics& s) { return s.n_radial_reaching_outer; }))),
                    mean_sd(values(g, last([](const lt::FractureStatistics& s) { return s.n_secondary; }))),
                    mean_sd(values(g, [](const RunOutcome& o) { return o.p_peak; })), paper.fractures_text()});
}

void add_borehole_node_metrics(const std::vector<const RunOutcome*>& flux, const std::vector<const RunOutcome*>& eq16,
                               std::vector<Metric>& m) {
  const std::string paper =
      "the paper's Fig. 13 (no fracture at its first time, the lattice on the 1D curve): shown, "
      "not tuned; with Table 1's T_u the 1D wall passes T_u long before (errata E16)";
  for (const auto* g : {&flux, &eq16}) {
    const std::vector<double> unbroken = values(*g, first_snapshot_unbroken);
    if (unbroken.empty()) continue;
    const double t1 = g->front()->snaps.front().t;
    m.push_back({.name = group_name(*g) + ": fraction of runs unbroken at t* = " + fmt(t1),
                 .value = mean_of(unbroken),
                 .reference = 1.0,
                 .tolerance = 0.0,
                 .comparison = Comparison::abs_error,
                 .justification = paper,
                 .gating = false});
    const std::vector<double> u = values(*g, [](const RunOutcome& o) { return o.snaps.front().u_ratio_mean; });
    if (!u.empty())
      m.push_back({.name = group_name(*g) + ": u_r/u_r,1D (mean over shells, unbroken runs) at t* = " + fmt(t1),
                   .value = mean_of(u),
                   .reference = 1.0,
                   .tolerance = 0.05,
                   .comparison = Comparison::rel_error,
                   .justification = paper + "; 5% as the 2D-vs-1D comparison before fracture (lattice2d.vs_fdm1d)",
                   .gating = false});
  }
  const double t_flux = mean_of(values(flux, [](const RunOutcome& o) { return o.t_first; }));
  const double t_eq16 = mean_of(values(eq16, [](const RunOutcome& o) { return o.t_first; }));
  if (flux.empty() || eq16.empty() || std::isnan(t_flux) || std::isnan(t_eq16)) return;
  m.push_back({.name = group_name(eq16) + ": first break t*, Eq. 16 node / flux node (mean over seeds)",
               .value = t_eq16 / t_flux,
               .reference = 1.0,
               .tolerance = 1.0,
               .comparison = Comparison::at_least,
               .justification = "information: Eq. 16's storage holds p_h low early on (errata E15), so the wall "
                                "reaches T_u later; measured 24x (b = 0.2) and ~28x (b = 0.8) at N = 2e4",
               .gating = false});
}

std::string notes_borehole_node() {
  return "Borehole node (docs/borehole_fracture.md, \"Which borehole node\"): the cases use a flux-boundary borehole, "
         "under which the unfractured lattice follows the 1D model (gated by the twin). The paper's Eq. 16 node as "
         "printed is run beside it on the same lattices and strengths: it delays the first break and roughly halves "
         "the damage and the arm count, the largest single lever on the counts we found, but before the first "
         "break it holds u_r far below the 1D model (errata E15), where the paper's Fig. 13 has the lattice on the 1D "
         "curve; and neither node makes the paper's fracture-free Fig. 13 times consistent with Table 1's T_u "
         "(errata E16).";
}

}  // namespace hm::verification::borehole_fracture
