#pragma once
/// \file
/// The one way to build the coupled 2D model of a case: the lattice of [lattice], the calibrated beams
/// of its stiffness scaling, the case's boundary, mechanics, flow and coupling, and, with [fracture]
/// enabled, one strength per beam drawn from [fracture] and the case's break loop.
#include <memory>

#include "hm/case/run_case.hpp"
#include "hm/lattice2d/coupled/coupled_model.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"

namespace hm::cases {

/// The model of case `c` on the lattice generated from c.lattice. Throws hm::InputError (via the
/// model's validation) for inconsistent parameters. Owned by pointer: the model holds its parts by
/// reference and never moves.
std::unique_ptr<lattice2d::CoupledModel> make_coupled_model(const RunCase& c);

/// The same on a lattice already generated from c.lattice (a study that runs one lattice many times).
std::unique_ptr<lattice2d::CoupledModel> make_coupled_model(const RunCase& c, lattice2d::Lattice lattice);

}  // namespace hm::cases
