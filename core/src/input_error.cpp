#include "hm/core/input_error.hpp"

#include <algorithm>

namespace hm::core {

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
