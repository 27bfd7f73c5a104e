#include "hm/case/sweep.hpp"

#include <algorithm>
#include <map>
#include <sstream>
#include <toml.hpp>

#include "hm/case/case_file.hpp"
#include "hm/case/fdm1d_case.hpp"
#include "hm/case/run_case.hpp"
#include "hm/core/file_output.hpp"
#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"
#include "sweep_csv.hpp"

namespace hm::cases {

namespace fs = std::filesystem;

namespace {

// A combination's name is a file name on every system the toolkit runs on: anything but these
// becomes '-', and two combinations that end up with one name are refused.
bool is_name_character(char ch) {
  return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') || ch == '.' || ch == '_' ||
         ch == '=' || ch == '+' || ch == '-';
}

std::string safe_name(std::string text) {
  for (char& ch : text)
    if (!is_name_character(ch)) ch = '-';
  return text;
}

// A value as it appears in names, index.csv and messages: numbers as the user would write them.
std::string value_text(const toml::value& v) {
  if (v.is_floating()) return core::format_value(v.as_floating());
  if (v.is_integer()) return std::to_string(v.as_integer());
  if (v.is_boolean()) return v.as_boolean() ? "true" : "false";
  if (v.is_string()) return v.as_string().str;
  return toml::format(v);
}

// A value as quoted in messages: as the user would write it in TOML, one line.
std::string echo_value(const toml::value& v) {
  if (v.is_string()) return core::echo(toml::format(v));
  if (v.is_array()) {
    std::string text = "[";
    for (const toml::value& x : v.as_array()) text += (text.size() > 1 ? ", " : "") + echo_value(x);
    return core::echo(text + "]");
  }
  if (v.is_table()) {
    std::string text;
    for (const auto& [key, x] : v.as_table()) text += (text.empty() ? "" : ", ") + key + " = " + echo_value(x);
    return core::echo("{" + text + "}");
  }
  return core::echo(value_text(v));
}

// Which kind of list a [sweep] entry is; integers and reals are both numbers (a real key takes 1).
std::string kind_of(const toml::value& v) {
  if (v.is_floating() || v.is_integer()) return "number";
  if (v.is_string()) return "string";
  if (v.is_boolean()) return "boolean";
  return "";
}

struct Axis {
  SweepAxis shown;
  std::string table, key;
  std::vector<toml::value> values;
  toml::source_location where;
};

constexpr const char* list_rule = "a non-empty list of numbers, strings or booleans, all of one kind";

std::vector<Axis> read_axes(const toml::value& root, const std::string& file) {
  const auto fail = [&](const std::string& message) -> void { throw InputError(file + ": [sweep] " + message); };
  if (!root.contains("sweep"))
    throw InputError(file +
                     ": [sweep] is missing, allowed: a table of \"table.key\" = [values] (see docs/case-format.md)");
  const toml::value& sweep = root.at("sweep");
  if (!sweep.is_table() || sweep.as_table().empty())
    throw InputError(file + ": sweep = " + echo_value(sweep) +
                     ", allowed: a table of \"table.key\" = [values] with at least one key");
  // "physics.Q" = [...] (a quoted key) and physics.Q = [...] (a dotted one: a sub-table) alike.
  std::vector<std::pair<std::string, const toml::value*>> entries;
  for (const auto& [name, value] : sweep.as_table())
    if (value.is_table())
      for (const auto& [key, list] : value.as_table()) entries.emplace_back(name + "." + key, &list);
    else
      entries.emplace_back(name, &value);
  std::vector<Axis> axes;
  for (const auto& [name, entry] : entries) {
    const toml::value& list = *entry;
    const std::string shown = name + " = " + echo_value(list);
    const auto dot = name.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == name.size() || name.find('.', dot + 1) != std::string::npos)
      fail(shown + ", allowed: a key \"table.key\" of the case, e.g. \"physics.Q\"");
    const std::string table = name.substr(0, dot), key = name.substr(dot + 1);
    if (table == "sweep" || table == "provenance")
      fail(shown + ", allowed: a key of the case's model, not of [" + table + "]");
    if (!list.is_array() || list.as_array().empty()) fail(shown + ", allowed: " + list_rule);
    const std::string kind = kind_of(list.as_array().front());
    for (const toml::value& v : list.as_array())
      if (kind.empty() || kind_of(v) != kind) fail(shown + ", allowed: " + list_rule);
    Axis axis{{name, key, {}}, table, key, list.as_array(), list.location()};
    for (const toml::value& v : axis.values) axis.shown.values.push_back(value_text(v));
    axes.push_back(std::move(axis));
  }
  // toml11 keeps a table unordered: the file's order is the lines the lists are on.
  std::sort(axes.begin(), axes.end(), [](const Axis& a, const Axis& b) {
    return std::pair(a.where.line(), a.where.column()) < std::pair(b.where.line(), b.where.column());
  });
  // Two axes with one short name (lattice.seed, fracture.seed) are named in full.
  std::map<std::string, int> uses;
  for (const Axis& a : axes) ++uses[a.shown.short_name];
  for (Axis& a : axes)
    if (uses[a.shown.short_name] > 1) a.shown.short_name = a.shown.key;
  return axes;
}

// The model's reader on one combination, which messages call `source`: its resolved case text.
std::string resolved_case(const std::string& model, const toml::value& c, const std::string& source) {
  const CaseFile combination(c, source);
  try {
    if (model == "fdm1d") return fdm1d_case_to_toml(read_fdm1d_case(combination), "");
    return run_case_to_toml(read_run_case(combination), "");
  } catch (const LocatedError&) {
    throw;
  } catch (const InputError& e) {  // a rule of the reader's that names no table
    throw LocatedError(source + ": " + e.what());
  }
}

// The case with [sweep] replaced by the swept keys' values `at` (one index per axis).
toml::value case_with(const toml::value& root, const std::vector<Axis>& axes, const std::vector<std::size_t>& at,
                      const std::string& file) {
  toml::value c = root;
  c.as_table().erase("sweep");
  for (std::size_t i = 0; i < axes.size(); ++i) {
    const Axis& a = axes[i];
    if (!c.contains(a.table)) c[a.table] = toml::table{};
    if (!c.at(a.table).is_table())
      throw InputError(file + ": [sweep] " + a.shown.key + ": " + a.table + " = " + echo_value(c.at(a.table)) +
                       ", allowed: a table [" + a.table + "]");
    c[a.table][a.key] = a.values[at[i]];
  }
  return c;
}

// The model named by the file; "lattice2d" or "fdm1d", else refused.
std::string model_of(const toml::value& root, const std::string& file) {
  const std::string model =
      root.contains("model") && root.at("model").is_string() ? root.at("model").as_string().str : "";
  if (model != "lattice2d" && model != "fdm1d")
    throw InputError(
        file + ": model = " + (root.contains("model") ? core::echo(toml::format(root.at("model"))) : "(missing)") +
        ", allowed: \"lattice2d\" or \"fdm1d\" (the model every combination runs)");
  return model;
}

// The product of the lists' sizes, refused above `max_combinations` before anything is written.
long long planned_combinations(const std::vector<Axis>& axes, long long max_combinations, const std::string& file) {
  long long n = 1;
  std::string sizes;
  for (const Axis& a : axes) {
    n = static_cast<long long>(std::min<double>(static_cast<double>(n) * a.values.size(), 9e18));
    sizes += (sizes.empty() ? "" : " x ") + std::to_string(a.values.size());
  }
  if (n > max_combinations)
    throw InputError(file + ": [sweep] " + sizes + " = " + std::to_string(n) + " combinations, allowed: at most " +
                     std::to_string(max_combinations) + " (--max-combinations N to allow more)");
  return n;
}

// The next combination's indices, the first axis slowest (an odometer over the lists); false after the last.
bool advance(std::vector<std::size_t>& at, const std::vector<Axis>& axes) {
  for (std::size_t i = axes.size(); i-- > 0;) {
    if (++at[i] < axes[i].values.size()) return true;
    at[i] = 0;
  }
  return false;
}

// The case's own value of a swept key is replaced, but it is part of the file: checked as `run`
// would check it, in the first combination with that one key put back (after every combination
// has passed, so that what fails here is that value).
void check_own_values(const toml::value& root, const std::vector<Axis>& axes, const std::string& model,
                      const std::string& file) {
  for (std::size_t k = 0; k < axes.size(); ++k) {
    const Axis& own = axes[k];
    if (!root.contains(own.table) || !root.at(own.table).is_table() || !root.at(own.table).contains(own.key)) continue;
    toml::value c = case_with(root, axes, std::vector<std::size_t>(axes.size(), 0), file);
    c[own.table][own.key] = root.at(own.table).at(own.key);
    try {
      resolved_case(model, c, file);
    } catch (const InputError& e) {
      throw InputError(std::string(e.what()) + " (the case's own value of " + own.shown.key +
                       ", which [sweep] replaces)");
    }
  }
}

void write_index(const fs::path& folder, const SweepExpansion& out) {
  core::write_file_atomically(folder / sweep_index_name, [&](std::ostream& f) {
    f << "name,command";
    for (const SweepAxis& a : out.axes) f << ',' << sweep_csv::field(a.key);
    f << '\n';
    for (const SweepCombination& c : out.combinations) {
      f << sweep_csv::field(c.name) << ',' << out.command;
      for (const std::string& v : c.values) f << ',' << sweep_csv::field(v);
      f << '\n';
    }
  });
}

}  // namespace

SweepExpansion expand_sweep(const fs::path& case_file, const fs::path& folder, long long max_combinations,
                            const std::function<bool()>& stop) {
  const std::string file = case_file.string();
  CaseFile readable(case_file);  // a missing file or malformed TOML: its one-line message
  const toml::value root = toml::parse(file);
  SweepExpansion out;
  out.model = model_of(root, file);
  out.command = out.model == "fdm1d" ? "fdm1d" : "run";
  const std::vector<Axis> axes = read_axes(root, file);
  for (const Axis& a : axes) out.axes.push_back(a.shown);
  out.n_planned = planned_combinations(axes, max_combinations, file);

  std::vector<std::size_t> at(axes.size(), 0);
  std::map<std::string, std::string> seen;  // name -> the assignments that made it
  do {
    if (stop && stop()) {
      out.stopped = true;
      return out;
    }
    SweepCombination combination;
    std::string assignments;
    for (std::size_t i = 0; i < axes.size(); ++i) {
      const Axis& a = axes[i];
      combination.values.push_back(a.shown.values[at[i]]);
      combination.name += (i ? "_" : "") + a.shown.short_name + "=" + a.shown.values[at[i]];
      assignments += (i ? ", " : "") + a.shown.key + " = " + echo_value(a.values[at[i]]);
    }
    combination.name = safe_name(combination.name);
    if (combination.name.size() > 200)
      throw InputError(file + ": [sweep] combination " + core::echo(combination.name) + " (" + assignments +
                       "): name longer than 200 characters, allowed: shorter values or fewer keys");
    if (const auto [it, fresh] = seen.emplace(combination.name, assignments); !fresh)
      throw InputError(file + ": [sweep] " + assignments + ", allowed: values that differ from " + it->second +
                       " in a letter, digit or one of . _ = + - (both are named " + combination.name + ")");
    // The combination as the user could have written it, read by the model's own reader.
    const std::string text =
        resolved_case(out.model, case_with(root, axes, at, file),
                      file + ": [sweep] combination " + combination.name + " (" + assignments + ")");
    core::write_file_atomically(folder / (combination.name + ".toml"), [&](std::ostream& f) {
      f << "# Combination " << combination.name << " of the sweep " << file << ": " << assignments << ".\n"
        << "# Written by `hmlattice sweep expand`.\n"
        << text;
    });
    out.combinations.push_back(std::move(combination));
  } while (advance(at, axes));
  check_own_values(root, axes, out.model, file);
  write_index(folder, out);
  return out;
}

std::string sweep_reference_markdown() {
  return "## Sweeps: [sweep] (`hmlattice sweep expand`)\n\n"
         "A case of either model may hold a `[sweep]` table that gives a list of values for some keys,\n"
         "named \"table.key\":\n\n"
         "```toml\n"
         "[sweep]\n"
         "\"physics.Q\" = [1e-3, 1e-2, 1e-1]\n"
         "\"lattice.seed\" = [1, 2, 3]\n"
         "```\n\n"
         "`hmlattice sweep expand CASE --out DIR` writes one resolved case per combination of the lists\n"
         "(their cartesian product, the first key varying slowest), named after its values\n"
         "(`Q=0.001_seed=1.toml`; a key's part after the dot, unless two keys share it; characters other\n"
         "than letters, digits and `. _ = + -` become `-`), and `index.csv` (name, command, one column per\n"
         "key). A swept key replaces the case's value of it. Every combination is read and checked as a\n"
         "case of its own before anything is written: a list that is empty, mixes kinds (numbers, strings,\n"
         "booleans) or holds tables, a key that is not \"table.key\" of the model, a value outside its rule\n"
         "or two combinations with one name is one line naming the key and the value, exit 2, nothing written;\n"
         "so is the case's own value of a swept key that `run` would refuse, and a sweep of more than 10000\n"
         "combinations unless `--max-combinations N` allows it. Ctrl-C or SIGTERM ends the expansion with one\n"
         "line (exit 130 or 143), nothing written.\n"
         "`hmlattice run` and `hmlattice fdm1d` refuse a case with `[sweep]`; run the expanded ones.\n"
         "`hmlattice sweep collect DIR --runs RUNS` prints one CSV row per combination: its swept values,\n"
         "status (complete, incomplete or missing, for the run folder RUNS/<name>), wall time, breakdown.csv's\n"
         "columns and fracture_summary.csv's last row (`final_` columns).\n\n";
}

}  // namespace hm::cases
