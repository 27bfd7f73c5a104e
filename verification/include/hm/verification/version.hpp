#pragma once
#include <string>
namespace hm::verification {
/// The toolkit version (CMake project version).
std::string version();
}  // namespace hm::verification
