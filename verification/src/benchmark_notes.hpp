#pragma once
// The prose beside a benchmark's numbers: verification/notes/<id>.md (the id without a trailing
// "_quick": a quick and a paper benchmark of one kind share their notes), one note per paragraph. What a
// benchmark computes stays in its code; what was measured once, and why, is written here, where it
// can be read and kept current without a rebuild.
#include <string>
#include <vector>

namespace hm::verification {

/// The paragraphs of the notes file of benchmark `id` (none if it has no file).
std::vector<std::string> benchmark_notes(const std::string& id);

}  // namespace hm::verification
