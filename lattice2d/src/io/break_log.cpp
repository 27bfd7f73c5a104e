#include "hm/lattice2d/io/break_log.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "hm/core/csv_writer.hpp"
#include "hm/core/file_output.hpp"
#include "hm/core/input_error.hpp"

namespace hm::lattice2d {

using core::csv_number;

namespace {

// The headers of the two logs around their load column, whose name the caller chooses.
const std::string kBreakHeaderBefore = "sequence,beam,particle_i,particle_j,x,y,";
const std::string kBreakHeaderAfter = ",sigma_1,sigma_3,ratio,crack_tip_factor,mode";
const std::string kToothHeaderBefore = "sequence,beam,";
const std::string kToothHeaderAfter = ",tooth,stiffness_factor,axial_stress,ratio,energy";

}  // namespace

void write_break_log_header(std::ostream& out, const std::string& load_column) {
  out << kBreakHeaderBefore << load_column << kBreakHeaderAfter << '\n';
}

void write_break_log_rows(std::ostream& out, const std::vector<BreakEvent>& events) {
  for (const BreakEvent& ev : events)
    out << ev.sequence << ',' << ev.beam << ',' << ev.particle_i << ',' << ev.particle_j << ','
        << csv_number(ev.position.x()) << ',' << csv_number(ev.position.y()) << ',' << csv_number(ev.load) << ','
        << csv_number(ev.sigma_1) << ',' << csv_number(ev.sigma_3) << ',' << csv_number(ev.ratio) << ','
        << csv_number(ev.crack_tip_factor) << ',' << core::name_of(ev.mode) << '\n';
}

void write_break_log(const std::filesystem::path& path, const std::vector<BreakEvent>& events,
                     const std::string& load_column) {
  core::write_file_atomically(path, [&](std::ostream& out) {
    write_break_log_header(out, load_column);
    write_break_log_rows(out, events);
  });
}

void write_tooth_log(const std::filesystem::path& path, const std::vector<ToothEvent>& events,
                     const std::string& load_column) {
  core::write_file_atomically(path, [&](std::ostream& out) {
    out << kToothHeaderBefore << load_column << kToothHeaderAfter << '\n';
    for (const ToothEvent& ev : events)
      out << ev.sequence << ',' << ev.beam << ',' << csv_number(ev.load) << ',' << ev.tooth << ','
          << csv_number(ev.stiffness_factor) << ',' << csv_number(ev.axial_stress) << ',' << csv_number(ev.ratio) << ','
          << csv_number(ev.energy) << '\n';
  });
}

namespace {

// The rows of a log written by this file's writers: the header checked by `header_ok` (its text echoed
// in the error as `expected_header`), each data row split into `n_columns` cells and handed to
// `parse_row` with number parsers that name the file and line of a malformed cell.
class LogRows {
 public:
  explicit LogRows(const std::filesystem::path& path) : path_(path), in_(path) {
    if (!in_) throw InputError("cannot read the log " + path.string());
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(path_.string() + ":" + std::to_string(line_no_) + ": " + what);
  }
  template <class HeaderOk, class ParseRow>
  void read(HeaderOk header_ok, const std::string& expected_header, std::size_t n_columns, ParseRow parse_row) {
    std::string line;
    std::getline(in_, line);
    if (!header_ok(line)) fail("header '" + core::echo(line) + "', expected '" + expected_header + "'");
    while (std::getline(in_, line)) {
      ++line_no_;
      if (line.empty()) continue;
      cells_.clear();
      std::stringstream row(line);
      for (std::string cell; std::getline(row, cell, ',');) cells_.push_back(cell);
      if (cells_.size() != n_columns)
        fail(std::to_string(cells_.size()) + " columns, expected " + std::to_string(n_columns));
      try {
        parse_row(cells_);
      } catch (const std::logic_error&) {  // std::invalid_argument and std::out_of_range
        fail("not a number in '" + core::echo(line) + "'");
      }
    }
  }
  static int integer(const std::string& c) {
    std::size_t used = 0;
    const int v = std::stoi(c, &used);
    if (used != c.size()) throw std::invalid_argument(c);
    return v;
  }
  static double real(const std::string& c) {
    std::size_t used = 0;
    const double v = std::stod(c, &used);
    if (used != c.size()) throw std::invalid_argument(c);
    return v;
  }

 private:
  std::filesystem::path path_;
  std::ifstream in_;
  int line_no_ = 1;
  std::vector<std::string> cells_;
};

// A header "<before><load column><after>" with a load column of any name.
auto header_around(const std::string& before, const std::string& after) {
  return [before, after](const std::string& line) {
    return line.rfind(before, 0) == 0 && line.size() >= before.size() + after.size() &&
           line.compare(line.size() - after.size(), after.size(), after) == 0;
  };
}

}  // namespace

std::vector<BreakEvent> read_break_log(const std::filesystem::path& path) {
  const std::string &before = kBreakHeaderBefore, &after = kBreakHeaderAfter;
  std::vector<BreakEvent> events;
  LogRows rows(path);
  rows.read(header_around(before, after), before + "<load>" + after, 12, [&](const std::vector<std::string>& c) {
    BreakEvent ev;
    ev.sequence = LogRows::integer(c[0]);
    ev.beam = LogRows::integer(c[1]);
    ev.particle_i = LogRows::integer(c[2]);
    ev.particle_j = LogRows::integer(c[3]);
    ev.position = Eigen::Vector2d(LogRows::real(c[4]), LogRows::real(c[5]));
    ev.load = LogRows::real(c[6]);
    ev.sigma_1 = LogRows::real(c[7]);
    ev.sigma_3 = LogRows::real(c[8]);
    ev.ratio = LogRows::real(c[9]);
    ev.crack_tip_factor = LogRows::real(c[10]);
    try {
      ev.mode = core::from_name<FailureMode>(c[11], "mode", {FailureMode::tensile, FailureMode::shear});
    } catch (const InputError& e) {
      rows.fail(e.what());
    }
    events.push_back(ev);
  });
  return events;
}

std::vector<ToothEvent> read_tooth_log(const std::filesystem::path& path) {
  const std::string &before = kToothHeaderBefore, &after = kToothHeaderAfter;
  std::vector<ToothEvent> events;
  LogRows rows(path);
  rows.read(header_around(before, after), before + "<load>" + after, 8, [&](const std::vector<std::string>& c) {
    ToothEvent ev;
    ev.sequence = LogRows::integer(c[0]);
    ev.beam = LogRows::integer(c[1]);
    ev.load = LogRows::real(c[2]);
    ev.tooth = LogRows::integer(c[3]);
    ev.stiffness_factor = LogRows::real(c[4]);
    ev.axial_stress = LogRows::real(c[5]);
    ev.ratio = LogRows::real(c[6]);
    ev.energy = LogRows::real(c[7]);
    events.push_back(ev);
  });
  return events;
}

}  // namespace hm::lattice2d
