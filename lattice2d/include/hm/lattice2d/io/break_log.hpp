#pragma once
/// \file
/// The break log of a run (breaks.csv): one row per broken beam, in breaking order, written once
/// and read back by the fracture re-analysis and the figure scripts; and the saw-tooth law's tooth log
/// (teeth.csv), read back by the re-analysis for the softened beams.
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "hm/lattice2d/fracture/failure.hpp"
#include "hm/lattice2d/fracture/sawtooth_law.hpp"

namespace hm::lattice2d {

/// Writes the break log as CSV, one header row and one row per event, via a temporary file renamed
/// into place (a crash leaves the previous file or none, never half of one). Columns:
///   sequence, beam, particle_i, particle_j  integers;
///   x, y                                    beam midpoint (over R);
///   <load_column>                           load or time, named by the caller ("load", "time");
///   sigma_1, sigma_3                        in-plane principal beam stresses (over E, tension positive);
///   ratio                                   max(sigma_1/T_u, sigma_CC/C_u) >= 1;
///   crack_tip_factor                        (L/2L_m)^(1/2) or 1;
///   mode                                    "tensile" or "shear".
/// Numbers with 10 significant digits. Throws std::runtime_error naming the path if it cannot write.
void write_break_log(const std::filesystem::path& path, const std::vector<BreakEvent>& events,
                     const std::string& load_column = "load");

/// The two parts of write_break_log, for a log written while a run goes on (one flush per step):
/// the header row, and the rows of `events`.
void write_break_log_header(std::ostream& out, const std::string& load_column);
void write_break_log_rows(std::ostream& out, const std::vector<BreakEvent>& events);

/// Reads a log written by write_break_log (any load column name; numbers as written, so 10
/// significant digits). Throws std::runtime_error "<path>:<line>: ..." if the file cannot be read,
/// its header is not write_break_log's, or a row is malformed.
std::vector<BreakEvent> read_break_log(const std::filesystem::path& path);

/// Writes the saw-tooth law's tooth log (teeth.csv) as write_break_log does, one row per tooth that
/// gave way (a beam's last tooth, stiffness_factor 0, is also its row in the break log). Columns:
///   sequence, beam                          integers;
///   <load_column>                           load or time;
///   tooth                                   the tooth that gave way (0 = the intact beam);
///   stiffness_factor                        the beam's stiffness over its intact one after it (0: broken);
///   axial_stress                            N / d at the step (over E);
///   ratio                                   axial stress over the tooth's strength, >= 1;
///   energy                                  the energy the step released (over E R^2, per unit thickness).
void write_tooth_log(const std::filesystem::path& path, const std::vector<ToothEvent>& events,
                     const std::string& load_column = "load");

/// Reads a log written by write_tooth_log, as read_break_log does (same errors).
std::vector<ToothEvent> read_tooth_log(const std::filesystem::path& path);

}  // namespace hm::lattice2d
