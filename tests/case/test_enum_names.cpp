// Every enum a case file, a CLI option or a result column spells has a complete names table: each
// value named, no two values with one name, and every name parsed back to its value.
#include <catch2/catch.hpp>
#include <set>
#include <string>

#include "hm/analytic/failure_criteria.hpp"
#include "hm/analytic/poroelastic_parameters.hpp"
#include "hm/core/enum_names.hpp"
#include "hm/lattice2d/coupled/coupled_model.hpp"
#include "hm/lattice2d/coupled/relaxation.hpp"
#include "hm/lattice2d/flow/flow_network.hpp"
#include "hm/lattice2d/fracture/fracture.hpp"
#include "hm/lattice2d/fracture/fracture_statistics.hpp"
#include "hm/lattice2d/fracture/strength.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/linalg/spd_solver.hpp"
#include "hm/lattice2d/mechanics/beam_stiffness.hpp"
#include "hm/lattice2d/mechanics/mechanics.hpp"

namespace lt = hm::lattice2d;

// The enums' values run 0 ... n - 1 (none sets its own): a table with n entries names each one.
template <class Enum>
void check_names(int n_values) {
  const auto table = enum_names(Enum{});
  CHECK(static_cast<int>(table.size()) == n_values);
  std::set<std::string> names;
  for (int k = 0; k < n_values; ++k) {
    const auto value = static_cast<Enum>(k);
    const std::string name = hm::core::name_of(value);
    INFO(name);
    CHECK_FALSE(name.empty());
    CHECK(name.rfind("unknown(", 0) != 0);
    CHECK(hm::core::from_name<Enum>(name, "key") == value);
    names.insert(name);
  }
  CHECK(static_cast<int>(names.size()) == n_values);
}

TEST_CASE("Every named enum has one distinct name per value, parsed back to it", "[case]") {
  check_names<lt::DomainShape>(3);
  check_names<lt::StiffnessScaling>(2);
  check_names<lt::BoundarySupport>(2);
  check_names<lt::SpdSolverKind>(2);
  check_names<lt::BoreholeStorage>(3);
  check_names<lt::BoreholeDeformation>(3);
  check_names<lt::BrokenBeamSpring>(2);
  check_names<lt::CrackCoupling>(2);
  check_names<lt::CouplingSplit>(2);
  check_names<lt::CouplingRelaxation>(3);
  check_names<lt::FractureCheck>(2);
  check_names<lt::CouplingPredictor>(2);
  check_names<lt::CoupledStatus>(6);
  check_names<lt::StrengthDistribution>(3);
  check_names<lt::FractureLink>(2);
  check_names<lt::FractureKind>(2);
  check_names<lt::BreakLoopStatus>(4);
  check_names<lt::LoadingStatus>(5);
  check_names<hm::analytic::FailureMode>(3);
  check_names<hm::analytic::VolStrain>(2);
}
