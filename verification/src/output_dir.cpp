#include "hm/verification/output_dir.hpp"

#include <random>
#include <string>

namespace hm::verification {

namespace fs = std::filesystem;

StagedDirectory::StagedDirectory(fs::path target) : target_(std::move(target)) {
  std::random_device rd;
  const fs::path parent = target_.has_parent_path() ? target_.parent_path() : fs::path(".");
  fs::create_directories(parent);
  std::string name = ".";  // appended step by step: GCC 12 warns falsely (-Wrestrict) on a + chain here
  name += target_.filename().string();
  name += ".partial-";
  name += std::to_string(rd() % 1000000);
  staging_ = parent / name;
  fs::remove_all(staging_);
  fs::create_directories(staging_);
}

StagedDirectory::~StagedDirectory() {
  if (!committed_) {
    std::error_code ec;  // never throw from a destructor; a leftover staging folder is harmless
    fs::remove_all(staging_, ec);
  }
}

void StagedDirectory::commit() {
  fs::remove_all(target_);
  fs::rename(staging_, target_);
  committed_ = true;
}

}  // namespace hm::verification
