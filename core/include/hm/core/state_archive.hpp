#pragma once
/// \file
/// The binary state of a computation, for checkpoints that continue a run bitwise where it stopped.
/// Each value is stored under a tag with its element type and count; the reader asks for the same tags
/// in the same order, so a checkpoint written by other code (another version of a class's
/// save_state) is refused at the first difference, naming the tag, instead of being misread. Doubles
/// are stored as their bytes: a restored value is the same bits. A CRC-32 over everything refuses a
/// truncated or damaged file. Not a portable format: the same build reads what it wrote.
///
/// Usage: both have io(tag, value), so one template lists a class's state for saving and restoring:
///   template <class Archive, class Self> static void transfer(Archive& a, Self& s) {
///     a.io("time", s.time_);
///     a.io("u", s.u_);
///   }
///   void save_state(core::StateWriter& w) const { transfer(w, *this); }
///   void restore_state(core::StateReader& r) { transfer(r, *this); }
#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace hm::core {

namespace detail {
/// The type code stored with each value.
template <class T>
constexpr char state_kind() {
  if constexpr (std::is_same_v<T, double>)
    return 'd';
  else if constexpr (std::is_same_v<T, std::int64_t>)
    return 'l';
  else if constexpr (std::is_same_v<T, int>)
    return 'i';
  else if constexpr (std::is_same_v<T, char>)
    return 'c';
  else
    static_assert(sizeof(T) == 0, "state archive: double, int, std::int64_t or char elements only");
}
}  // namespace detail

/// Collects tagged values into a byte string (bytes(): the checkpoint file's content), or writes them
/// straight to a stream.
class StateWriter {
 public:
  /// In memory: bytes() and clear().
  StateWriter();
  /// Straight to `out`, the same bytes as bytes() would give (finish() adds the checksum): a checkpoint
  /// needs no copy of the whole state in memory beside the model, which at large N is most of a run's
  /// peak memory.
  explicit StateWriter(std::ostream& out);
  void put(std::string_view tag, double value) { put_array(tag, &value, 1); }
  void put(std::string_view tag, std::int64_t value) { put_array(tag, &value, 1); }
  void put(std::string_view tag, int value) { put(tag, static_cast<std::int64_t>(value)); }
  void put(std::string_view tag, bool value) { put(tag, static_cast<std::int64_t>(value)); }
  void put(std::string_view tag, std::size_t value) { put(tag, static_cast<std::int64_t>(value)); }
  void put(std::string_view tag, long long value) { put(tag, static_cast<std::int64_t>(value)); }
  void put(std::string_view tag, const std::string& value) { put_array(tag, value.data(), value.size()); }
  void put(std::string_view tag, const std::vector<bool>& flags);
  /// A contiguous vector of double, int, std::int64_t or char (std::vector, Eigen::VectorXd, VectorXi).
  template <class Vector, class = decltype(std::declval<const Vector&>().data())>
  void put(std::string_view tag, const Vector& v) {
    put_array(tag, v.data(), static_cast<std::size_t>(v.size()));
  }
  /// n elements at `data` (a library's array), read back as a vector: stored without a copy.
  template <class T>
  void put(std::string_view tag, const T* data, std::size_t n) {
    put_array(tag, data, n);
  }
  /// An enumeration, as its underlying integer.
  template <class Enum, std::enable_if_t<std::is_enum_v<Enum>, int> = 0>
  void put(std::string_view tag, Enum value) {
    put(tag, static_cast<std::int64_t>(value));
  }
  /// An Eigen compressed sparse matrix: its size, pattern and values.
  template <class Sparse>
  void put_sparse(std::string_view tag, const Sparse& a);
  /// put, under the name StateReader::io has for get (one transfer function for both).
  template <class T>
  void io(std::string_view tag, const T& value) {
    put(tag, value);
  }

  /// The content with its checksum (in memory).
  std::string bytes() const;
  /// Empties the writer for the next state, keeping its memory and making room for one a quarter larger
  /// than the last (in memory; a snapshot taken every step).
  void clear();
  /// Writes the checksum (streamed); nothing may be put after it.
  void finish();
  /// Makes room for a state of `bytes` (in memory), e.g. measure()'s before a first snapshot.
  void reserve(std::size_t bytes) { buffer_.reserve(bytes); }
  /// The bytes `save(writer)` puts, counted by a writer that keeps none of them.
  template <class Save>
  static std::size_t measure(const Save& save) {
    StateWriter counter(Counting{});
    save(counter);
    return counter.counted_;
  }

 private:
  friend class StateReader;
  template <class T>
  void put_array(std::string_view tag, const T* data, std::size_t n);
  void put_raw(std::string_view tag, char kind, std::size_t element_size, const void* data, std::size_t n);
  void write_bytes(const void* data, std::size_t n);
  struct Counting {};
  explicit StateWriter(Counting);
  std::string buffer_;              // in memory
  std::ostream* stream_ = nullptr;  // streamed
  std::uint32_t stream_crc_ = 0;    // streamed: the CRC-32 register after what was written
  bool counting_ = false;           // measure(): bytes counted, none kept
  std::size_t counted_ = 0;
  bool finished_ = false;
};

/// Reads what a StateWriter wrote. Every failure (a damaged file, a tag or type that differs, a size
/// that differs from `expected`) throws hm::InputError naming `source` and the tag.
class StateReader {
 public:
  /// Checks the header and the checksum of `bytes`.
  StateReader(std::string bytes, std::string source);
  /// Reads what `w` holds now, in place and without a checksum (a snapshot this process took and
  /// keeps in memory, where nothing can damage it): `w` must outlive the reader and not change.
  static StateReader of_snapshot(const StateWriter& w, std::string source);
  void get(std::string_view tag, double& value) { get_array(tag, &value, 1); }
  void get(std::string_view tag, std::int64_t& value) { get_array(tag, &value, 1); }
  void get(std::string_view tag, int& value);
  void get(std::string_view tag, bool& value);
  void get(std::string_view tag, std::size_t& value);
  void get(std::string_view tag, long long& value);
  void get(std::string_view tag, std::string& value);
  void get(std::string_view tag, std::vector<bool>& flags);
  /// A contiguous vector (std::vector or Eigen vector), resized to the stored count.
  template <class Vector, class = decltype(std::declval<Vector&>().data())>
  void get(std::string_view tag, Vector& v) {
    using T = std::remove_cv_t<std::remove_pointer_t<decltype(v.data())>>;
    v.resize(static_cast<decltype(v.size())>(next_count(tag, detail::state_kind<T>(), sizeof(T))));
    get_array(tag, v.data(), static_cast<std::size_t>(v.size()));
  }
  template <class Enum, std::enable_if_t<std::is_enum_v<Enum>, int> = 0>
  void get(std::string_view tag, Enum& value) {
    std::int64_t v = 0;
    get(tag, v);
    value = static_cast<Enum>(v);
  }
  /// Exactly `n` values into `data` (storage the caller owns, e.g. a library's arrays).
  template <class T>
  void get(std::string_view tag, T* data, std::size_t n) {
    get_array(tag, data, n);
  }
  template <class Sparse>
  void get_sparse(std::string_view tag, Sparse& a);
  template <class T>
  void io(std::string_view tag, T& value) {
    get(tag, value);
  }
  /// True once every value has been read.
  bool at_end() const { return position_ >= end_; }
  const std::string& source() const { return source_; }

 private:
  template <class T>
  void get_array(std::string_view tag, T* data, std::size_t n);
  std::size_t next_count(std::string_view tag, char kind, std::size_t element_size) const;
  void get_raw(std::string_view tag, char kind, std::size_t element_size, void* data, std::size_t n);
  [[noreturn]] void fail(std::string_view tag, const std::string& why) const;
  StateReader() = default;
  const char* data() const { return snapshot_ ? snapshot_->data() : bytes_.data(); }
  std::string bytes_, source_;
  const std::string* snapshot_ = nullptr;  // of_snapshot's writer buffer, read in place of bytes_
  std::size_t position_ = 0, end_ = 0;
};

/// Throws hm::InputError naming `source` and `tag` unless (outer, inner) is a compressed-column
/// pattern of an n_rows x n_cols matrix: outer starts at 0, never decreases and ends at inner's
/// size; each column's row indices are in range and increasing. A damaged checkpoint whose checksum
/// still matches is refused here, before a solver follows an index out of its arrays.
void check_compressed_pattern(const int* outer, const int* inner, std::int64_t n_rows, std::int64_t n_cols,
                              std::size_t n_inner, const std::string& source, std::string_view tag);

// ------------------------------------------------------------------------------------------------

template <class T>
void StateWriter::put_array(std::string_view tag, const T* data, std::size_t n) {
  put_raw(tag, detail::state_kind<T>(), sizeof(T), data, n);
}

template <class T>
void StateReader::get_array(std::string_view tag, T* data, std::size_t n) {
  get_raw(tag, detail::state_kind<T>(), sizeof(T), data, n);
}

template <class Sparse>
void StateWriter::put_sparse(std::string_view tag, const Sparse& a) {
  const std::string t(tag);
  put(t + ".rows", static_cast<std::int64_t>(a.rows()));
  put(t + ".cols", static_cast<std::int64_t>(a.cols()));
  put_array(t + ".outer", a.outerIndexPtr(), static_cast<std::size_t>(a.outerSize() + 1));
  put_array(t + ".inner", a.innerIndexPtr(), static_cast<std::size_t>(a.nonZeros()));
  put_array(t + ".values", a.valuePtr(), static_cast<std::size_t>(a.nonZeros()));
}

template <class Sparse>
void StateReader::get_sparse(std::string_view tag, Sparse& a) {
  const std::string t(tag);
  std::int64_t rows = 0, cols = 0;
  get(t + ".rows", rows);
  get(t + ".cols", cols);
  if (rows < 0 || cols < 0 || rows > std::int64_t{1} << 31 || cols > std::int64_t{1} << 31)
    fail(tag, "a matrix of " + std::to_string(rows) + " x " + std::to_string(cols));
  a.resize(static_cast<typename Sparse::Index>(rows), static_cast<typename Sparse::Index>(cols));
  a.makeCompressed();
  get_array(t + ".outer", a.outerIndexPtr(), static_cast<std::size_t>(a.outerSize() + 1));
  const std::size_t nnz = next_count(t + ".inner", 'i', sizeof(int));
  a.resizeNonZeros(static_cast<typename Sparse::Index>(nnz));
  get_array(t + ".inner", a.innerIndexPtr(), nnz);
  check_compressed_pattern(a.outerIndexPtr(), a.innerIndexPtr(), rows, cols, nnz, source_, tag);
  get_array(t + ".values", a.valuePtr(), nnz);
}

}  // namespace hm::core
