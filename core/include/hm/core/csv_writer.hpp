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

class CsvWriter {
 public:
  CsvWriter(std::ostream& out, const std::vector<std::string>& columns);
  void row(const std::vector<double>& values);
  void row(std::initializer_list<double> values) { row(std::vector<double>(values)); }

 private:
  std::ostream& out_;
  std::size_t n_columns_;
};

}  // namespace hm::core
