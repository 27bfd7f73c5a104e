#include "hm/analytic/poroelastic_parameters.hpp"

#include "hm/core/input_error.hpp"
#include "hm/core/validation.hpp"

namespace hm::analytic {

using namespace hm::core;  // require_* and format_value

double vol_strain_factor(VolStrain v) { return v == VolStrain::plane_strain ? 1.0 : 1.0 / 3.0; }

void PoroelasticParameters::validate() const {
  require_open(nu, "nu", 0.0, 0.5);
  require_closed(b, "b", 0.0, 1.0);
  require_positive(E_over_M, "E_over_M");
}

double oedometric_compliance(double nu) { return (1.0 + nu) * (1.0 - 2.0 * nu) / (1.0 - nu); }

double storage_coefficient(const PoroelasticParameters& m) {
  return m.E_over_M + vol_strain_factor(m.vol_strain) * m.b * m.b * oedometric_compliance(m.nu);
}

}  // namespace hm::analytic
