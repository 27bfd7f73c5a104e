// The saw-tooth softening of one beam: taken through all its teeth it dissipates G_f times its facet
// whatever its length (the crack band's energy identity), on teeth that keep the envelope's shape.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "hm/core/input_error.hpp"
#include "hm/lattice2d/fracture/sawtooth.hpp"

using namespace hm::lattice2d;

namespace {

// Table 1's rock in the toolkit's units: f_t = T_u/E = 2e-4; K_Ic = 0.5 MPa m^1/2 gives
// G_f = K_Ic^2 (1 - nu^2) / E = 23.4 J/m^2, over E R: 2.34e-9. The critical beam length
// 2 E_n G_f / f_t^2 is then 0.117 (E_n = 1).
constexpr double e_n = 1.0, f_t = 2e-4, g_f = 2.34e-9;

// Displacement control of the single beam through its teeth: the work sum_i (1/2) E_i
// (eps_i^2 - eps_{i-1}^2) done on it up to each drop; at the end it holds no elastic energy, so the
// work is what it dissipated. Independent of released_energy_density's sum over drops.
double work_to_break(const BeamTeeth& t) {
  double work = 0.0, eps_before = 0.0;
  for (std::size_t i = 0; i < t.strength.size(); ++i) {
    const double e_i = t.stiffness_factor[i] * e_n;
    const double eps_i = t.strength[i] / e_i;
    REQUIRE(eps_i >= eps_before);  // each tooth gives way at a larger strain: no cascade at one strain
    work += 0.5 * e_i * (eps_i * eps_i - eps_before * eps_before);
    eps_before = eps_i;
  }
  return work;
}

}  // namespace

TEST_CASE("A saw-tooth beam dissipates G_f per unit facet at every length", "[lattice2d][fracture]") {
  const SawtoothSpec spec;  // a = 2, 10 teeth
  for (double length : {0.002, 0.006, 0.02, 0.05, 0.1, 0.116, 0.2, 0.5}) {
    INFO("L = " << length);
    const BeamTeeth t = sawtooth_teeth(e_n, f_t, g_f, length, spec);
    // Energy per unit volume times the length = energy per unit facet: G_f to round-off (the
    // stretch of the envelope is bisected to the last bit).
    CHECK(released_energy_density(t, e_n) * length == Approx(g_f).epsilon(1e-12));
    CHECK(work_to_break(t) * length == Approx(g_f).epsilon(1e-12));
    const bool too_long = length >= 2.0 * e_n * g_f / (f_t * f_t);
    CHECK(t.brittle == too_long);
    if (too_long) {
      REQUIRE(t.strength.size() == 1);
      CHECK(t.strength[0] == Approx(std::sqrt(2.0 * e_n * g_f / length)).epsilon(1e-15));
      CHECK(t.strength[0] < f_t);
      continue;
    }
    REQUIRE(t.strength.size() == 10);
    CHECK(t.strength[0] == f_t);  // initiation stays the strength criterion
    // The teeth lie on the stretched envelope, from (eps_0, f_t) to (eps_u', 0), in falling order.
    const double eps_0 = f_t / e_n, d = f_t / (t.ultimate_strain - eps_0);
    for (std::size_t i = 0; i < t.strength.size(); ++i) {
      CHECK(t.stiffness_factor[i] == std::pow(0.5, static_cast<double>(i)));
      const double eps_i = t.strength[i] / (t.stiffness_factor[i] * e_n);
      // To round-off in the strains (~1e-16 eps_u) times the softening slope D: next to the critical
      // length (eps_u' = 1.013 eps_0) D is ~80 E_n and the difference eps_u' - eps_i cancels digits.
      const double round_off = 1e-14 * d * t.ultimate_strain;
      CHECK(t.strength[i] == Approx(d * (t.ultimate_strain - eps_i)).epsilon(1e-12).margin(round_off));
      if (i > 0) CHECK(t.strength[i] < t.strength[i - 1]);
    }
    // The stretch that makes the teeth's area G_f. On the unstretched envelope the teeth release 72%
    // (L = 0.002, eps_u = 58 eps_0) to 99.7% (L = 0.116, next to the critical length) of G_f, and the
    // stretch that restores it is 1.41 ... 1.004 (a = 2, 10 teeth; computed independently): < 1.5.
    const double eps_u = 2.0 * g_f / (f_t * length);
    CHECK(t.ultimate_strain > eps_u);
    CHECK(t.ultimate_strain < 1.5 * eps_u);
  }
}

TEST_CASE("The saw-tooth refuses a bad spec or beam by name", "[lattice2d][fracture]") {
  CHECK_THROWS_WITH(sawtooth_teeth(e_n, f_t, g_f, 0.01, SawtoothSpec{1.0, 10}),
                    "sawtooth.reduction = 1, allowed: > 1, finite");
  CHECK_THROWS_WITH(sawtooth_teeth(e_n, f_t, g_f, 0.01, SawtoothSpec{2.0, 0}),
                    "sawtooth.n_teeth = 0, allowed: 1 ... 100");
  CHECK_THROWS_AS(sawtooth_teeth(e_n, f_t, -1.0, 0.01), hm::InputError);
  CHECK_THROWS_AS(sawtooth_teeth(e_n, f_t, g_f, NAN), hm::InputError);
  CHECK_THROWS_AS(sawtooth_teeth(INFINITY, f_t, g_f, 0.01), hm::InputError);
}

TEST_CASE("The teeth's envelope followed continuously dissipates what a damage law does, G_f per unit facet at the end",
          "[lattice2d][fracture]") {
  for (double length : {0.002, 0.02, 0.1, 0.2}) {
    INFO("L = " << length);
    const LinearSoftening env = linear_softening(e_n, f_t, g_f, length);
    CHECK(env.dissipated_density(env.ultimate_strain) * length == Approx(g_f).epsilon(1e-12));
    CHECK(env.secant_factor(0.5 * env.peak_strain()) == 1.0);
    CHECK(env.secant_factor(env.ultimate_strain) == 0.0);
    if (length >= 2.0 * e_n * g_f / (f_t * f_t)) {  // no softening branch: breaks at the reduced strength
      CHECK(env.strength == Approx(std::sqrt(2.0 * e_n * g_f / length)).epsilon(1e-15));
      CHECK(env.ultimate_strain == env.peak_strain());
      // At that strength the beam's stored triangle is G_f / L: what breaking it releases.
      CHECK(0.5 * env.strength * env.peak_strain() * length == Approx(g_f).epsilon(1e-12));
      continue;
    }
    CHECK(env.strength == f_t);
    CHECK(env.dissipated_density(env.peak_strain()) == 0.0);
    CHECK(env.ultimate_strain == Approx(2.0 * g_f / (f_t * length)).epsilon(1e-15));
    // A damage law dissipates (1/2) E_n kappa^2 per unit drop of its secant factor (the energy the
    // secant stores at fixed strain): its integral from eps_0, by the midpoint rule on 20000 intervals
    // (error O(h^2), ~1e-9 relative here), is the closed form at every kappa.
    const int n = 20000;
    const double h = (env.ultimate_strain - env.peak_strain()) / n;
    double integral = 0.0;
    for (int i = 0; i < n; ++i) {
      const double a = env.peak_strain() + i * h, b = a + h, mid = a + 0.5 * h;
      integral += 0.5 * e_n * mid * mid * (env.secant_factor(a) - env.secant_factor(b));
      if (i == n / 2 - 1 || i == n - 1) CHECK(integral == Approx(env.dissipated_density(b)).epsilon(1e-7));
    }
    // On the envelope: the secant's stress falls linearly from f_t to 0.
    const double kappa = 0.5 * (env.peak_strain() + env.ultimate_strain);
    CHECK(env.secant_factor(kappa) * e_n * kappa == Approx(0.5 * f_t).epsilon(1e-12));
  }
}
