#pragma once
/// \file
/// checkpoint.bin, the file in a run folder from which `hmlattice run --resume` continues a run: the
/// model's whole state between two steps (coupled_model.hpp's save_state: displacement, pressure,
/// beam states, the mechanical factor as modified so far, the flow's factor matrix, the break log,
/// strengths, the step cursor) and the recorder's (file lengths, breakdown, output snapshots), under
/// the identity of the run that wrote it: the toolkit's version, commit and build type and the
/// resolved case. A checkpoint of another build or another case is refused, because only the same
/// binary on the same case continues bitwise. Written atomically (a new file, then a rename): a run
/// killed while writing one keeps the previous checkpoint.
#include <filesystem>
#include <string>

#include "hm/case/run_output.hpp"
#include "hm/core/state_archive.hpp"
#include "hm/lattice2d/coupled/coupled_model.hpp"

namespace hm::cases {

inline constexpr const char* checkpoint_file_name = "checkpoint.bin";

/// Writes `dir`/checkpoint.bin for the state after the model's last accepted step (call it from the
/// run's observer, after recorder.record). `case_text` is the resolved case (run_case_to_toml without
/// provenance).
void write_checkpoint(const std::filesystem::path& dir, const std::string& case_text,
                      const hm::lattice2d::CoupledModel& model, RunRecorder& recorder);

/// Reads `dir`/checkpoint.bin into `model` (built from the same case, not yet run) and returns the
/// reader at the recorder's part, for RunRecorder's resuming constructor. Throws hm::InputError (one
/// line) for a missing or damaged file, or one written by another build or for another case.
core::StateReader read_checkpoint(const std::filesystem::path& dir, const std::string& case_text,
                                  hm::lattice2d::CoupledModel& model);

}  // namespace hm::cases
