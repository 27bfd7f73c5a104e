#include "hm/core/csv_writer.hpp"

#include <cassert>
#include <cstdio>

namespace hm::core {

std::string csv_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

CsvWriter::CsvWriter(std::ostream& out, const std::vector<std::string>& columns)
    : out_(out), n_columns_(columns.size()) {
  for (std::size_t i = 0; i < columns.size(); ++i) out_ << (i ? "," : "") << columns[i];
  out_ << "\n";
}

void CsvWriter::row(const std::vector<double>& values) {
  assert(values.size() == n_columns_ && "CsvWriter: row width differs from the header");
  for (std::size_t i = 0; i < values.size(); ++i) out_ << (i ? "," : "") << csv_number(values[i]);
  out_ << "\n";
}

}  // namespace hm::core
