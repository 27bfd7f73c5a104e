#pragma once
/// \file
/// Reading simulation cases (TOML, toml11). Every key is consumed exactly once by the code that
/// understands it; whatever is left over is an error, so a misspelt key never passes silently.
/// All errors are hm::InputError with one line: "<file>: [<table>] <key> = <value>, allowed: <rule>".
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <toml.hpp>
#include <vector>

#include "hm/analytic/physical_parameters.hpp"

namespace hm::cases {

/// One TOML table being read; remembers which keys were used.
class CaseTable {
 public:
  CaseTable(const toml::value& table, std::string file, std::string name);

  bool has(const std::string& key) const;
  double get_double(const std::string& key, double default_value);
  double get_double(const std::string& key);  ///< required
  long long get_int(const std::string& key, long long default_value);
  std::string get_string(const std::string& key, const std::string& default_value);
  bool get_bool(const std::string& key, bool default_value);
  std::vector<double> get_doubles(const std::string& key, const std::vector<double>& default_value);
  std::vector<std::string> get_strings(const std::string& key, const std::vector<std::string>& default_value);
  /// Whether `key` is present and a string (for a key that takes a number or a word, e.g. 3 or "all").
  bool is_string(const std::string& key) const;
  /// An array of arrays of finite numbers, each inner one of `size` entries ([[x0, y0, x1, y1], ...]).
  std::vector<std::vector<double>> get_double_lists(const std::string& key, std::size_t size,
                                                    const std::vector<std::vector<double>>& default_value);
  /// Marks a key as understood without reading it (e.g. [provenance] in a resolved config).
  void ignore(const std::string& key) { used_.insert(key); }
  /// A sub-table; an empty one if absent.
  CaseTable table(const std::string& key);
  /// An array of tables ([[key]] ...), each named "key[i]" in messages; empty if absent.
  std::vector<CaseTable> tables(const std::string& key);

  /// Throws for the first key nobody asked for, listing the keys that are understood here.
  void reject_unknown() const;
  /// Prefixes an InputError message from validate() with file and table.
  [[noreturn]] void fail(const std::string& message) const;
  const std::string& file() const { return file_; }
  const std::string& name() const { return name_; }

 private:
  const toml::value* find(const std::string& key);
  [[noreturn]] void wrong_type(const std::string& key, const std::string& wanted) const;
  long long integer_of(const toml::value& v, const std::string& key) const;
  double finite_number(const toml::value& x, const std::string& key, const std::string& wanted) const;

  toml::value table_;
  std::string file_, name_;
  std::set<std::string> used_;
};

/// A parsed case file: the root table plus where it came from.
class CaseFile {
 public:
  /// Parses `path`; a missing file or malformed TOML is an InputError "<path>:<line>: ...". Each
  /// override "table.key=value" (the command line's --set; value a TOML value, e.g. physics.Q=3e-3 or
  /// output.times=[0.1,0.2]) then replaces or adds that key, before anything is read: the case is
  /// validated as if the file had said it. A malformed override is an InputError naming it.
  explicit CaseFile(const std::filesystem::path& path, const std::vector<std::string>& overrides = {});
  /// A case made in memory (a sweep's combination): messages name it `source`.
  CaseFile(toml::value root, std::string source) : source_(std::move(source)), root_(std::move(root)) {}
  /// Messages name the file, and "with --set" when the command line changed it.
  CaseTable root() const { return CaseTable(root_, source_, ""); }

 private:
  std::string source_;
  toml::value root_;
};

/// The physics of a case, from exactly one of [physics] (dimensionless, paper units) or
/// [physics_si] (Table 1 values, converted by hm::analytic::to_dimensionless). Validated.
struct CasePhysics {
  hm::analytic::DimensionlessParameters parameters;
  /// Present when the case gave physical values: the scales that turn results back into SI.
  std::optional<hm::analytic::PhysicalParameters> physical;
  std::optional<hm::analytic::Scales> scales;
};
CasePhysics read_physics(CaseTable& root);
/// Fails for the first required key of the physics (Q and b, or q and b) the file lacks, or if it has
/// neither table. Called after everything else is read, so that wrong values are reported first.
void require_physics_present(CaseTable& root);

/// The reference of [physics] and [physics_si]: every key, its default, rule and meaning (markdown).
std::string physics_reference_markdown();

/// The resolved physics as TOML: [physics] with every field; for a case that gave [physics_si],
/// [physics_si] with every field instead, the dimensionless values and the scales as comments (a
/// rerun converts the same inputs again). Written beside results; itself a valid case section.
std::string physics_to_toml(const CasePhysics& physics);

}  // namespace hm::cases
