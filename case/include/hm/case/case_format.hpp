#pragma once
/// \file
/// The case-format reference (docs/case-format.md, `hmlattice case-format`), generated from the key
/// tables the readers use, so that it lists exactly the keys a case file may hold.
#include <string>

namespace hm::cases {

/// The whole reference as markdown: [physics]/[physics_si], then each model's tables.
std::string case_format_reference();

}  // namespace hm::cases
