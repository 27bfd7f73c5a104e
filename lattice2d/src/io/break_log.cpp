#include "hm/lattice2d/io/break_log.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "hm/core/csv_writer.hpp"
#include "hm/core/file_output.hpp"
#include "hm/core/input_error.hpp"

namespace hm::lattice2d {

using core::csv_number;

void write_break_log_header(std::ostream& out, const std::string& load_column) {
  out << "sequence,beam,particle_i,particle_j,x,y," << load_column << ",sigma_1,sigma_3,ratio,crack_tip_factor,mode\n";
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
    out << "sequence,beam," << load_column << ",tooth,stiffness_factor,axial_stress,ratio,energy\n";
    for (const ToothEvent& ev : events)
      out << ev.sequence << ',' << ev.beam << ',' << csv_number(ev.load) << ',' << ev.tooth << ','
          << csv_number(ev.stiffness_factor) << ',' << csv_number(ev.axial_stress) << ',' << csv_number(ev.ratio) << ','
          << csv_number(ev.energy) << '\n';
  });
}

std::vector<BreakEvent> read_break_log(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read the break log " + path.string());
  int line_no = 1;
  const auto fail = [&](const std::string& what) {
    throw InputError(path.string() + ":" + std::to_string(line_no) + ": " + what);
  };
  std::string line;
  std::getline(in, line);
  const std::string before = "sequence,beam,particle_i,particle_j,x,y,";
  const std::string after = ",sigma_1,sigma_3,ratio,crack_tip_factor,mode";
  if (line.rfind(before, 0) != 0 || line.size() < before.size() + after.size() ||
      line.compare(line.size() - after.size(), after.size(), after) != 0)
    fail("header '" + core::echo(line) + "', expected '" + before + "<load>" + after + "'");
  std::vector<BreakEvent> events;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty()) continue;
    std::vector<std::string> cells;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    if (cells.size() != 12) fail(std::to_string(cells.size()) + " columns, expected 12");
    BreakEvent ev;
    try {
      std::size_t used = 0;
      const auto integer = [&](const std::string& c) {
        const int v = std::stoi(c, &used);
        if (used != c.size()) throw std::invalid_argument(c);
        return v;
      };
      const auto real = [&](const std::string& c) {
        const double v = std::stod(c, &used);
        if (used != c.size()) throw std::invalid_argument(c);
        return v;
      };
      ev.sequence = integer(cells[0]);
      ev.beam = integer(cells[1]);
      ev.particle_i = integer(cells[2]);
      ev.particle_j = integer(cells[3]);
      ev.position = Eigen::Vector2d(real(cells[4]), real(cells[5]));
      ev.load = real(cells[6]);
      ev.sigma_1 = real(cells[7]);
      ev.sigma_3 = real(cells[8]);
      ev.ratio = real(cells[9]);
      ev.crack_tip_factor = real(cells[10]);
    } catch (const std::logic_error&) {  // std::invalid_argument and std::out_of_range
      fail("not a number in '" + core::echo(line) + "'");
    }
    try {
      ev.mode = core::from_name<FailureMode>(cells[11], "mode", {FailureMode::tensile, FailureMode::shear});
    } catch (const InputError& e) {
      fail(e.what());
    }
    events.push_back(ev);
  }
  return events;
}

}  // namespace hm::lattice2d
