#pragma once
/// \file
/// The one exception type for bad user input (config files, command-line values), and how a value
/// the user gave is quoted in its message.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace hm {

/// Thrown for invalid user input only. The message names the parameter, the value given and the
/// rule it breaks, e.g. "b = 1.5, allowed: 0 <= b <= 1". Callers prefix the source (file, option).
/// Programming errors use assertions; numerical trouble is returned in result structs.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

namespace core {

/// `text` as one line of at most `max_chars` characters: line breaks and other control characters
/// become spaces, and a longer text is cut with "…" — so an inline table, a [[table]] or a 100 k
/// character string quoted in a message keeps the message one readable line.
std::string one_line(std::string_view text, std::size_t max_chars);

/// A value the user gave, as quoted inside a message (one line, at most 60 characters).
inline std::string echo(std::string_view value) { return one_line(value, 60); }

}  // namespace core

}  // namespace hm
