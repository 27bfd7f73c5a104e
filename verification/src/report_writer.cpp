#include "report_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "hm/core/file_output.hpp"
#include "paper_readings.hpp"

namespace hm::verification {

using cases::Provenance;

namespace fs = std::filesystem;

std::string format_number(double value) {
  if (!std::isfinite(value)) return std::isnan(value) ? "nan" : (value > 0 ? "inf" : "-inf");
  char buf[32];
  const double a = std::abs(value);
  if (a != 0.0 && (a < 1e-3 || a >= 1e5))
    std::snprintf(buf, sizeof buf, "%.3e", value);
  else
    std::snprintf(buf, sizeof buf, "%.5g", value);
  return buf;
}

namespace {

std::string comparison_text(const Metric& m) {
  switch (m.comparison) {
    case Comparison::abs_error: return "|value − ref| ≤ " + format_number(m.tolerance);
    case Comparison::rel_error: return "rel. error ≤ " + format_number(m.tolerance);
    case Comparison::at_most: return "≤ " + format_number(m.tolerance);
    case Comparison::at_least: return "≥ " + format_number(m.tolerance);
  }
  return "";
}

std::string verdict(const Metric& m) {
  if (!m.gating) return m.passes() ? "agrees (info)" : "differs (info)";
  return m.passes() ? "pass" : "**FAIL**";
}

std::string cell(const std::string& s) {  // keep markdown tables intact
  std::string out;
  for (char c : s) out += (c == '|') ? std::string("\\|") : std::string(1, c == '\n' ? ' ' : c);
  return out;
}

std::string reference_text(const Metric& m) {  // bounds (at_most/at_least) usually have no reference
  const bool bound = m.comparison == Comparison::at_most || m.comparison == Comparison::at_least;
  return (bound && m.reference == 0.0) ? "—" : format_number(m.reference);
}

void write_table(std::ostream& md, const Table& t) {
  if (!t.title.empty()) md << "*" << t.title << "*\n\n";
  md << "|";
  for (const auto& h : t.header) md << " " << cell(h) << " |";
  md << "\n|";
  for (std::size_t i = 0; i < t.header.size(); ++i) md << "---|";
  md << "\n";
  for (const auto& row : t.rows) {
    md << "|";
    for (const auto& c : row) md << " " << cell(c) << " |";
    md << "\n";
  }
  md << "\n";
}

// Every result figure of the paper, the benchmarks of each tier that draw it (declared with the
// benchmark, Benchmark::paper_figures), and where it is in this report.
void write_paper_figures(std::ostream& md, const std::vector<BenchmarkOutcome>& outcomes) {
  const auto drawing = [](const std::string& number, Tier tier) {
    std::string ids;
    for (const Benchmark& b : all_benchmarks())
      if (b.tier == tier && std::find(b.paper_figures.begin(), b.paper_figures.end(), number) != b.paper_figures.end())
        ids += (ids.empty() ? "`" : ", `") + b.id + "`";
    return ids.empty() ? std::string("-") : ids;
  };
  md << "## The paper's result figures\n\nWhich benchmark regenerates each of the paper's result figures "
        "(`hmlattice verify --tier T --filter ID`), and where it is drawn in this report.\n\n"
        "| figure | what it shows | quick tier | paper tier adds | in this report |\n|---|---|---|---|---|\n";
  for (const PaperFigure& f : paper_result_figures()) {
    std::string here;
    for (const auto& o : outcomes) {
      const auto& figs = o.benchmark->paper_figures;
      if (std::find(figs.begin(), figs.end(), f.number) != figs.end() && o.error.empty())
        here += (here.empty() ? "" : ", ") + ("[" + o.benchmark->id + "](#" + o.benchmark->id + ")");
    }
    md << "| " << f.number << " | " << cell(f.subject) << " | " << drawing(f.number, Tier::quick) << " | "
       << drawing(f.number, Tier::paper) << " | " << (here.empty() ? "-" : here) << " |\n";
  }
  md << "\n";
}

int failed_gating(const BenchmarkOutcome& o) {
  int n = 0;
  for (const auto& m : o.result.metrics) n += (m.gating && !m.passes());
  return n;
}

}  // namespace

void write_report_markdown(const fs::path& file, const std::vector<BenchmarkOutcome>& outcomes, const Provenance& prov,
                           Tier tier) {
  core::write_file_atomically(file, [&](std::ostream& md) {
    md << "# hmlattice verification report\n\n"
       << "Tier **" << (tier == Tier::quick ? "quick" : "paper") << "**; hmlattice " << prov.version << " (commit "
       << prov.git_commit << ", " << prov.build_type << "), " << prov.utc_time << ".  \n"
       << "Command: `" << prov.command_line << "`\n\n"
       << "Each metric states what is compared, the tolerance and where that tolerance comes from. "
          "Metrics marked *(info)* compare with numbers read from the paper; they are shown, never tuned, "
          "and do not decide the verdict. Machine-readable values: `metrics.json`.\n\n"
       << "## Summary\n\n| benchmark | metrics | failed | time [s] |\n|---|---|---|---|\n";
    for (const auto& o : outcomes) {
      const std::string failed = o.error.empty() ? std::to_string(failed_gating(o)) : "error";
      md << "| [" << o.benchmark->title << "](#" << o.benchmark->id << ") | " << o.result.metrics.size() << " | "
         << failed << " | " << format_number(o.seconds) << " |\n";
    }
    md << "\n";
    write_paper_figures(md, outcomes);
    for (const auto& o : outcomes) {
      const Benchmark& b = *o.benchmark;
      md << "<a id=\"" << b.id << "\"></a>\n## " << b.title << "\n\n`" << b.id << "`. " << b.description << "\n\n";
      if (!o.error.empty()) md << "**The benchmark stopped with an error:** " << o.error << "\n\n";
      if (!o.result.metrics.empty()) {
        md << "| metric | value | reference | check | verdict | why this tolerance |\n|---|---|---|---|---|---|\n";
        for (const auto& m : o.result.metrics)
          md << "| " << cell(m.name) << " | " << format_number(m.value) << " | " << reference_text(m) << " | "
             << comparison_text(m) << " | " << verdict(m) << " | " << cell(m.justification) << " |\n";
        md << "\n";
      }
      for (const auto& t : o.result.tables) write_table(md, t);
      for (const auto& f : o.result.figures)
        md << "![" << f.caption << "](figures/" << o.benchmark->id << "/" << f.file << ")\n\n*" << f.caption << "*\n\n";
      for (const auto& e : o.figure_errors) md << "> Figure missing: " << e << "\n\n";
      for (const auto& n : o.result.notes) md << n << "\n\n";
    }
  });
}

void write_metrics_json(const fs::path& file, const std::vector<BenchmarkOutcome>& outcomes) {
  auto number = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  nlohmann::json list = nlohmann::json::array();
  for (const auto& o : outcomes) {
    if (!o.error.empty())
      list.push_back({{"benchmark", o.benchmark->id},
                      {"metric", "error"},
                      {"value", nullptr},
                      {"reference", nullptr},
                      {"tolerance", nullptr},
                      {"pass", false},
                      {"gating", true},
                      {"error", o.error}});
    for (const auto& m : o.result.metrics)
      list.push_back({{"benchmark", o.benchmark->id},
                      {"metric", m.name},
                      {"value", number(m.value)},
                      {"reference", number(m.reference)},
                      {"tolerance", number(m.tolerance)},
                      {"pass", m.passes()},
                      {"gating", m.gating},
                      {"justification", m.justification}});
  }
  core::write_file_atomically(file, [&](std::ostream& out) { out << list.dump(2) << "\n"; });
}

}  // namespace hm::verification
