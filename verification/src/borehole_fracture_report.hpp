#pragma once
// Reporting the Fig. 12/13 runs (borehole_fracture_runs.hpp): the report's tables, the gating metrics and
// the paper's values shown beside ours, runs.csv for the figure scripts, the figures and the notes.
#include <filesystem>
#include <string>
#include <vector>

#include "borehole_fracture_runs.hpp"
#include "hm/verification/benchmark.hpp"
#include "paper_readings.hpp"

namespace hm::verification::borehole_fracture {

/// "b = 0.2, N = 3000, seed 1" (", Eq. 16 node" for that variant): how a run is named in every table.
std::string run_name(const RunOutcome& o);

/// "m ± s" (sample standard deviation) of several values; the value itself for one.
std::string mean_sd(const std::vector<double>& x);

/// The fracture counts per output time; `paper` says what the paper's figure shows.
Table snapshot_table(const std::string& paper);
void add_snapshot_rows(const RunOutcome& o, Table& t, const PaperReading& paper);
/// The fluid per output time: p_h, the pressure range and in the fractures, backflows.
Table fluid_table(const std::string& paper);
void add_fluid_rows(const RunOutcome& o, Table& t);
/// Mean ± sd over the seed runs of one case: per output time, and of the breakdown (a failed run is left out).
Table scatter_table(long long n_particles);
Table scatter_breakdown_table(long long n_particles);
void add_scatter_rows(const std::string& b, const std::vector<RunOutcome>& seeds, Table& scatter, Table& breakdown);
Table breakdown_table();
void add_breakdown_row(const RunOutcome& o, Table& t);
Table timing_table();
void add_timing_row(const RunOutcome& o, Table& t);

/// The borehole-node comparison (errata E15, E16): per group of runs (one case, one node, one or more
/// seeds) the first break, whether the case is unbroken at Fig. 13's first time, the damage and the
/// counts at the last time, beside the paper's.
Table borehole_node_table();
void add_borehole_node_row(const std::vector<const RunOutcome*>& group, Table& t, const PaperReading& paper);
/// Shown beside the paper, never gating: how far the Eq. 16 node moves the first break and the counts.
void add_borehole_node_metrics(const std::vector<const RunOutcome*>& flux, const std::vector<const RunOutcome*>& eq16,
                               std::vector<Metric>& m);

/// What must hold for every run (gating), and the 1D comparison before the first break (not gating).
void add_gating_metrics(const RunOutcome& o, std::vector<Metric>& m);
/// The paper's reading of the run's figure, shown beside ours (never gating).
void add_paper_metrics(const RunOutcome& o, std::vector<Metric>& m, const PaperReading& paper);

/// runs.csv: which folder is which (text columns; read by the figure scripts with csv.DictReader).
/// `source` says where each run's folder is (RunSource::folder).
void write_index(const std::filesystem::path& root, const std::vector<RunOutcome>& runs,
                 const std::vector<bool>& in_figure, const RunSource& source);

/// Figs. 12 and 13 drawn from root/<subdir>; `what` names the tier in the captions.
std::vector<Figure> figures(const std::string& subdir, const std::string& what);

/// The definitions every Fig. 12 report needs (fracture, arm, pressure in the fractures, the 1D reference).
std::string notes_common();
/// What the borehole-node table shows and why the cases keep the flux boundary.
std::string notes_borehole_node();

}  // namespace hm::verification::borehole_fracture
