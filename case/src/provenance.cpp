#include "hm/case/provenance.hpp"

#include <sstream>

#include "hm/core/toml_text.hpp"

namespace hm::cases {

Provenance make_provenance(const std::string& command_line) {
  return {HM_VERSION, HM_GIT_COMMIT, command_line, core::utc_now(), HM_BUILD_TYPE};
}

std::string to_toml(const Provenance& p) {
  std::ostringstream os;
  os << "[provenance]\n"
     << "version = " << core::toml_string(p.version) << "\n"
     << "git_commit = " << core::toml_string(p.git_commit) << "\n"
     << "command_line = " << core::toml_string(p.command_line) << "\n"
     << "utc_time = " << core::toml_string(p.utc_time) << "\n"
     << "build_type = " << core::toml_string(p.build_type) << "\n";
  return os.str();
}

}  // namespace hm::cases
