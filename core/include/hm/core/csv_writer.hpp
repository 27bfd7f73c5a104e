#pragma once
/// \file
/// CSV of numbers: a header row, then rows of numbers with 10 significant digits (well beyond any
/// plot or check in the toolkit). csv_number is the one formatting of a number in every CSV file.
#include <initializer_list>
#include <ostream>
#include <string>
#include <vector>

namespace hm::core {

/// `v` with 10 significant digits, printf's %.10g.
std::string csv_number(double v);

/// What a row with an inf or nan does: written as it is, or refused (an InputError naming the
/// column: results that overflowed double precision are bad input, not results).
enum class NonFinite { write, reject };

/// Whether the writer starts with the header row, or appends rows to a file that has it (a resumed run).
enum class CsvHeader { write, already_written };

class CsvWriter {
 public:
  CsvWriter(std::ostream& out, const std::vector<std::string>& columns, NonFinite non_finite = NonFinite::write,
            CsvHeader header = CsvHeader::write);
  void row(const std::vector<double>& values);
  void row(std::initializer_list<double> values) { row(std::vector<double>(values)); }

 private:
  std::ostream& out_;
  std::vector<std::string> columns_;
  NonFinite non_finite_;
};

}  // namespace hm::core
