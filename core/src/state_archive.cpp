// See state_archive.hpp. Layout: a header line, then per value [u16 tag length][tag][kind][u64 count]
// [count elements as their bytes], then the CRC-32 of everything before it (4 bytes).
#include "hm/core/state_archive.hpp"

#include <cstring>
#include <ostream>
#include <stdexcept>

#include <boost/crc.hpp>

#include "hm/core/input_error.hpp"

namespace hm::core {

namespace {

constexpr std::string_view header = "hmlattice state, format 1\n";

std::uint32_t crc32(const char* data, std::size_t n) {
  boost::crc_32_type crc;
  crc.process_bytes(data, n);
  return crc.checksum();
}

template <class T>
void append(std::string& out, T value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

}  // namespace

StateWriter::StateWriter() : buffer_(header) {}

StateWriter::StateWriter(std::ostream& out) : stream_(&out), stream_crc_(boost::crc_32_type().get_interim_remainder()) {
  write_bytes(header.data(), header.size());
}

StateWriter::StateWriter(Counting) : counting_(true), counted_(header.size()) {}

void StateWriter::write_bytes(const void* data, std::size_t n) {
  if (finished_) throw std::logic_error("StateWriter: a value put after finish()");
  if (counting_) {
    counted_ += n;
    return;
  }
  if (!stream_) {
    buffer_.append(static_cast<const char*>(data), n);
    return;
  }
  stream_->write(static_cast<const char*>(data), static_cast<std::streamsize>(n));
  boost::crc_32_type crc(stream_crc_);  // continued from the bytes before: the checksum of the whole
  crc.process_bytes(data, n);
  stream_crc_ = crc.get_interim_remainder();
}

void StateWriter::put(std::string_view tag, const std::vector<bool>& flags) {
  const std::string bytes(flags.begin(), flags.end());  // one char 0 or 1 per flag
  put_array(tag, bytes.data(), bytes.size());
}

void StateWriter::put_raw(std::string_view tag, char kind, std::size_t element_size, const void* data, std::size_t n) {
  const auto length = static_cast<std::uint16_t>(tag.size());
  const auto count = static_cast<std::uint64_t>(n);
  write_bytes(&length, sizeof length);
  write_bytes(tag.data(), tag.size());
  write_bytes(&kind, 1);
  write_bytes(&count, sizeof count);
  if (n > 0) write_bytes(data, n * element_size);
}

std::string StateWriter::bytes() const {
  if (stream_) throw std::logic_error("StateWriter::bytes() of a streamed writer");
  std::string out;
  out.reserve(buffer_.size() + 4);  // the checksum's 4 bytes without growing a copy of the whole state
  out.append(buffer_);
  append(out, crc32(buffer_.data(), buffer_.size()));
  return out;
}

void StateWriter::clear() {
  if (stream_) throw std::logic_error("StateWriter::clear() of a streamed writer");
  // Room for a state a quarter larger than the last, made while the buffer is empty: growing a full
  // buffer would hold the old and the new copy of a state at once, the peak of a large run's memory.
  const std::size_t room = buffer_.size() + buffer_.size() / 4;
  buffer_.assign(header);
  if (buffer_.capacity() < room) buffer_.reserve(room);
}

void StateWriter::finish() {
  if (!stream_) throw std::logic_error("StateWriter::finish() of an in-memory writer");
  const std::uint32_t crc = boost::crc_32_type(stream_crc_).checksum();
  write_bytes(&crc, sizeof crc);
  finished_ = true;
}

StateReader StateReader::of_snapshot(const StateWriter& w, std::string source) {
  StateReader r;
  r.snapshot_ = &w.buffer_;
  r.source_ = std::move(source);
  r.end_ = w.buffer_.size();
  r.position_ = header.size();
  return r;
}

StateReader::StateReader(std::string bytes, std::string source) : bytes_(std::move(bytes)), source_(std::move(source)) {
  if (bytes_.size() < header.size() + 4 || bytes_.compare(0, header.size(), header) != 0)
    throw InputError(source_ + ": not a state file of this toolkit (or of another format version)");
  end_ = bytes_.size() - 4;
  std::uint32_t stored = 0;
  std::memcpy(&stored, bytes_.data() + end_, sizeof stored);
  if (stored != crc32(bytes_.data(), end_))
    throw InputError(source_ + ": checksum mismatch (the file is truncated or damaged)");
  position_ = header.size();
}

void StateReader::fail(std::string_view tag, const std::string& why) const {
  throw InputError(source_ + ": at '" + std::string(tag) + "': " + why +
                   " (written by another version of the toolkit, or damaged)");
}

std::size_t StateReader::next_count(std::string_view tag, char kind, std::size_t element_size) const {
  std::size_t at = position_;
  auto take = [&](void* out, std::size_t n) {
    if (at + n > end_) fail(tag, "the file ends early");
    std::memcpy(out, data() + at, n);
    at += n;
  };
  std::uint16_t length = 0;
  take(&length, sizeof length);
  std::string stored(length, '\0');
  take(stored.data(), length);
  if (stored != tag) fail(tag, "found '" + one_line(stored, 60) + "' instead");
  char stored_kind = 0;
  take(&stored_kind, 1);
  if (stored_kind != kind) fail(tag, std::string("element type '") + stored_kind + "', expected '" + kind + "'");
  std::uint64_t n = 0;
  take(&n, sizeof n);
  if (n > (end_ - at) / element_size) fail(tag, "the file ends early");
  return static_cast<std::size_t>(n);
}

void StateReader::get_raw(std::string_view tag, char kind, std::size_t element_size, void* data, std::size_t n) {
  const std::size_t stored = next_count(tag, kind, element_size);
  if (stored != n) fail(tag, std::to_string(stored) + " values, expected " + std::to_string(n));
  position_ += sizeof(std::uint16_t) + tag.size() + 1 + sizeof(std::uint64_t);
  if (n > 0) std::memcpy(data, this->data() + position_, n * element_size);
  position_ += n * element_size;
}

void StateReader::get(std::string_view tag, int& value) {
  std::int64_t v = 0;
  get(tag, v);
  value = static_cast<int>(v);
}

void StateReader::get(std::string_view tag, bool& value) {
  std::int64_t v = 0;
  get(tag, v);
  value = v != 0;
}

void StateReader::get(std::string_view tag, std::size_t& value) {
  std::int64_t v = 0;
  get(tag, v);
  value = static_cast<std::size_t>(v);
}

void StateReader::get(std::string_view tag, long long& value) {
  std::int64_t v = 0;
  get(tag, v);
  value = v;
}

void StateReader::get(std::string_view tag, std::string& value) {
  value.resize(next_count(tag, 'c', 1));
  get_raw(tag, 'c', 1, value.data(), value.size());
}

void StateReader::get(std::string_view tag, std::vector<bool>& flags) {
  std::string bytes;
  get(tag, bytes);
  flags.assign(bytes.size(), false);
  for (std::size_t k = 0; k < bytes.size(); ++k) flags[k] = bytes[k] != 0;
}

void check_compressed_pattern(const int* outer, const int* inner, std::int64_t n_rows, std::int64_t n_cols,
                              std::size_t n_inner, const std::string& source, std::string_view tag) {
  const auto fail = [&](const std::string& why) {
    throw InputError(source + ": at '" + std::string(tag) + "': " + why + " (damaged, or of another version)");
  };
  if (outer[0] != 0 || static_cast<std::size_t>(outer[n_cols]) != n_inner)
    fail("column pointers do not span the entries");
  for (std::int64_t j = 0; j < n_cols; ++j)
    if (outer[j + 1] < outer[j]) fail("column pointers decrease at column " + std::to_string(j));
  for (std::int64_t j = 0; j < n_cols; ++j)
    for (int k = outer[j]; k < outer[j + 1]; ++k)
      if (inner[k] < 0 || inner[k] >= n_rows || (k > outer[j] && inner[k] <= inner[k - 1]))
        fail("row index out of range or order in column " + std::to_string(j));
}

}  // namespace hm::core
