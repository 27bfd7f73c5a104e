#pragma once
// Draws one report figure by running its script from figures/ with the Python that has matplotlib.
#include <filesystem>
#include <string>

#include "hm/verification/benchmark.hpp"

namespace hm::verification {

/// The interpreter: $HMLATTICE_PYTHON if set, else the one CMake found with matplotlib and numpy.
std::string figure_python();

/// Runs figures/<figure.script> --data data_dir --out figure_dir; returns "" on success, else a
/// one-line reason (the script's last stderr line, or "no python with matplotlib").
std::string draw_figure(const Figure& figure, const std::filesystem::path& data_dir,
                        const std::filesystem::path& figure_dir);

}  // namespace hm::verification
