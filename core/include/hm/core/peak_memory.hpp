#pragma once
/// \file
/// The process's peak resident memory so far (the high-water mark the kernel keeps), for run summaries.

namespace hm::core {

/// Peak resident set size of this process in bytes (getrusage's ru_maxrss); 0 if it cannot be read.
double peak_memory_bytes();

}  // namespace hm::core
