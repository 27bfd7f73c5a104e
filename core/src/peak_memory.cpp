#include "hm/core/peak_memory.hpp"

#include <sys/resource.h>

namespace hm::core {

double peak_memory_bytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0.0;
  return 1024.0 * static_cast<double>(usage.ru_maxrss);  // Linux reports kilobytes
}

}  // namespace hm::core
