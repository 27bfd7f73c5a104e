// The notes files of verification/notes/: see benchmark_notes.hpp.
#include "benchmark_notes.hpp"

#include <filesystem>
#include <fstream>

namespace hm::verification {

std::vector<std::string> benchmark_notes(const std::string& id) {
  std::string stem = id;
  const std::string quick = "_quick";
  if (stem.size() > quick.size() && stem.compare(stem.size() - quick.size(), quick.size(), quick) == 0)
    stem.resize(stem.size() - quick.size());
  std::ifstream in(std::filesystem::path(HM_SOURCE_DIR) / "verification" / "notes" / (stem + ".md"));
  std::vector<std::string> notes;
  std::string line, paragraph;
  const auto flush = [&] {
    if (!paragraph.empty()) notes.push_back(paragraph);
    paragraph.clear();
  };
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t") == std::string::npos) {
      flush();
      continue;
    }
    paragraph += (paragraph.empty() ? "" : " ") + line;
  }
  flush();
  return notes;
}

}  // namespace hm::verification
