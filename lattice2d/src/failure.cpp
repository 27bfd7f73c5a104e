#include "hm/lattice2d/failure.hpp"

#include <cassert>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "hm/core/file_output.hpp"

namespace hm::lattice2d {

std::string to_string(FailureMode mode) {
  switch (mode) {
    case FailureMode::none: return "none";
    case FailureMode::tensile: return "tensile";
    case FailureMode::shear: return "shear";
  }
  return "?";
}

namespace {

bool is_intact(const std::vector<BeamState>& states, int beam) {
  return states.empty() || states[static_cast<std::size_t>(beam)] == BeamState::intact;
}

}  // namespace

FailureField evaluate_failure(const BeamStress& stress, const BeamStrengths& strengths,
                              const std::vector<BeamState>& states) {
  const int n_beams = static_cast<int>(stress.sigma_1.size());
  assert(strengths.n_beams() == n_beams && "one strength per beam");
  assert((states.empty() || static_cast<int>(states.size()) == n_beams) && "one state per beam");
  FailureField out{Eigen::VectorXd::Zero(n_beams), std::vector<FailureMode>(static_cast<std::size_t>(n_beams))};
  const FailureCriterion criterion(strengths.friction);
  for (int e = 0; e < n_beams; ++e) {
    if (!is_intact(states, e)) continue;
    const auto check = criterion.check(stress.sigma_1[e], stress.sigma_3[e], strengths.tensile[e], strengths.compressive[e]);
    assert(!std::isnan(check.ratio) && "failure ratio is NaN: non-finite stress");
    out.ratio[e] = check.ratio;
    out.mode[static_cast<std::size_t>(e)] = check.mode;
  }
  return out;
}

BreakCandidate select_beam_to_break(const BeamStress& stress, const BeamStrengths& strengths,
                                    const std::vector<BeamState>& states) {
  // evaluate_failure's check, beam by beam, without its two per-beam arrays.
  const int n_beams = static_cast<int>(stress.sigma_1.size());
  assert(strengths.n_beams() == n_beams && "one strength per beam");
  assert((states.empty() || static_cast<int>(states.size()) == n_beams) && "one state per beam");
  const FailureCriterion criterion(strengths.friction);
  BreakCandidate best;
  bool any_intact = false;
  for (int e = 0; e < n_beams; ++e) {
    if (!is_intact(states, e)) continue;
    const auto check = criterion.check(stress.sigma_1[e], stress.sigma_3[e], strengths.tensile[e], strengths.compressive[e]);
    assert(!std::isnan(check.ratio) && "failure ratio is NaN: non-finite stress");
    const double r = check.ratio;
    if (!any_intact || r > best.max_ratio) best.max_ratio = r;
    any_intact = true;
    // Strictly greater: on equal ratios the lowest index, visited first, stays.
    if (r >= 1.0 && (!best.found() || r > best.ratio)) {
      best.beam = e;
      best.ratio = r;
      best.mode = check.mode;
    }
  }
  return best;
}

BreakEvent make_break_event(const Lattice& lattice, const BeamStress& stress, const BreakCandidate& candidate,
                            double load, int sequence) {
  assert(candidate.found() && "make_break_event: no beam selected");
  const int e = candidate.beam;
  return make_break_event(lattice, candidate, stress.sigma_1[e], stress.sigma_3[e], stress.crack_tip_factor[e], load,
                          sequence);
}

BreakEvent make_break_event(const Lattice& lattice, const BreakCandidate& candidate, double sigma_1, double sigma_3,
                            double crack_tip_factor, double load, int sequence) {
  assert(candidate.found() && "make_break_event: no beam selected");
  const int e = candidate.beam;
  const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
  BreakEvent event;
  event.sequence = sequence;
  event.beam = e;
  event.particle_i = i;
  event.particle_j = j;
  event.position = 0.5 * (lattice.points.col(i) + lattice.points.col(j));
  event.load = load;
  event.sigma_1 = sigma_1;
  event.sigma_3 = sigma_3;
  event.ratio = candidate.ratio;
  event.crack_tip_factor = crack_tip_factor;
  event.mode = candidate.mode;
  return event;
}

void write_break_log(const std::filesystem::path& path, const std::vector<BreakEvent>& events,
                     const std::string& load_column) {
  core::write_file_atomically(path, [&](std::ostream& out) {
    out << "sequence,beam,particle_i,particle_j,x,y," << load_column
        << ",sigma_1,sigma_3,ratio,crack_tip_factor,mode\n";
    char buf[32];
    const auto number = [&](double v) {
      std::snprintf(buf, sizeof buf, "%.10g", v);
      return std::string(buf);
    };
    for (const BreakEvent& ev : events)
      out << ev.sequence << ',' << ev.beam << ',' << ev.particle_i << ',' << ev.particle_j << ','
          << number(ev.position.x()) << ',' << number(ev.position.y()) << ',' << number(ev.load) << ','
          << number(ev.sigma_1) << ',' << number(ev.sigma_3) << ',' << number(ev.ratio) << ','
          << number(ev.crack_tip_factor) << ',' << to_string(ev.mode) << '\n';
  });
}

std::vector<BreakEvent> read_break_log(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read the break log " + path.string());
  int line_no = 1;
  const auto fail = [&](const std::string& what) {
    throw std::runtime_error(path.string() + ":" + std::to_string(line_no) + ": " + what);
  };
  std::string line;
  std::getline(in, line);
  const std::string before = "sequence,beam,particle_i,particle_j,x,y,";
  const std::string after = ",sigma_1,sigma_3,ratio,crack_tip_factor,mode";
  if (line.rfind(before, 0) != 0 || line.size() < before.size() + after.size() ||
      line.compare(line.size() - after.size(), after.size(), after) != 0)
    fail("header '" + line + "', expected '" + before + "<load>" + after + "'");
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
      fail("not a number in '" + line + "'");
    }
    if (cells[11] == to_string(FailureMode::tensile)) ev.mode = FailureMode::tensile;
    else if (cells[11] == to_string(FailureMode::shear)) ev.mode = FailureMode::shear;
    else fail("mode '" + cells[11] + "', allowed: tensile, shear");
    events.push_back(ev);
  }
  return events;
}

}  // namespace hm::lattice2d
