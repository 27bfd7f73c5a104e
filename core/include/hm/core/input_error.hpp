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

/// Bad input whose message already says where it came from ("<file>: [table] ..."): a layer that
/// adds the place to the messages it catches passes this one on as it is.
class LocatedError : public InputError {
 public:
  using InputError::InputError;
};

/// Bad input in one field of a parameter struct, kept in its parts so that the layer that knows where
/// the field came from (a case file's [table] key) names it without rewriting the message: the field's
/// name in the struct ("output_times"), the element ("[2]", or empty), the value as given and the rule,
/// in which "{}" stands for the field (with its element). what() names the field as the struct does.
class FieldError : public InputError {
 public:
  FieldError(std::string field, std::string element, std::string value, std::string rule);
  const std::string& field() const { return field_; }
  /// The message with the field called `name`: "name[2] = 5, allowed: 0 < name[2] <= t_end (1)".
  std::string message_as(std::string_view name) const;

 private:
  std::string field_, element_, value_, rule_;
};

namespace core {

/// "[k]": the element of a list field, for FieldError.
std::string element_of(std::size_t k);

/// `text` as one line of at most `max_chars` characters: line breaks and other control characters
/// become spaces, and a longer text is cut with "…" — so an inline table, a [[table]] or a 100 k
/// character string quoted in a message keeps the message one readable line.
std::string one_line(std::string_view text, std::size_t max_chars);

/// A value the user gave, as quoted inside a message (one line, at most 60 characters).
inline std::string echo(std::string_view value) { return one_line(value, 60); }

}  // namespace core

}  // namespace hm
