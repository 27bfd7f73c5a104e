#include "hm/core/input_error.hpp"

#include <algorithm>
#include <utility>

namespace hm {

namespace {
std::string field_message(std::string_view name, const std::string& element, const std::string& value,
                          std::string rule) {
  const std::string named = std::string(name) + element;
  for (std::size_t at; (at = rule.find("{}")) != std::string::npos;) rule.replace(at, 2, named);
  return named + " = " + value + ", allowed: " + rule;
}
}  // namespace

FieldError::FieldError(std::string field, std::string element, std::string value, std::string rule)
    : InputError(field_message(field, element, value, rule)),
      field_(std::move(field)),
      element_(std::move(element)),
      value_(std::move(value)),
      rule_(std::move(rule)) {}

std::string FieldError::message_as(std::string_view name) const { return field_message(name, element_, value_, rule_); }

}  // namespace hm

namespace hm::core {

std::string element_of(std::size_t k) {
  std::string s = "[";
  s += std::to_string(k);
  s += ']';
  return s;
}

std::string one_line(std::string_view text, std::size_t max_chars) {
  std::string out;
  out.reserve(std::min(text.size(), max_chars));
  bool space = false;  // runs of control characters and spaces become one space
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char ch = static_cast<unsigned char>(text[i]);
    const bool blank = ch < 0x20 || ch == 0x7f || ch == ' ';
    if (blank) {
      space = !out.empty();
      continue;
    }
    if (space) out += ' ';
    space = false;
    // Cut before a character that would pass the limit; never inside a UTF-8 sequence.
    if (out.size() + 1 > max_chars && (ch & 0xC0) != 0x80) {
      out += "…";
      return out;
    }
    out += static_cast<char>(ch);
  }
  return out;
}

}  // namespace hm::core
