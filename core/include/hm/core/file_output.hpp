#pragma once
/// \file
/// Checked file output: a result file is either written completely or the write is an error that
/// names the file and the operating system's reason ("No space left on device", ...). No output
/// stream of the toolkit is left unchecked: a full disk must never leave a 0-byte "result".
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <ostream>

namespace hm::core {

/// Runs `write` on a stream to `<path>.partial` and renames it onto `path` only if every byte reached
/// the operating system (the stream is good after closing); otherwise removes the partial file and
/// throws std::runtime_error "cannot write '<path>': <reason>". `path` is never left half-written.
void write_file_atomically(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write);

/// Opens `path` for writing (truncating it); throws std::runtime_error naming the path and the reason
/// if it cannot be opened. For files written over a whole run (series, logs); close with close_checked.
std::ofstream open_for_writing(const std::filesystem::path& path);

/// Opens `path` for appending after cutting it to its first `size` bytes (a resumed run continues a
/// file where its checkpoint was taken). Throws hm::InputError if the file is missing or shorter,
/// std::runtime_error naming the path if it cannot be cut or opened.
std::ofstream open_for_appending(const std::filesystem::path& path, std::uintmax_t size);

/// Closes a stream that was writing `path` and throws std::runtime_error "cannot write '<path>':
/// <reason>" if any write to it failed or the data could not be flushed.
void close_checked(std::ofstream& file, const std::filesystem::path& path);

}  // namespace hm::core
