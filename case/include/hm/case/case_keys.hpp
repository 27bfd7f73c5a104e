#pragma once
/// \file
/// The keys of a case model, declared once: each entry says where the key lives ([table] and name),
/// what it holds, its default, what is allowed and what it means. From the one list come the reader
/// (read), the resolved config.toml (to_toml) and the case-format reference (reference_markdown,
/// docs/case-format.md), so a key added here is read, written and documented.
///
///   CaseKeys<MyCase> keys;
///   keys.table("numerics").real("t_end", [](auto& c) -> auto& { return c.t_end; },
///                               "> 0, finite", "end time t* (over the diffusion time)");
///
/// A field is a generic lambda from the case to the member, so that the reader (Case&) and the
/// writer (const Case&) name the same member once.
///
/// A key's default is the value its field holds before reading (the library struct's default),
/// unless the entry computes it from keys read before it (`default_of`). Values are checked by the
/// library's validate() where the struct has one (the table's `check`), by the entry where the
/// rule is about the file (an integer's range, an enum's names).
#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "hm/case/case_file.hpp"
#include "hm/core/enum_names.hpp"

namespace hm::cases {

/// One key of a case file.
template <class Case>
struct CaseKey {
  std::string name;
  std::string type;                             ///< "real", "integer", "boolean", "string", "list of reals"
  std::string default_text;                     ///< the default as the reference states it; empty: the value of Case{}
  std::string allowed;                          ///< the rule
  std::string help;                             ///< what it means, one line
  std::function<void(CaseTable&, Case&)> read;  ///< reads the key, or sets its default
  std::function<std::string(const Case&)> to_toml;  ///< the resolved value as TOML
  bool required = false;                            ///< no default: a case without the key is an error
};

/// One [table] of a case file: its keys in order, and what is checked once they are read.
template <class Case>
struct CaseKeyTable {
  std::string name;
  std::vector<CaseKey<Case>> keys;
  /// Runs after the table's keys are read and unknown keys rejected (the struct's validate() and
  /// rules across keys); root is the whole file, for a rule that names another table.
  std::function<void(CaseTable& table, CaseTable& root, Case&)> check;
  /// Comment lines written after the table's keys in config.toml (e.g. what a key implies).
  std::function<std::string(const Case&)> comment;
};

/// Formats of the values a key holds, shared by every key of the type.
std::string toml_real(double value);
std::string toml_bool(bool value);
std::string toml_quoted(const std::string& text);
std::string toml_reals(const std::vector<double>& values);

/// Runs `read`; an InputError from a library parser or validate() becomes
/// "<file>: [table] key = value, allowed: rule" (the struct's field names are the table's keys).
void located(CaseTable& table, const std::function<void()>& read);

/// The keys of one case model, table by table in file order.
template <class Case>
class CaseKeys {
 public:
  /// Starts a table; the keys declared next belong to it.
  CaseKeys& table(std::string name) {
    tables_.push_back({std::move(name), {}, {}, {}});
    return *this;
  }
  CaseKeys& check(std::function<void(CaseTable&, CaseTable&, Case&)> rule) {
    tables_.back().check = std::move(rule);
    return *this;
  }
  CaseKeys& comment(std::function<std::string(const Case&)> text) {
    tables_.back().comment = std::move(text);
    return *this;
  }

  /// The key declared last has no default: the experiment is never implied (an empty or truncated
  /// file is an error naming what is missing; see require_present).
  CaseKeys& required() {
    tables_.back().keys.back().required = true;
    return *this;
  }

  /// Any key: `read` and `to_toml` spelled out.
  CaseKeys& key(CaseKey<Case> entry) {
    tables_.back().keys.push_back(std::move(entry));
    return *this;
  }

  /// A number; default_of (if given) computes the default from the keys read before.
  template <class Field>
  CaseKeys& real(std::string name, Field field, std::string allowed, std::string help,
                 std::function<double(const Case&)> default_of = {}, std::string default_text = "") {
    return key({name, "real", std::move(default_text), std::move(allowed), std::move(help),
                [name, field, default_of](CaseTable& t, Case& c) {
                  const double fallback = default_of ? default_of(c) : field(c);
                  field(c) = t.get_double(name, fallback);
                },
                [field](const Case& c) { return toml_real(field(c)); }});
  }

  /// An integer in [lo, hi]; outside, "<name> = v, allowed: <allowed>".
  template <class Field>
  CaseKeys& integer(std::string name, Field field, long long lo, long long hi, std::string allowed, std::string help) {
    return key({name, "integer", "", allowed, std::move(help),
                [name, field, lo, hi, allowed](CaseTable& t, Case& c) {
                  using Int = std::remove_reference_t<decltype(field(c))>;
                  const long long v = t.get_int(name, static_cast<long long>(field(c)));
                  // Checked before the conversion: 4294967696 must not become an int's 400.
                  if (v < lo || v > hi || !std::in_range<Int>(v))
                    t.fail(name + " = " + std::to_string(v) + ", allowed: " + allowed);
                  field(c) = static_cast<Int>(v);
                },
                [field](const Case& c) { return std::to_string(field(c)); }});
  }

  /// A boolean; `allowed` states a rule the table's check enforces (e.g. one that needs another key).
  template <class Field>
  CaseKeys& boolean(std::string name, Field field, std::string help, std::string allowed = "true or false") {
    return key({name, "boolean", "", std::move(allowed), std::move(help),
                [name, field](CaseTable& t, Case& c) { field(c) = t.get_bool(name, field(c)); },
                [field](const Case& c) { return toml_bool(field(c)); }});
  }

  /// A choice's computed default: the enum from the case read so far (not deduced from the argument,
  /// so a lambda converts).
  template <class Field>
  using DefaultOf = std::function<std::remove_cvref_t<std::invoke_result_t<Field, Case&>>(const Case&)>;

  /// One of the names of `values` (the enum's names table, hm/core/enum_names.hpp); anything else is
  /// "<name> = 'x', allowed: <the names of values>". default_of (if given) computes the default from
  /// the keys read before.
  template <class Field, class Enum = std::remove_cvref_t<std::invoke_result_t<Field, Case&>>>
  CaseKeys& choice(std::string name, Field field, std::vector<Enum> values, std::string help,
                   DefaultOf<Field> default_of = {}, std::string default_text = "") {
    std::string allowed;
    for (const Enum& v : values) allowed += (allowed.empty() ? "" : ", ") + toml_quoted(core::name_of(v));
    return key(
        {name, "string", std::move(default_text), "one of " + allowed, std::move(help),
         [name, field, values, default_of](CaseTable& t, Case& c) {
           const Enum fallback = default_of ? default_of(c) : field(c);
           located(t, [&] { field(c) = core::from_name(t.get_string(name, core::name_of(fallback)), name, values); });
         },
         [field](const Case& c) { return toml_quoted(core::name_of(field(c))); }});
  }
  /// Any value of the enum.
  template <class Field>
  CaseKeys& choice(std::string name, Field field, std::string help, DefaultOf<Field> default_of = {},
                   std::string default_text = "") {
    using Enum = std::remove_cvref_t<std::invoke_result_t<Field, Case&>>;
    return choice(std::move(name), field, core::enum_values<Enum>(), std::move(help), std::move(default_of),
                  std::move(default_text));
  }

  template <class Field>
  CaseKeys& reals(std::string name, Field field, std::string allowed, std::string help) {
    return key({name, "list of reals", "", std::move(allowed), std::move(help),
                [name, field](CaseTable& t, Case& c) { field(c) = t.get_doubles(name, field(c)); },
                [field](const Case& c) { return toml_reals(field(c)); }});
  }

  /// Reads every table of `root` into `c`: its keys in order, unknown keys rejected, then its check.
  void read(CaseTable& root, Case& c) const {
    for (const CaseKeyTable<Case>& spec : tables_) {
      CaseTable t = root.table(spec.name);
      located(t, [&] {
        for (const CaseKey<Case>& k : spec.keys) k.read(t, c);
        t.reject_unknown();
        if (spec.check) spec.check(t, root, c);
      });
    }
  }

  /// Fails for the first required key `root` lacks. Called once the whole file has been read, so
  /// that a wrong value is reported before a missing one.
  void require_present(CaseTable& root) const {
    for (const CaseKeyTable<Case>& spec : tables_) {
      CaseTable t = root.table(spec.name);
      for (const CaseKey<Case>& k : spec.keys)
        if (k.required && !t.has(k.name)) t.fail(k.name + " is missing, allowed: " + k.allowed + " (required)");
    }
  }

  /// Every table with every key's resolved value, in declaration order.
  std::string to_toml(const Case& c) const {
    std::string out;
    for (const CaseKeyTable<Case>& spec : tables_) {
      out += "[" + spec.name + "]\n";
      for (const CaseKey<Case>& k : spec.keys) out += k.name + " = " + k.to_toml(c) + "\n";
      if (spec.comment) out += spec.comment(c);
      out += "\n";
    }
    return out;
  }

  /// The reference: one markdown table per [table], every key with type, default, rule and meaning.
  std::string reference_markdown() const {
    const Case defaults{};
    std::string out;
    for (const CaseKeyTable<Case>& spec : tables_) {
      out += "### [" + spec.name + "]\n\n| key | type | default | allowed | meaning |\n|---|---|---|---|---|\n";
      for (const CaseKey<Case>& k : spec.keys) {
        // Appended piece by piece: g++ 12 warns (-Wrestrict, falsely) on a literal + string chain here.
        const std::string default_cell = k.required ? std::string("required")
                                         : k.default_text.empty()
                                             ? std::string(1, '`').append(k.to_toml(defaults)).append(1, '`')
                                             : k.default_text;
        out.append("| `").append(k.name).append("` | ").append(k.type).append(" | ").append(default_cell);
        out.append(" | ").append(k.allowed).append(" | ").append(k.help).append(" |\n");
      }
      out += "\n";
    }
    return out;
  }

  const std::vector<CaseKeyTable<Case>>& tables() const { return tables_; }

 private:
  std::vector<CaseKeyTable<Case>> tables_;
};

}  // namespace hm::cases
