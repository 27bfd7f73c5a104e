#include "hm/core/file_output.hpp"

#include "hm/core/input_error.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

namespace hm::core {

namespace fs = std::filesystem;

namespace {

// errno of the failed write or close, read right after it; a stream that failed without a system
// error (a formatting failure) still fails, with a generic reason.
[[noreturn]] void throw_write_error(const fs::path& path, int error) {
  throw std::runtime_error("cannot write '" + path.string() +
                           "': " + (error != 0 ? std::string(std::strerror(error)) : std::string("write failed")));
}

}  // namespace

std::ofstream open_for_writing(const fs::path& path) {
  errno = 0;
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  if (!file) throw_write_error(path, errno);
  return file;
}

std::ofstream open_for_appending(const fs::path& path, std::uintmax_t size) {
  std::error_code ec;
  const std::uintmax_t now = fs::file_size(path, ec);
  if (ec || now < size)
    throw InputError("'" + path.string() + "' holds " +
                     (ec ? std::string("nothing readable") : std::to_string(now) + " bytes") +
                     ", allowed: at least the " + std::to_string(size) + " its run had written at the checkpoint");
  fs::resize_file(path, size, ec);  // drop what steps after the checkpoint wrote: they are computed again
  if (ec) throw std::runtime_error("cannot write '" + path.string() + "': " + ec.message());
  errno = 0;
  std::ofstream file(path, std::ios::binary | std::ios::app);
  if (!file) throw_write_error(path, errno);
  return file;
}

void close_checked(std::ofstream& file, const fs::path& path) {
  // A failed write leaves the stream bad and later writes do nothing, so errno still holds its reason.
  const bool written_so_far = static_cast<bool>(file);
  const int write_error = errno;
  errno = 0;
  file.close();  // flushes: a full disk often shows only here
  if (!written_so_far) throw_write_error(path, write_error);
  if (!file) throw_write_error(path, errno);
}

void write_file_atomically(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  fs::path partial = path;
  partial += ".partial";
  try {
    std::ofstream out = open_for_writing(partial);
    write(out);
    close_checked(out, path);
    std::error_code ec;
    fs::rename(partial, path, ec);
    if (ec) throw std::runtime_error("cannot write '" + path.string() + "': " + ec.message());
  } catch (...) {
    std::error_code ec;  // best effort: the original error is the one to report
    fs::remove(partial, ec);
    throw;
  }
}

}  // namespace hm::core
