#include "hm/core/csv_writer.hpp"

#include <cassert>
#include <cmath>
#include <cstdio>

#include "hm/core/input_error.hpp"

namespace hm::core {

std::string csv_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

CsvWriter::CsvWriter(std::ostream& out, const std::vector<std::string>& columns, NonFinite non_finite, CsvHeader header)
    : out_(out), columns_(columns), non_finite_(non_finite) {
  if (header == CsvHeader::already_written) return;
  for (std::size_t i = 0; i < columns.size(); ++i) out_ << (i ? "," : "") << columns[i];
  out_ << "\n";
}

void CsvWriter::row(const std::vector<double>& values) {
  assert(values.size() == columns_.size() && "CsvWriter: row width differs from the header");
  if (non_finite_ == NonFinite::reject)
    for (std::size_t i = 0; i < values.size(); ++i)
      if (!std::isfinite(values[i]))
        throw InputError(columns_[i] + " = " + csv_number(values[i]) + " at " + columns_[0] + " = " +
                         csv_number(values[0]) + ": the inputs overflow double precision, allowed: inputs whose " +
                         columns_[i] + " is finite");
  for (std::size_t i = 0; i < values.size(); ++i) out_ << (i ? "," : "") << csv_number(values[i]);
  out_ << "\n";
}

}  // namespace hm::core
