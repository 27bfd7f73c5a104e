#pragma once
// What a folder holds, byte for byte: to show that a refused or failed command left the user's files
// exactly as they were.
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace hm::test {

/// Every entry under `root` (not following links): relative path -> "dir", "link -> target",
/// "special" or the file's content.
inline std::map<std::string, std::string> folder_snapshot(const std::filesystem::path& root) {
  namespace fs = std::filesystem;
  std::map<std::string, std::string> entries;
  for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator(); ++it) {
    const std::string name = fs::relative(it->path(), root).string();
    if (it->is_symlink()) {
      entries[name] = "link -> " + fs::read_symlink(it->path()).string();
    } else if (it->is_directory()) {
      entries[name] = "dir";
    } else if (!it->is_regular_file()) {
      entries[name] = "special";  // a pipe or device: never opened (reading a pipe would block)
    } else {
      std::ifstream in(it->path(), std::ios::binary);
      std::stringstream ss;
      ss << in.rdbuf();
      entries[name] = ss.str();
    }
  }
  return entries;
}

}  // namespace hm::test
