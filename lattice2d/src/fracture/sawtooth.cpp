#include "hm/lattice2d/fracture/sawtooth.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

namespace hm::lattice2d {

namespace {

// The teeth on the envelope from (eps_0, f_t) to (eps_u, 0), eps_u > eps_0.
BeamTeeth teeth_on(double e_n, double f_t, double eps_u, const SawtoothSpec& spec) {
  const double eps_0 = f_t / e_n;
  const double d = f_t / (eps_u - eps_0);  // softening modulus, > 0
  BeamTeeth t;
  t.ultimate_strain = eps_u;
  double factor = 1.0;
  for (int i = 0; i < spec.n_teeth; ++i, factor /= spec.reduction) {
    const double e_i = factor * e_n;
    t.stiffness_factor.push_back(factor);
    t.strength.push_back(i == 0 ? f_t : e_i * d * eps_u / (e_i + d));  // f_0 = f_t exactly
  }
  return t;
}

}  // namespace

void SawtoothSpec::validate() const {
  if (!(reduction > 1.0 && std::isfinite(reduction)))
    throw hm::InputError("sawtooth.reduction = " + core::format_value(reduction) + ", allowed: > 1, finite");
  if (n_teeth < 1 || n_teeth > 100)
    throw hm::InputError("sawtooth.n_teeth = " + std::to_string(n_teeth) + ", allowed: 1 ... 100");
}

bool is_snap_back(double axial_modulus, double tensile_strength, double fracture_energy, double length) {
  return 2.0 * fracture_energy / (tensile_strength * length) <= tensile_strength / axial_modulus;  // eps_u <= eps_0
}

double first_tooth_strength(double axial_modulus, double tensile_strength, double fracture_energy, double length) {
  return is_snap_back(axial_modulus, tensile_strength, fracture_energy, length)
             ? std::sqrt(2.0 * axial_modulus * (fracture_energy / length))
             : tensile_strength;
}

LinearSoftening linear_softening(double axial_modulus, double tensile_strength, double fracture_energy, double length) {
  LinearSoftening env;
  env.modulus = axial_modulus;
  env.strength = first_tooth_strength(axial_modulus, tensile_strength, fracture_energy, length);
  env.dissipation = fracture_energy / length;
  env.ultimate_strain = is_snap_back(axial_modulus, tensile_strength, fracture_energy, length)
                            ? env.peak_strain()
                            : 2.0 * fracture_energy / (tensile_strength * length);
  return env;
}

double LinearSoftening::secant_factor(double kappa) const {
  const double eps_0 = peak_strain();
  if (kappa >= ultimate_strain) return 0.0;  // first: a snap-back beam is spent at its peak
  if (kappa <= eps_0) return 1.0;
  return strength * (ultimate_strain - kappa) / (ultimate_strain - eps_0) / (modulus * kappa);
}

double LinearSoftening::dissipated_density(double kappa) const {
  const double eps_0 = peak_strain();
  if (kappa >= ultimate_strain) return dissipation;
  if (kappa <= eps_0) return 0.0;
  // The area under the envelope up to kappa, less the triangle the secant still stores.
  const double stress = strength * (ultimate_strain - kappa) / (ultimate_strain - eps_0);
  return 0.5 * strength * eps_0 + 0.5 * (strength + stress) * (kappa - eps_0) - 0.5 * stress * kappa;
}

double released_energy_density(const BeamTeeth& teeth, double axial_modulus) {
  double w = 0.0;
  for (std::size_t i = 0; i < teeth.strength.size(); ++i) {
    const double e_i = teeth.stiffness_factor[i] * axial_modulus;
    const double e_next = i + 1 < teeth.strength.size() ? teeth.stiffness_factor[i + 1] * axial_modulus : 0.0;
    const double eps_i = teeth.strength[i] / e_i;
    w += 0.5 * (e_i - e_next) * eps_i * eps_i;
  }
  return w;
}

BeamTeeth sawtooth_teeth(double axial_modulus, double tensile_strength, double fracture_energy, double length,
                         const SawtoothSpec& spec) {
  spec.validate();
  for (const auto& [value, name] :
       {std::pair{axial_modulus, "axial_modulus"}, std::pair{tensile_strength, "tensile_strength"},
        std::pair{fracture_energy, "fracture_energy"}, std::pair{length, "length"}})
    core::require_finite(value, name);
  core::require_positive(axial_modulus, "axial_modulus");
  core::require_positive(tensile_strength, "tensile_strength");
  core::require_positive(fracture_energy, "fracture_energy");
  core::require_positive(length, "length");
  const double e_n = axial_modulus, f_t = tensile_strength;
  const double target = fracture_energy / length;  // G_f d over the volume d L
  const double eps_0 = f_t / e_n, eps_u = 2.0 * fracture_energy / (f_t * length);
  if (is_snap_back(e_n, f_t, fracture_energy, length)) {  // one tooth that releases the same energy
    BeamTeeth t;
    t.brittle = true;
    t.ultimate_strain = eps_u;
    t.stiffness_factor = {1.0};
    t.strength = {first_tooth_strength(e_n, f_t, fracture_energy, length)};
    return t;
  }
  // The released energy grows with eps_u (every tooth's peak moves out along its secant): bracket the
  // eps_u that releases `target`, then bisect to the last bit.
  double lo = eps_u, hi = eps_u;
  while (released_energy_density(teeth_on(e_n, f_t, hi, spec), e_n) < target) hi = eps_0 + 2.0 * (hi - eps_0);
  for (int k = 0; k < 200 && lo < hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    (released_energy_density(teeth_on(e_n, f_t, mid, spec), e_n) < target ? lo : hi) = mid;
  }
  return teeth_on(e_n, f_t, hi, spec);
}

}  // namespace hm::lattice2d
