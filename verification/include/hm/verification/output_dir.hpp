#pragma once
/// \file
/// An output folder that appears only when complete: results are written into a staging folder
/// beside the target, which replaces the target on commit(). Abandoned staging folders are removed.
#include <filesystem>

namespace hm::verification {

class StagedDirectory {
 public:
  explicit StagedDirectory(std::filesystem::path target);
  ~StagedDirectory();  ///< removes the staging folder unless committed
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;

  /// Where to write now.
  const std::filesystem::path& path() const { return staging_; }
  /// The final location.
  const std::filesystem::path& target() const { return target_; }
  /// Replaces `target` with the staged content.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path staging_;
  bool committed_ = false;
};

}  // namespace hm::verification
