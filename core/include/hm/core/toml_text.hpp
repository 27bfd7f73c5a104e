#pragma once
/// \file
/// The small pieces of text every written TOML file (config.toml, the result marker) shares.
#include <string>

namespace hm::core {

/// `s` as a TOML basic string, quotes included: ", \ and control characters escaped, so any command
/// line or path reads back as it was; a byte that is not UTF-8 is written as U+FFFD (\ufffd), so
/// the string is valid TOML whatever the bytes (such a byte does not read back as itself).
std::string toml_string(const std::string& s);

/// The current time in UTC, ISO 8601 to the second ("2026-12-02T14:08:00Z").
std::string utc_now();

}  // namespace hm::core
