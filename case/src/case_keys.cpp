#include "hm/case/case_keys.hpp"

#include "hm/core/input_error.hpp"
#include "hm/core/toml_text.hpp"
#include "hm/core/validation.hpp"

namespace hm::cases {

std::string toml_real(double value) { return core::format_value(value); }

std::string toml_bool(bool value) { return value ? "true" : "false"; }

std::string toml_quoted(const std::string& text) { return core::toml_string(text); }

std::string toml_reals(const std::vector<double>& values) {
  std::string s = "[";
  for (std::size_t i = 0; i < values.size(); ++i) s += (i ? ", " : "") + toml_real(values[i]);
  return s + "]";
}

void located(CaseTable& table, const std::function<void()>& read) {
  try {
    read();
  } catch (const LocatedError&) {
    throw;
  } catch (const InputError& e) {
    table.fail(e.what());
  }
}

}  // namespace hm::cases
