#include "hm/analytic/radial_state.hpp"

namespace hm::analytic {

void set_plane_strain_stresses(RadialState& s, double nu, double eps_r, double eps_theta) {
  // Hooke's law in plane strain with E = 1: sigma = lambda tr(eps) I + 2 G eps, eps_z = 0.
  const double lambda = nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  const double two_G = 1.0 / (1.0 + nu);
  const double trace = eps_r + eps_theta;
  s.sigma_r = lambda * trace + two_G * eps_r;
  s.sigma_theta = lambda * trace + two_G * eps_theta;
  s.sigma_z = lambda * trace;
}

}  // namespace hm::analytic
