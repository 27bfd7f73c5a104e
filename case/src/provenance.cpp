#include "hm/case/provenance.hpp"

#include <ctime>
#include <sstream>

namespace hm::cases {

namespace {
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}
}  // namespace

Provenance make_provenance(const std::string& command_line) {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return {HM_VERSION, HM_GIT_COMMIT, command_line, stamp, HM_BUILD_TYPE};
}

std::string to_toml(const Provenance& p) {
  std::ostringstream os;
  os << "[provenance]\n"
     << "version = " << quoted(p.version) << "\n"
     << "git_commit = " << quoted(p.git_commit) << "\n"
     << "command_line = " << quoted(p.command_line) << "\n"
     << "utc_time = " << quoted(p.utc_time) << "\n"
     << "build_type = " << quoted(p.build_type) << "\n";
  return os.str();
}

}  // namespace hm::cases
