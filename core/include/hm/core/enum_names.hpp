#pragma once
/// \file
/// The names of an enum's values: one table per enum, declared beside the enum, in its namespace,
/// as a function found by argument-dependent lookup:
///
///   enum class Split { undrained, drained };
///   constexpr auto enum_names(Split) {
///     return core::enum_table<Split>({{Split::undrained, "undrained"}, {Split::drained, "drained"}});
///   }
///
/// Case files, config.toml, CSV columns, the case-format reference and every message then spell a
/// value the same way, and parsing is the exact inverse of naming. C++17, for the one C++17 target
/// (fdm1d's Odeint reference) that includes parameter headers.
#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "hm/core/input_error.hpp"

namespace hm::core {

template <class Enum>
struct EnumName {
  Enum value;
  std::string_view name;
};

/// The table of an enum_names function, its size taken from the list.
template <class Enum, std::size_t N>
constexpr std::array<EnumName<Enum>, N> enum_table(const EnumName<Enum> (&entries)[N]) {
  std::array<EnumName<Enum>, N> table{};
  for (std::size_t i = 0; i < N; ++i) table[i] = entries[i];
  return table;
}

/// The name of `value`; "unknown(k)" for an integer cast to the enum that the table lacks.
template <class Enum>
std::string name_of(Enum value) {
  for (const auto& entry : enum_names(Enum{}))
    if (entry.value == value) return std::string(entry.name);
  return "unknown(" + std::to_string(static_cast<long long>(value)) + ")";
}

/// "a, b, c": the names of `values` in order.
template <class Values>
std::string names_list(const Values& values) {
  std::string list;
  for (const auto& v : values) list += (list.empty() ? "" : ", ") + name_of(v);
  return list;
}

/// Every value of the enum, in table order.
template <class Enum>
std::vector<Enum> enum_values() {
  std::vector<Enum> values;
  for (const auto& entry : enum_names(Enum{})) values.push_back(entry.value);
  return values;
}

/// The value among `allowed` named `name`; otherwise throws
/// InputError "<field> = '<name>', allowed: a, b".
template <class Enum>
Enum from_name(std::string_view name, std::string_view field, const std::vector<Enum>& allowed = enum_values<Enum>()) {
  for (Enum v : allowed)
    if (name == name_of(v)) return v;
  throw InputError(std::string(field) + " = '" + echo(name) + "', allowed: " + names_list(allowed));
}

}  // namespace hm::core
