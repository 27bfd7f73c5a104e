#pragma once
// A place where writing fails as on a full disk, to test that no command reports an incomplete result
// as complete. As root (CI) a tmpfs of a few KiB is mounted on a fresh folder; where that is not
// allowed, the same failure is injected with a file-size limit (RLIMIT_FSIZE with SIGXFSZ ignored,
// so a write past the limit fails with EFBIG instead of killing the process).
#include <sys/mount.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

namespace hm::test {

class SmallDisk {
 public:
  /// `folder` is created; `kib` is the size of the tmpfs or of the file-size limit.
  SmallDisk(std::filesystem::path folder, int kib) : folder_(std::move(folder)), kib_(kib) {
    std::filesystem::create_directories(folder_);
    const std::string size = "size=" + std::to_string(kib) + "k";
    // HM_TEST_NO_TMPFS=1 tries the fault injection as root too.
    mounted_ = ::geteuid() == 0 && !std::getenv("HM_TEST_NO_TMPFS") &&
               ::mount("tmpfs", folder_.c_str(), "tmpfs", 0, size.c_str()) == 0;
  }
  ~SmallDisk() {
    if (mounted_) ::umount(folder_.c_str());
    std::error_code ec;
    std::filesystem::remove_all(folder_, ec);
  }
  SmallDisk(const SmallDisk&) = delete;
  SmallDisk& operator=(const SmallDisk&) = delete;

  /// The folder to write results into.
  const std::filesystem::path& folder() const { return folder_; }
  bool is_tmpfs() const { return mounted_; }
  /// Shell commands to put before the command under test (empty on a tmpfs): each file it writes is
  /// limited to the small size. /bin/sh counts `ulimit -f` in 512-byte blocks.
  std::string shell_prefix() const {
    return mounted_ ? std::string() : "trap '' XFSZ; ulimit -f " + std::to_string(2 * kib_) + "; ";
  }

 private:
  std::filesystem::path folder_;
  int kib_;
  bool mounted_ = false;
};

}  // namespace hm::test
