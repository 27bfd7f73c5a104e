// The viscosity-dominated KGD fracture (M-vertex, Adachi & Detournay 2002): its approximate profiles
// checked against the conservation laws they must satisfy, and against the rounded relations quoted
// with them, and its scalings.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include <boost/math/quadrature/tanh_sinh.hpp>

#include "hm/analytic/kgd_viscosity.hpp"

using hm::analytic::KgdViscosityVertex;

namespace {
// Lattice units: E' of nu = 0.25, mu' = 12 k/R^2 with k/R^2 = 1e-14, Q = 10.
const KgdViscosityVertex vertex{1.0 / (1.0 - 0.0625), 12e-14, 10.0};
}  // namespace

TEST_CASE("KGD M-vertex: the crack holds the injected volume and the inlet passes half of Q to each wing",
          "[analytic]") {
  const double t = 3e-6;
  const double l = vertex.half_length(t);
  boost::math::quadrature::tanh_sinh<double> integrator;
  const double volume = integrator.integrate([&](double x) { return vertex.opening(x, t); }, -l, l);
  // The shape is a three-term approximation with 3-4 digit coefficients and gamma = 0.616 (0.6152 in
  // other quotes): the volume closes to 1% (measured 0.97% high), well inside a 10% benchmark.
  CHECK(volume == Approx(vertex.Q * t).epsilon(0.015));
  CHECK(volume > vertex.Q * t);
  // Poiseuille at the inlet: each wing carries w0^3/mu' (-dp/dx) = Q/2; the pressure's kink at x = 0
  // is its B (2 - pi |rho|) term. The two-term approximation gives 0.510 Q (2% high).
  const double h = 1e-6 * l;
  const double w0 = vertex.opening(0.0, t);
  const double gradient = (vertex.net_pressure(h, t) - vertex.net_pressure(2 * h, t)) / h;
  CHECK(w0 * w0 * w0 / vertex.mu_prime * gradient == Approx(0.5 * vertex.Q).epsilon(0.03));
}

TEST_CASE("KGD M-vertex: the inlet's opening and pressure as quoted, and the vertex's scalings", "[analytic]") {
  const double t = 3e-6;
  const double w0 = vertex.opening(0.0, t), p0 = vertex.net_pressure(0.0, t), l = vertex.half_length(t);
  const double mQE = vertex.mu_prime * vertex.Q * vertex.E_prime;
  // w0 p0 = 0.62 (mu' Q E')^(1/2) and w0^2 = 2.1 (mu' Q / E')^(1/2) l (the relations GEOS quotes from
  // Adachi & Detournay, rounded to two digits): within their rounding.
  CHECK(w0 * p0 == Approx(0.62 * std::sqrt(mQE)).epsilon(0.01));
  CHECK(w0 * w0 == Approx(2.1 * std::sqrt(vertex.mu_prime * vertex.Q / vertex.E_prime) * l).epsilon(0.01));
  CHECK(l == Approx(0.616 * std::pow(vertex.E_prime * std::pow(vertex.Q, 3) / vertex.mu_prime, 1.0 / 6.0) *
                    std::pow(t, 2.0 / 3.0))
                 .epsilon(1e-14));
  // Self-similar: l ~ t^(2/3), w0 ~ t^(1/3), p0 ~ t^(-1/3).
  CHECK(vertex.half_length(8 * t) == Approx(4 * l).epsilon(1e-14));
  CHECK(vertex.opening(0.0, 8 * t) == Approx(2 * w0).epsilon(1e-14));
  CHECK(vertex.net_pressure(0.0, 8 * t) == Approx(0.5 * p0).epsilon(1e-14));
  // Closed at and beyond the tips; the pressure falls towards them (suction near the tip).
  CHECK(vertex.opening(l, t) == 0.0);
  CHECK(vertex.opening(-1.5 * l, t) == 0.0);
  CHECK(vertex.net_pressure(0.99 * l, t) < 0.0);
  // K_m of K_Ic = 0: the vertex itself.
  CHECK(vertex.toughness_number(0.0) == 0.0);
}
