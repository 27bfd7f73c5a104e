#include "hm/case/case_file.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <regex>
#include <sstream>
#include <system_error>

#include "hm/analytic/biot_modulus.hpp"
#include "hm/case/case_keys.hpp"
#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

namespace hm::cases {

using hm::core::format_value;

CaseTable::CaseTable(const toml::value& table, std::string file, std::string name)
    : table_(table), file_(std::move(file)), name_(std::move(name)) {}

void CaseTable::fail(const std::string& message) const {
  throw LocatedError(file_ + ": " + (name_.empty() ? "" : "[" + name_ + "] ") + message);
}

void CaseTable::wrong_type(const std::string& key, const std::string& wanted) const {
  fail(key + " = " + core::echo(toml::format(table_.at(key))) + ", allowed: " + wanted);
}

// toml11 reads an integer literal beyond 64 bits as the nearest limit; TOML calls such a file
// invalid, so a limit is checked against the literal as written.
long long CaseTable::integer_of(const toml::value& v, const std::string& key) const {
  const long long x = v.as_integer();
  if (x != std::numeric_limits<long long>::max() && x != std::numeric_limits<long long>::min()) return x;
  const toml::source_location at = v.location();
  if (at.column() < 1 || at.column() - 1 + at.region() > at.line_str().size()) return x;
  std::string digits;
  for (char ch : at.line_str().substr(at.column() - 1, at.region()))
    if (ch != '_' && ch != '+') digits += ch;
  long long parsed = 0;
  if (std::from_chars(digits.data(), digits.data() + digits.size(), parsed).ec == std::errc::result_out_of_range)
    fail(key + " = " + core::echo(at.line_str().substr(at.column() - 1, at.region())) +
         ", allowed: an integer within 64 bits (-2^63 ... 2^63 - 1)");
  return x;
}

// One number of `key`'s value (the value itself or an array element): an integer, or a finite real.
double CaseTable::finite_number(const toml::value& x, const std::string& key, const std::string& wanted) const {
  if (x.is_integer()) return static_cast<double>(integer_of(x, key));
  // TOML's nan and inf are numbers, but no quantity of a case is: every real is finite.
  if (x.is_floating() && std::isfinite(x.as_floating())) return x.as_floating();
  wrong_type(key, wanted);
}

bool CaseTable::has(const std::string& key) const { return table_.is_table() && table_.contains(key); }

const toml::value* CaseTable::find(const std::string& key) {
  used_.insert(key);
  return has(key) ? &table_.at(key) : nullptr;
}

double CaseTable::get_double(const std::string& key, double default_value) {
  const toml::value* v = find(key);
  if (!v) return default_value;
  return finite_number(*v, key, "a finite number");
}

double CaseTable::get_double(const std::string& key) {
  if (!has(key)) fail(key + " is missing, allowed: a number (required)");
  return get_double(key, 0.0);
}

long long CaseTable::get_int(const std::string& key, long long default_value) {
  const toml::value* v = find(key);
  if (!v) return default_value;
  if (v->is_integer()) return integer_of(*v, key);
  wrong_type(key, "an integer");
}

std::string CaseTable::get_string(const std::string& key, const std::string& default_value) {
  const toml::value* v = find(key);
  if (!v) return default_value;
  if (v->is_string()) return v->as_string().str;
  wrong_type(key, "a string");
}

bool CaseTable::get_bool(const std::string& key, bool default_value) {
  const toml::value* v = find(key);
  if (!v) return default_value;
  if (v->is_boolean()) return v->as_boolean();
  wrong_type(key, "true or false");
}

std::vector<double> CaseTable::get_doubles(const std::string& key, const std::vector<double>& default_value) {
  const toml::value* v = find(key);
  if (!v) return default_value;
  if (!v->is_array()) wrong_type(key, "an array of numbers");
  std::vector<double> out;
  for (const auto& x : v->as_array()) out.push_back(finite_number(x, key, "an array of finite numbers"));
  return out;
}

std::vector<std::string> CaseTable::get_strings(const std::string& key, const std::vector<std::string>& default_value) {
  const toml::value* v = find(key);
  if (!v) return default_value;
  if (!v->is_array()) wrong_type(key, "an array of strings");
  std::vector<std::string> out;
  for (const auto& x : v->as_array()) {
    if (!x.is_string()) wrong_type(key, "an array of strings");
    out.push_back(x.as_string().str);
  }
  return out;
}

bool CaseTable::is_string(const std::string& key) const { return has(key) && table_.at(key).is_string(); }

std::vector<std::vector<double>> CaseTable::get_double_lists(const std::string& key, std::size_t size,
                                                             const std::vector<std::vector<double>>& default_value) {
  const toml::value* v = find(key);
  if (!v) return default_value;
  const std::string wanted = "an array of arrays of " + std::to_string(size) + " finite numbers";
  if (!v->is_array()) wrong_type(key, wanted);
  std::vector<std::vector<double>> out;
  for (const auto& inner : v->as_array()) {
    if (!inner.is_array() || inner.as_array().size() != size) wrong_type(key, wanted);
    std::vector<double> values;
    for (const auto& x : inner.as_array()) values.push_back(finite_number(x, key, wanted));
    out.push_back(std::move(values));
  }
  return out;
}

CaseTable CaseTable::table(const std::string& key) {
  const toml::value* v = find(key);
  const std::string sub = name_.empty() ? key : name_ + "." + key;
  if (!v) return CaseTable(toml::value(toml::table{}), file_, sub);
  if (!v->is_table()) wrong_type(key, "a table [" + sub + "]");
  return CaseTable(*v, file_, sub);
}

std::vector<CaseTable> CaseTable::tables(const std::string& key) {
  const toml::value* v = find(key);
  std::vector<CaseTable> out;
  if (!v) return out;
  const std::string sub = name_.empty() ? key : name_ + "." + key;
  if (!v->is_array()) wrong_type(key, "an array of tables [[" + sub + "]]");
  for (const auto& element : v->as_array()) {
    if (!element.is_table()) wrong_type(key, "an array of tables [[" + sub + "]]");
    out.emplace_back(element, file_, sub + "[" + std::to_string(out.size()) + "]");
  }
  return out;
}

void CaseTable::reject_unknown() const {
  if (!table_.is_table()) return;
  for (const auto& [key, value] : table_.as_table()) {
    if (used_.count(key)) continue;
    std::string known;
    for (const auto& k : used_) known += (known.empty() ? "" : ", ") + k;
    fail("unknown key '" + core::echo(key) + "', allowed: " + (known.empty() ? "none here" : known));
  }
}

namespace {

/// toml11's message is several lines (message, file, source excerpt): keep the message and the line.
std::string one_line_toml_error(const std::string& path, const std::string& what) {
  std::istringstream in(what);
  std::string first, line, number;
  std::getline(in, first);
  static const std::regex excerpt(R"(^\s*(\d+) \|)");
  std::smatch m;
  while (std::getline(in, line))
    if (number.empty() && std::regex_search(line, m, excerpt)) number = m[1];
  if (first.rfind("[error] ", 0) == 0) first = first.substr(8);
  return path + (number.empty() ? "" : ":" + number) + ": malformed TOML: " + first;
}

}  // namespace

CaseFile::CaseFile(const std::filesystem::path& path, const std::vector<std::string>& overrides)
    : source_(path.string() + (overrides.empty() ? "" : " with --set")) {
  std::error_code error;  // a dangling link or a link loop is bad input too, not a crash
  const bool is_file = std::filesystem::is_regular_file(path, error);
  if (error && error != std::errc::no_such_file_or_directory)
    throw InputError(core::echo(path.string()) + ": cannot read: " + error.message());
  if (!is_file) throw InputError(core::echo(path.string()) + ": no such case file, allowed: a TOML file (see cases/)");
  try {
    root_ = toml::parse(path.string());
  } catch (const toml::syntax_error& e) {
    throw InputError(one_line_toml_error(path.string(), e.what()));
  } catch (const std::runtime_error& e) {
    throw InputError(path.string() + ": cannot read: " + e.what());
  }
  for (const std::string& item : overrides) {
    const auto fail = [&](const std::string& why) {
      throw InputError("--set " + core::echo(item) + ": " + why +
                       ", allowed: table.key=value with a TOML value (e.g. physics.Q=3e-3, fracture.law=\"sawtooth\")");
    };
    const auto eq = item.find('=');
    const std::string name = item.substr(0, eq);
    const auto dot = name.find('.');
    if (eq == std::string::npos || dot == std::string::npos || dot == 0 || dot + 1 == name.size() ||
        name.find('.', dot + 1) != std::string::npos)
      fail("not of the form table.key=value");
    const std::string table = name.substr(0, dot), key = name.substr(dot + 1);
    toml::value parsed;
    try {
      std::istringstream in("value = " + item.substr(eq + 1) + "\n");
      parsed = toml::parse(in, "--set " + name);
    } catch (const toml::syntax_error& e) {
      fail("the value is not TOML (" + one_line_toml_error("--set " + name, e.what()) + ")");
    }
    if (!root_.is_table()) root_ = toml::table{};
    toml::value& t = root_.as_table()[table];
    if (t.is_uninitialized()) t = toml::table{};
    if (!t.is_table()) fail("'" + table + "' is not a table of the case");
    t.as_table()[key] = parsed.as_table().at("value");
  }
}

namespace {

// The key tables are laid out one key per entry (clang-format would break each entry before its name).
// clang-format off
// [physics_si]: Table 1's physical inputs and the volumetric-strain choice (not a physical value).
struct PhysicsSi {
  analytic::PhysicalParameters p;
  analytic::VolStrain vol_strain = analytic::VolStrain::plane_strain;
};

template <class Case, class Field>
void add_vol_strain(CaseKeys<Case>& k, Field field) {
  k.choice("vol_strain", field,
           "the fluid equation's volumetric strain: plane strain, or Appendix A's (docs/errata.md)");
}

const CaseKeys<analytic::DimensionlessParameters>& physics_keys() {
  static const CaseKeys<analytic::DimensionlessParameters> keys = [] {
    CaseKeys<analytic::DimensionlessParameters> k;
    k.table("physics")
        .real("Q", [](auto& d) -> auto& { return d.Q; }, "0 <= Q <= 1e6", "injection rate mu q/(k E) (Eq. 14)")
        .required()
        .real("b", [](auto& d) -> auto& { return d.material.b; }, "0 <= b <= 1", "Biot coefficient")
        .required()
        .real("nu", [](auto& d) -> auto& { return d.material.nu; }, "0 < nu < 0.5", "Poisson ratio")
        .real("E_over_M", [](auto& d) -> auto& { return d.material.E_over_M; }, "> 0",
              "E/M, the inverse dimensionless Biot modulus (Eqs. 14, 22)",
              [](const analytic::DimensionlessParameters& d) { return analytic::E_over_M_table1(d.material.b, d.material.nu); },
              "Eq. 22 with Table 1's porosity, K_w and E at this b and nu")
        .real("E_over_Kw", [](auto& d) -> auto& { return d.E_over_Kw; }, "> 0",
              "E/K_w, the fluid's compressibility over the rock's: the water-filled borehole's storage "
              "([flow] borehole_storage = \"fluid\"); Eq. 22's E/M is given by E_over_M");
    add_vol_strain(k, [](auto& d) -> auto& { return d.material.vol_strain; });
    k.real("R_i", [](auto& d) -> auto& { return d.R_i; }, "0 <= R_i < 1", "borehole radius R_i/R; 0 for point injection")
        .real("iota", [](auto& d) -> auto& { return d.iota; }, "1 <= iota <= 1e12",
              "fracture permeability enhancement k_f/k (an open crack conducts at least as the rock it cuts; at most a 0.3 mm cubic-law aperture, k_f ~ 1e-8 m^2, in a "
              "nanodarcy shale, k ~ 1e-20 m^2)")
        .real("tensile_strength", [](auto& d) -> auto& { return d.tensile_strength; }, "0 < tensile_strength <= 1",
              "T_u/E (a strain at failure: above 1 it is a strength in Pa)")
        .real("compressive_strength", [](auto& d) -> auto& { return d.compressive_strength; },
              "0 < compressive_strength <= 1", "C_u/E (a strain at failure: above 1 it is a strength in Pa)")
        .real("friction", [](auto& d) -> auto& { return d.friction; }, ">= 0", "mu_i, internal friction of Eq. 11")
        .check([](CaseTable&, CaseTable&, analytic::DimensionlessParameters& d) { d.validate(); });
    return k;
  }();
  return keys;
}

const CaseKeys<PhysicsSi>& physics_si_keys() {
  static const CaseKeys<PhysicsSi> keys = [] {
    CaseKeys<PhysicsSi> k;
    k.table("physics_si");
    add_vol_strain(k, [](auto& s) -> auto& { return s.vol_strain; });
    k.real("E", [](auto& s) -> auto& { return s.p.E_si; }, "> 0", "Young modulus [Pa]")
        .real("nu", [](auto& s) -> auto& { return s.p.nu; }, "0 < nu < 0.5", "Poisson ratio")
        .real("k", [](auto& s) -> auto& { return s.p.k_si; }, "> 0", "permeability [m^2]")
        .real("k_f", [](auto& s) -> auto& { return s.p.k_f_si; }, "> 0", "permeability in fractures [m^2]")
        .real("mu", [](auto& s) -> auto& { return s.p.mu_si; }, "> 0", "fluid viscosity [Pa s]")
        .real("q", [](auto& s) -> auto& { return s.p.q_si; }, ">= 0", "injection rate per unit axial length [m^2/s]")
        .required()
        .real("R", [](auto& s) -> auto& { return s.p.R_si; }, "> 0", "domain outer radius [m]")
        .real("R_i", [](auto& s) -> auto& { return s.p.R_i_si; }, "0 <= R_i < R", "borehole radius [m]")
        .real("porosity", [](auto& s) -> auto& { return s.p.porosity; }, "0 < porosity < 1, <= b", "porosity")
        .real("K_w", [](auto& s) -> auto& { return s.p.K_w_si; }, "> 0", "fluid bulk modulus [Pa]")
        .real("b", [](auto& s) -> auto& { return s.p.b; }, "0 <= b <= 1", "Biot coefficient")
        .required()
        .real("T_u", [](auto& s) -> auto& { return s.p.T_u_si; }, "> 0", "uniaxial tensile strength [Pa]")
        .real("C_u", [](auto& s) -> auto& { return s.p.C_u_si; }, "> 0", "uniaxial compressive strength [Pa]")
        .real("mu_i", [](auto& s) -> auto& { return s.p.mu_i; }, ">= 0", "internal friction coefficient");
    return k;
  }();
  return keys;
}

// clang-format on
}  // namespace

std::string physics_reference_markdown() {
  return physics_keys().reference_markdown() + physics_si_keys().reference_markdown();
}

CasePhysics read_physics(CaseTable& root) {
  const bool dimensionless = root.has("physics"), physical = root.has("physics_si");
  if (dimensionless && physical) root.fail("both [physics] and [physics_si] given, allowed: exactly one of them");
  CasePhysics out;
  if (physical) {
    PhysicsSi si;
    physics_si_keys().read(root, si);
    CaseTable t = root.table("physics_si");
    located(t, [&] { out.parameters = analytic::to_dimensionless(si.p, si.vol_strain); });
    out.physical = si.p;
    out.scales = analytic::scales_of(si.p);
  } else {
    physics_keys().read(root, out.parameters);
  }
  return out;
}

void require_physics_present(CaseTable& root) {
  const bool dimensionless = root.has("physics"), physical = root.has("physics_si");
  if (!dimensionless && !physical)
    root.fail("neither [physics] nor [physics_si] given, allowed: exactly one of them (required)");
  if (physical)
    physics_si_keys().require_present(root);
  else
    physics_keys().require_present(root);
}

std::string physics_to_toml(const CasePhysics& c) {
  const auto& d = c.parameters;
  std::ostringstream os;
  auto v = [](double x) { return format_value(x); };
  // Only the table's lines: the blank line that ends a table comes after the comments below.
  const auto table_lines = [](const std::string& table) { return table.substr(0, table.size() - 1); };
  if (c.physical) {
    // An SI case stays one: its resolved [physics_si] is what a rerun reads (the same inputs convert
    // to the same doubles, shortest round-trip printing), so every rerun's config.toml keeps the SI
    // inputs and scales. The dimensionless values the run used are comments.
    PhysicsSi si;
    si.p = *c.physical;
    si.vol_strain = d.material.vol_strain;
    os << table_lines(physics_si_keys().to_toml(si));
    std::istringstream dimensionless(physics_keys().to_toml(d));
    std::string line;
    std::getline(dimensionless, line);  // the [physics] header
    os << "# converted to [physics]:";
    for (const char* separator = " "; std::getline(dimensionless, line) && !line.empty(); separator = ", ")
      os << separator << line;
    os << "\n";
  } else {
    os << table_lines(physics_keys().to_toml(d));
  }
  if (c.scales)
    os << "# scales to SI: length x " << v(c.scales->length_m) << " m, stress x " << v(c.scales->stress_pa)
       << " Pa, time x " << v(c.scales->time_s) << " s (t_s = mu R^2/(k E))\n";
  return os.str();
}

}  // namespace hm::cases
