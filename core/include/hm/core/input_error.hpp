#pragma once
/// \file
/// The one exception type for bad user input (config files, command-line values).
#include <stdexcept>
#include <string>

namespace hm {

/// Thrown for invalid user input only. The message names the parameter, the value given and the
/// rule it breaks, e.g. "b = 1.5, allowed: 0 <= b <= 1". Callers prefix the source (file, option).
/// Programming errors use assertions; numerical trouble is returned in result structs.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace hm
