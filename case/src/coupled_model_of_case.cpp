#include "hm/case/coupled_model_of_case.hpp"

#include "hm/lattice2d/fracture/notch.hpp"
#include "hm/lattice2d/fracture/strength.hpp"

namespace hm::cases {

namespace lt = hm::lattice2d;

std::unique_ptr<lt::CoupledModel> make_coupled_model(const RunCase& c, lt::Lattice lattice) {
  auto model = std::make_unique<lt::CoupledModel>(std::move(lattice), c.beams(), c.boundary_conditions(), c.mechanics,
                                                  c.flow_parameters(), c.coupling);
  if (c.fracture_enabled) {
    model->enable_fracture(lt::draw_beam_strengths(c.strength, model->lattice().n_beams()), c.break_loop);
    if (c.fracture_law == lt::FractureLaw::sawtooth) model->use_sawtooth_law(c.sawtooth);
    model->cut_beams(lt::beams_crossing(model->lattice(), c.notches), c.notch_aperture);
  }
  return model;
}

std::unique_ptr<lt::CoupledModel> make_coupled_model(const RunCase& c) {
  return make_coupled_model(c, lt::generate_lattice(c.lattice));
}

}  // namespace hm::cases
