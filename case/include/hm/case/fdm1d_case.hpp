#pragma once
/// \file
/// A 1D case file (model = "fdm1d"): [physics] or [physics_si] (read_physics), then the tables of
/// fdm1d_case_keys() — [mechanics], [numerics], [output]. Every key: docs/case-format.md (`hmlattice case-format`).
#include <filesystem>
#include <string>

#include "hm/case/case_file.hpp"
#include "hm/case/case_keys.hpp"
#include "hm/fdm1d/fdm1d.hpp"

namespace hm::cases {

struct Fdm1dCase {
  CasePhysics physics;
  hm::fdm1d::Fdm1dNumerics numerics;
  /// [mechanics] S_H = S_h (isotropic only: the model is radially symmetric) and p0.
  hm::fdm1d::RestState rest;
};

/// The keys of a 1D case after [physics]: the reader, the config.toml writer and the reference.
const CaseKeys<Fdm1dCase>& fdm1d_case_keys();

/// Reads and validates the whole case; throws hm::InputError "<file>: [table] key = value, allowed: ...".
Fdm1dCase read_fdm1d_case(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});
/// The same for a case already parsed (or made in memory).
Fdm1dCase read_fdm1d_case(const CaseFile& file);

/// The resolved case as TOML (itself a valid case file), with a [provenance] table.
std::string fdm1d_case_to_toml(const Fdm1dCase& c, const std::string& provenance_toml);

}  // namespace hm::cases
