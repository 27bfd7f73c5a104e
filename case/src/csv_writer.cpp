#include "hm/case/csv_writer.hpp"

#include <cassert>
#include <cstdio>

namespace hm::cases {

CsvWriter::CsvWriter(std::ostream& out, const std::vector<std::string>& columns)
    : out_(out), n_columns_(columns.size()) {
  for (std::size_t i = 0; i < columns.size(); ++i) out_ << (i ? "," : "") << columns[i];
  out_ << "\n";
}

void CsvWriter::row(const std::vector<double>& values) {
  assert(values.size() == n_columns_ && "CsvWriter: row width differs from the header");
  char buf[32];
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%.10g", values[i]);
    out_ << (i ? "," : "") << buf;
  }
  out_ << "\n";
}

}  // namespace hm::cases
