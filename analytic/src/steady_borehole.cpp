// Implemented by the steady-borehole work item; placeholder so the library links.
#include "hm/analytic/steady_borehole.hpp"
#include <stdexcept>
namespace hm::analytic {
SteadyBorehole::SteadyBorehole(double Q, double b, double nu, double R_i) : Q_(Q), b_(b), nu_(nu), R_i_(R_i) {}
double SteadyBorehole::borehole_pressure() const { throw std::logic_error("not implemented"); }
RadialState SteadyBorehole::state(double) const { throw std::logic_error("not implemented"); }
}  // namespace hm::analytic
