#include "hm/case/case_file.hpp"

#include <cstdio>
#include <regex>
#include <sstream>

#include "hm/analytic/biot_modulus.hpp"
#include "hm/core/input_error.hpp"
#include "hm/analytic/validation.hpp"

namespace hm::cases {

using hm::analytic::format_value;

CaseTable::CaseTable(const toml::value& table, std::string file, std::string name)
    : table_(table), file_(std::move(file)), name_(std::move(name)) {}

void CaseTable::fail(const std::string& message) const {
  throw InputError(file_ + ": " + (name_.empty() ? "" : "[" + name_ + "] ") + message);
}

void CaseTable::wrong_type(const std::string& key, const std::string& wanted) const {
  fail(key + " = " + toml::format(table_.at(key)) + ", allowed: " + wanted);
}

bool CaseTable::has(const std::string& key) const { return table_.is_table() && table_.contains(key); }

const toml::value* CaseTable::find(const std::string& key) {
  used_.insert(key);
  return has(key) ? &table_.at(key) : nullptr;
}

double CaseTable::get_double(const std::string& key, double default_value) {
  const toml::value* v = find(key);
  if (!v) return default_value;
  if (v->is_floating()) return v->as_floating();
  if (v->is_integer()) return static_cast<double>(v->as_integer());
  wrong_type(key, "a number");
}

double CaseTable::get_double(const std::string& key) {
  if (!has(key)) fail(key + " is missing, allowed: a number (required)");
  return get_double(key, 0.0);
}

long long CaseTable::get_int(const std::string& key, long long default_value) {
  const toml::value* v = find(key);
  if (!v) return default_value;
  if (v->is_integer()) return v->as_integer();
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
  for (const auto& x : v->as_array()) {
    if (x.is_floating())
      out.push_back(x.as_floating());
    else if (x.is_integer())
      out.push_back(static_cast<double>(x.as_integer()));
    else
      wrong_type(key, "an array of numbers");
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

void CaseTable::reject_unknown() const {
  if (!table_.is_table()) return;
  for (const auto& [key, value] : table_.as_table()) {
    if (used_.count(key)) continue;
    std::string known;
    for (const auto& k : used_) known += (known.empty() ? "" : ", ") + k;
    fail("unknown key '" + key + "', allowed: " + (known.empty() ? "none here" : known));
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

CaseFile::CaseFile(const std::filesystem::path& path) : path_(path) {
  if (!std::filesystem::is_regular_file(path))
    throw InputError(path.string() + ": no such case file, allowed: a TOML file (see cases/)");
  try {
    root_ = toml::parse(path.string());
  } catch (const toml::syntax_error& e) {
    throw InputError(one_line_toml_error(path.string(), e.what()));
  } catch (const std::runtime_error& e) {
    throw InputError(path.string() + ": cannot read: " + e.what());
  }
}

namespace {

analytic::DimensionlessParameters read_dimensionless(CaseTable& t) {
  analytic::DimensionlessParameters d;
  auto& m = d.material;
  m.nu = t.get_double("nu", m.nu);
  m.b = t.get_double("b", m.b);
  // E/M defaults to Eq. 22 with Table 1's porosity, K_w, E at this case's b and nu.
  m.E_over_M = t.get_double("E_over_M", analytic::E_over_M_table1(m.b, m.nu));
  m.vol_strain = analytic::parse_vol_strain(t.get_string("vol_strain", to_string(m.vol_strain)));
  d.Q = t.get_double("Q", d.Q);
  d.iota = t.get_double("iota", d.iota);
  d.R_i = t.get_double("R_i", d.R_i);
  d.tensile_strength = t.get_double("tensile_strength", d.tensile_strength);
  d.compressive_strength = t.get_double("compressive_strength", d.compressive_strength);
  d.friction = t.get_double("friction", d.friction);
  return d;
}

analytic::PhysicalParameters read_physical(CaseTable& t) {
  analytic::PhysicalParameters p;
  p.E_si = t.get_double("E", p.E_si);
  p.nu = t.get_double("nu", p.nu);
  p.k_si = t.get_double("k", p.k_si);
  p.k_f_si = t.get_double("k_f", p.k_f_si);
  p.mu_si = t.get_double("mu", p.mu_si);
  p.q_si = t.get_double("q", p.q_si);
  p.R_si = t.get_double("R", p.R_si);
  p.R_i_si = t.get_double("R_i", p.R_i_si);
  p.porosity = t.get_double("porosity", p.porosity);
  p.K_w_si = t.get_double("K_w", p.K_w_si);
  p.b = t.get_double("b", p.b);
  p.T_u_si = t.get_double("T_u", p.T_u_si);
  p.C_u_si = t.get_double("C_u", p.C_u_si);
  p.mu_i = t.get_double("mu_i", p.mu_i);
  return p;
}

}  // namespace

CasePhysics read_physics(CaseTable& root) {
  const bool dimensionless = root.has("physics"), physical = root.has("physics_si");
  if (dimensionless && physical)
    root.fail("both [physics] and [physics_si] given, allowed: exactly one of them");
  CasePhysics out;
  CaseTable t = root.table(physical ? "physics_si" : "physics");
  try {
    if (physical) {
      const auto vs = analytic::parse_vol_strain(t.get_string("vol_strain", "plane-strain"));
      const auto phys = read_physical(t);
      t.reject_unknown();
      out.parameters = analytic::to_dimensionless(phys, vs);
      out.physical = phys;
      out.scales = analytic::scales_of(phys);
    } else {
      out.parameters = read_dimensionless(t);
      t.reject_unknown();
      out.parameters.validate();
    }
  } catch (const InputError& e) {
    if (std::string(e.what()).find(t.file()) == 0) throw;  // already located
    t.fail(e.what());
  }
  return out;
}

std::string physics_to_toml(const CasePhysics& c) {
  const auto& d = c.parameters;
  std::ostringstream os;
  auto v = [](double x) { return format_value(x); };
  os << "[physics]\n"
     << "Q = " << v(d.Q) << "\n"
     << "b = " << v(d.material.b) << "\n"
     << "nu = " << v(d.material.nu) << "\n"
     << "E_over_M = " << v(d.material.E_over_M) << "\n"
     << "vol_strain = \"" << to_string(d.material.vol_strain) << "\"\n"
     << "R_i = " << v(d.R_i) << "\n"
     << "iota = " << v(d.iota) << "\n"
     << "tensile_strength = " << v(d.tensile_strength) << "\n"
     << "compressive_strength = " << v(d.compressive_strength) << "\n"
     << "friction = " << v(d.friction) << "\n";
  // The physical inputs and scales are comments, so this file is itself a runnable case.
  if (c.physical) {
    const auto& p = *c.physical;
    os << "# converted from [physics_si]: E = " << v(p.E_si) << " Pa, nu = " << v(p.nu) << ", k = " << v(p.k_si)
       << " m^2, k_f = " << v(p.k_f_si) << " m^2, mu = " << v(p.mu_si) << " Pa s, q = " << v(p.q_si)
       << " m^2/s, R = " << v(p.R_si) << " m, R_i = " << v(p.R_i_si) << " m, porosity = " << v(p.porosity)
       << ", K_w = " << v(p.K_w_si) << " Pa, b = " << v(p.b) << ", T_u = " << v(p.T_u_si) << " Pa, C_u = "
       << v(p.C_u_si) << " Pa, mu_i = " << v(p.mu_i) << "\n";
  }
  if (c.scales)
    os << "# scales to SI: length x " << v(c.scales->length_m) << " m, stress x " << v(c.scales->stress_pa)
       << " Pa, time x " << v(c.scales->time_s) << " s (t_s = mu R^2/(k E))\n";
  return os.str();
}

}  // namespace hm::cases
