#include "hm/lattice2d/fracture/sawtooth_law.hpp"

#include <cassert>
#include <cmath>
#include <string>

#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

namespace hm::lattice2d {

void SawtoothLawOptions::validate() const {
  if (!(std::isfinite(fracture_energy) && fracture_energy > 0.0))
    throw hm::InputError("sawtooth_law.fracture_energy = " + core::format_value(fracture_energy) +
                         ", allowed: > 0, finite");
  if (!(std::isfinite(strength_factor) && strength_factor > 0.0))
    throw hm::InputError("sawtooth_law.strength_factor = " + core::format_value(strength_factor) +
                         ", allowed: > 0, finite");
  try {
    teeth.validate();
  } catch (const hm::InputError& e) {
    throw hm::InputError(std::string("sawtooth_law.") + e.what());
  }
}

double calibrated_sawtooth_strength_factor() { return 1.36; }

SawtoothLaw::SawtoothLaw(const Lattice& lattice, const DualGraph& dual, const BeamParameters& parameters,
                         const BeamStrengths& strengths, const SawtoothLawOptions& options)
    : lattice_(lattice), options_(options) {
  options_.validate();
  const int n = lattice.n_beams();
  if (strengths.n_beams() != n)
    throw hm::InputError("strengths: " + std::to_string(strengths.n_beams()) + " beams, allowed: one per beam (" +
                         std::to_string(n) + ")");
  assert(dual.dual_length.size() == n && "dual graph of another lattice");
  section_.resize(static_cast<std::size_t>(n));
  axial_modulus_.resize(static_cast<std::size_t>(n));
  tensile_.resize(static_cast<std::size_t>(n));
  first_strength_.resize(static_cast<std::size_t>(n));
  tooth_.assign(static_cast<std::size_t>(n), 0);
  const double g_f = options_.fracture_energy;
  for (int e = 0; e < n; ++e) {
    const auto k = static_cast<std::size_t>(e);
    const double length = lattice.length[e];
    const double k_n = beam_parameters_for(lattice, parameters, e).normal_stiffness;
    // The section the beam's stiffness stands for: under voronoi_facet k_n,beam = k_n sqrt(3)
    // max(d/L, floor), so d = k_n,beam L / (sqrt(3) k_n) gives every beam the modulus sqrt(3) k_n.
    const double d = parameters.stiffness_scaling == StiffnessScaling::voronoi_facet
                         ? k_n * length / (std::sqrt(3.0) * parameters.normal_stiffness)
                         : dual.dual_length[e];
    if (!(d > 0.0))
      throw hm::InputError("beam " + std::to_string(e) + ": facet length = " + core::format_value(d) +
                           ", allowed: > 0 (the saw-tooth law needs the beam's section; use stiffness_scaling = "
                           "voronoi_facet with facet_floor > 0)");
    section_[k] = d;
    axial_modulus_[k] = k_n * length / d;
    tensile_[k] = options_.strength_factor * strengths.tensile[e];
    first_strength_[k] = first_tooth_strength(axial_modulus_[k], tensile_[k], g_f, length);
    n_brittle_ += is_snap_back(axial_modulus_[k], tensile_[k], g_f, length);
  }
}

LinearSoftening SawtoothLaw::envelope(int beam) const {
  const auto k = static_cast<std::size_t>(beam);
  return linear_softening(axial_modulus_[k], tensile_[k], options_.fracture_energy, lattice_.length[beam]);
}

const BeamTeeth& SawtoothLaw::teeth(int beam) {
  auto it = teeth_.find(beam);
  if (it == teeth_.end()) {
    const auto k = static_cast<std::size_t>(beam);
    it = teeth_
             .emplace(beam, sawtooth_teeth(axial_modulus_[k], tensile_[k], options_.fracture_energy,
                                           lattice_.length[beam], options_.teeth))
             .first;
  }
  return it->second;
}

double SawtoothLaw::strength(int beam) const {
  const int i = tooth(beam);
  if (i == 0) return first_strength_[static_cast<std::size_t>(beam)];
  return teeth_.at(beam).strength[static_cast<std::size_t>(i)];  // a beam past tooth 0 has its teeth
}

bool SawtoothLaw::on_last_tooth(int beam) const {
  const int i = tooth(beam);
  if (i == 0)
    return options_.teeth.n_teeth == 1 ||
           is_snap_back(axial_modulus_[static_cast<std::size_t>(beam)], tensile_[static_cast<std::size_t>(beam)],
                        options_.fracture_energy, lattice_.length[beam]);
  return i + 1 >= static_cast<int>(teeth_.at(beam).strength.size());
}

double SawtoothLaw::next_stiffness_factor(int beam) {
  assert(!on_last_tooth(beam) && "next_stiffness_factor: on the last tooth");
  return teeth(beam).stiffness_factor[static_cast<std::size_t>(tooth(beam)) + 1];
}

double SawtoothLaw::give_way(int beam) {
  const BeamTeeth& t = teeth(beam);
  const auto k = static_cast<std::size_t>(beam);
  const auto i = static_cast<std::size_t>(tooth_[k]);
  assert(i < t.strength.size() && "give_way: the beam is spent");
  // (1/2)(E_i - E_{i+1}) eps_i^2 per unit volume, times the volume d L.
  const double e_i = t.stiffness_factor[i] * axial_modulus_[k];
  const double e_next = i + 1 < t.strength.size() ? t.stiffness_factor[i + 1] * axial_modulus_[k] : 0.0;
  const double eps_i = t.strength[i] / e_i;
  const double energy = 0.5 * (e_i - e_next) * eps_i * eps_i * section_[k] * lattice_.length[beam];
  ++tooth_[k];
  dissipated_ += energy;
  return energy;
}

void SawtoothLaw::save_state(core::StateWriter& w) const {
  w.put("sawtooth.tooth", tooth_);
  w.put("sawtooth.dissipated", dissipated_);
}

void SawtoothLaw::restore_state(core::StateReader& r) {
  std::vector<int> tooth;
  r.get("sawtooth.tooth", tooth);
  if (tooth.size() != tooth_.size())
    throw hm::InputError(r.source() + ": at 'sawtooth.tooth': a state of another lattice");
  for (std::size_t k = 0; k < tooth.size(); ++k)
    if (tooth[k] < 0 || tooth[k] > options_.teeth.n_teeth)
      throw hm::InputError(r.source() + ": at 'sawtooth.tooth': beam " + std::to_string(k) + " on tooth " +
                           std::to_string(tooth[k]) + ", allowed: 0 ... " + std::to_string(options_.teeth.n_teeth));
  r.get("sawtooth.dissipated", dissipated_);
  tooth_ = std::move(tooth);
  teeth_.clear();
  for (std::size_t k = 0; k < tooth_.size(); ++k)
    if (tooth_[k] > 0) teeth(static_cast<int>(k));
}

}  // namespace hm::lattice2d
