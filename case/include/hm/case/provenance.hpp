#pragma once
/// \file
/// What is written beside every result so a run can be traced and repeated.
#include <string>

namespace hm::cases {

struct Provenance {
  std::string version;       ///< toolkit version
  std::string git_commit;    ///< source commit at build time, or "unknown"
  std::string command_line;  ///< as typed
  std::string utc_time;      ///< ISO 8601
  std::string build_type;    ///< CMAKE_BUILD_TYPE
};

Provenance make_provenance(const std::string& command_line);

/// A TOML fragment ([provenance] table) for resolved-config files.
std::string to_toml(const Provenance& p);

}  // namespace hm::cases
