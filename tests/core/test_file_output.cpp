// A result file is written completely or the write is an error naming the file and the reason.
#include <sys/resource.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "hm/core/file_output.hpp"
#include "small_disk.hpp"

namespace fs = std::filesystem;

namespace {

// What write_file_atomically throws, or "" if it did not.
std::string write_error(const fs::path& path, std::size_t bytes) {
  try {
    hm::core::write_file_atomically(path, [&](std::ostream& out) { out << std::string(bytes, 'x'); });
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// Lowers this process's file-size limit for the scope (SIGXFSZ ignored: writes past it fail with
// EFBIG): the fault injection where no tmpfs can be mounted.
struct FileSizeLimit {
  rlimit saved{};
  explicit FileSizeLimit(rlim_t bytes) {
    ::getrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, SIG_IGN);
    rlimit low = saved;
    low.rlim_cur = bytes;
    ::setrlimit(RLIMIT_FSIZE, &low);
  }
  ~FileSizeLimit() { ::setrlimit(RLIMIT_FSIZE, &saved); }
};

}  // namespace

TEST_CASE("A file that fits is written whole, and nothing else is left beside it", "[core]") {
  const fs::path dir = fs::temp_directory_path() / ("hmlattice-file-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  CHECK(write_error(dir / "a.csv", 1000).empty());
  CHECK(fs::file_size(dir / "a.csv") == 1000);
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);
  fs::remove_all(dir);
}

TEST_CASE("A full disk is an error that names the file and the reason, and leaves no partial file", "[core]") {
  hm::test::SmallDisk disk(fs::temp_directory_path() / ("hmlattice-full-" + std::to_string(::getpid())), 16);
  const fs::path file = disk.folder() / "profiles.csv";
  std::string why;
  if (disk.is_tmpfs()) {
    why = write_error(file, 64 * 1024);
    CHECK(why == "cannot write '" + file.string() + "': No space left on device");
  } else {
    const FileSizeLimit limit(16 * 1024);
    why = write_error(file, 64 * 1024);
    CHECK(why == "cannot write '" + file.string() + "': File too large");
  }
  CHECK(fs::is_empty(disk.folder()));
  // An earlier complete file of that name is kept when the new one cannot be written.
  REQUIRE(write_error(file, 100).empty());
  if (disk.is_tmpfs()) {
    CHECK_FALSE(write_error(file, 64 * 1024).empty());
  } else {
    const FileSizeLimit limit(16 * 1024);
    CHECK_FALSE(write_error(file, 64 * 1024).empty());
  }
  CHECK(fs::file_size(file) == 100);
  fs::remove(file);
}

TEST_CASE("A stream written over a run fails on close_checked when the disk filled up", "[core]") {
  hm::test::SmallDisk disk(fs::temp_directory_path() / ("hmlattice-stream-" + std::to_string(::getpid())), 16);
  const fs::path file = disk.folder() / "series.csv";
  std::string why;
  {
    std::optional<FileSizeLimit> limit;
    if (!disk.is_tmpfs()) limit.emplace(16 * 1024);
    std::ofstream out = hm::core::open_for_writing(file);
    for (int i = 0; i < 10000; ++i) out << "0.000123456789,1.5,2.5\n";
    try {
      hm::core::close_checked(out, file);
    } catch (const std::runtime_error& e) {
      why = e.what();
    }
  }
  CHECK(why.find("cannot write '" + file.string() + "': ") == 0);
  fs::remove(file);
  CHECK_THROWS_WITH(hm::core::open_for_writing(disk.folder() / "no" / "such" / "folder.csv"),
                    Catch::Contains("No such file or directory"));
}
