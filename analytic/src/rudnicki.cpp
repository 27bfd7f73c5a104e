// Implemented by the Rudnicki work item; placeholder so the library links.
#include "hm/analytic/rudnicki.hpp"
#include <stdexcept>
namespace hm::analytic {
RudnickiLineSource::RudnickiLineSource(double Q, const PoroelasticParameters& m)
    : Q_(Q), material_(m), storage_(storage_coefficient(m)) {}
double RudnickiLineSource::pressure(double, double) const { throw std::logic_error("not implemented"); }
double RudnickiLineSource::radial_displacement(double, double) const { throw std::logic_error("not implemented"); }
RadialState RudnickiLineSource::state(double, double) const { throw std::logic_error("not implemented"); }
}  // namespace hm::analytic
