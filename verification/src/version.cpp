#include "hm/verification/version.hpp"
namespace hm::verification {
std::string version() { return HM_VERSION; }
}  // namespace hm::verification
