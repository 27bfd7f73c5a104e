#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include "approx.hpp"
#include "hm/core/input_error.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/mechanics/beam_stiffness.hpp"

using namespace hm::lattice2d;

namespace {

// Rigid-body motions of the whole lattice: translations in x and y, rotation about the origin
// (u = omega e_z x x, and every particle turns by omega).
Eigen::VectorXd rigid_motion(const Eigen::Matrix2Xd& x, int mode) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * x.cols());
  for (int i = 0; i < x.cols(); ++i) {
    if (mode == 0) u[dof_index(i, 0)] = 1.0;
    if (mode == 1) u[dof_index(i, 1)] = 1.0;
    if (mode == 2) {
      u[dof_index(i, 0)] = -x(1, i);
      u[dof_index(i, 1)] = x(0, i);
      u[dof_index(i, 2)] = 1.0;
    }
  }
  return u;
}

}  // namespace

TEST_CASE("Beam parameters: defaults valid, bad values rejected naming the field", "[lattice2d]") {
  REQUIRE_NOTHROW(BeamParameters{}.validate());
  BeamParameters p;
  p.normal_stiffness = -1.0;
  CHECK_THROWS_WITH(p.validate(), Catch::Contains("normal_stiffness = -1"));
  p = BeamParameters{};
  p.aspect = 0.0;
  CHECK_THROWS_WITH(p.validate(), Catch::Contains("aspect = 0"));
  p = BeamParameters{};
  p.beam_poisson = 0.5;
  CHECK_THROWS_AS(p.validate(), hm::InputError);
  CHECK_THROWS_WITH(p.validate(), Catch::Contains("beam_poisson = 0.5"));
}

TEST_CASE("The element stiffness has the coefficients of Eqs. 5-7", "[lattice2d]") {
  BeamParameters p;
  p.normal_stiffness = 2.0;
  p.aspect = 0.7;
  p.beam_poisson = 0.2;
  const double L = 0.3, theta = 0.7, c = std::cos(theta), s = std::sin(theta);
  const double k_n = p.normal_stiffness, k_w = p.rotational_stiffness(), g = p.gamma();
  CHECK(k_w == hm::test::roundoff(2.0 / (2.0 / 0.49 + 4.0 * 1.2)));
  CHECK(g == hm::test::roundoff(0.49 * 1.2 / 6.0));
  const Matrix6d K = beam_element_stiffness(L, theta, p);
  // Rows of particle i; columns (x_i, y_i, w_i, x_j, y_j, w_j). Eq. 5 (x), Eq. 6 (y), Eq. 7 (w),
  // the displacement terms multiply (x_i - x_j), so the j columns carry the opposite sign.
  // Eq. 7 prints 2 k_w L on the rotations; Eq. 4 and moment balance give 2 k_w L^2 (docs/lattice.md).
  const double xx = k_n * c * c + 2 * k_w * s * s, xy = (k_n - 2 * k_w) * s * c, yy = k_n * s * s + 2 * k_w * c * c;
  CHECK(K(0, 0) == hm::test::roundoff(xx));
  CHECK(K(0, 1) == hm::test::roundoff(xy));
  CHECK(K(0, 2) == hm::test::roundoff(-k_w * L * s));
  CHECK(K(0, 3) == hm::test::roundoff(-xx));
  CHECK(K(0, 4) == hm::test::roundoff(-xy));
  CHECK(K(0, 5) == hm::test::roundoff(-k_w * L * s));
  CHECK(K(1, 1) == hm::test::roundoff(yy));
  CHECK(K(1, 2) == hm::test::roundoff(k_w * L * c));
  CHECK(K(1, 5) == hm::test::roundoff(k_w * L * c));
  CHECK(K(2, 2) == hm::test::roundoff(2 * k_w * L * L * (g + 1.0 / 3.0)));
  CHECK(K(2, 5) == hm::test::roundoff(-2 * k_w * L * L * (g - 1.0 / 6.0)));
  CHECK(K(2, 3) == hm::test::roundoff(k_w * L * s));
  CHECK(K(2, 4) == hm::test::roundoff(-k_w * L * c));
  // Symmetric to round-off (T^T K T products of O(1) entries).
  CHECK((K - K.transpose()).cwiseAbs().maxCoeff() < 1e-15);
}

TEST_CASE("Element stiffness: rigid-body null space, rank 3 intact, rank 1 in contact, 0 open", "[lattice2d]") {
  const BeamParameters p;
  const double L = 0.05, theta = -2.1;
  Eigen::Matrix2Xd x(2, 2);
  x << 0.3, 0.3 + L * std::cos(theta), -0.1, -0.1 + L * std::sin(theta);
  const Matrix6d K = beam_element_stiffness(L, theta, p);
  for (int mode = 0; mode < 3; ++mode) {
    const Eigen::VectorXd u = rigid_motion(x, mode);
    // Round-off: entries O(1), displacements O(1).
    CHECK((K * u).norm() < 1e-14);
  }
  auto rank = [](const Matrix6d& m) {
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Matrix6d>(0.5 * (m + m.transpose())).eigenvalues();
    CHECK(ev.minCoeff() > -1e-14 * ev.cwiseAbs().maxCoeff());  // positive semi-definite up to round-off
    return static_cast<int>((ev.array() > 1e-10 * std::max(1.0, ev.cwiseAbs().maxCoeff())).count());
  };
  CHECK(rank(K) == 3);
  CHECK(rank(beam_element_stiffness(L, theta, p, BeamState::contact)) == 1);
  CHECK(beam_element_stiffness(L, theta, p, BeamState::open).isZero(0.0));
}

TEST_CASE("Eq. 8's contact rule: overlap closes a broken beam, separation opens it, with hysteresis", "[lattice2d]") {
  const double tol = 1e-10;
  // A just-broken beam: contact if shortened at all, else open.
  CHECK(contact_state(BeamState::intact, -1e-12, 0.0) == BeamState::contact);
  CHECK(contact_state(BeamState::intact, 0.0, 0.0) == BeamState::open);
  CHECK(contact_state(BeamState::intact, 1e-12, 0.0) == BeamState::open);
  // The active set: a switch only beyond +-tol, else the current state stays.
  CHECK(contact_state(BeamState::open, -2 * tol, tol) == BeamState::contact);
  CHECK(contact_state(BeamState::open, -0.5 * tol, tol) == BeamState::open);
  CHECK(contact_state(BeamState::contact, 0.5 * tol, tol) == BeamState::contact);
  CHECK(contact_state(BeamState::contact, 2 * tol, tol) == BeamState::open);
}

TEST_CASE("The assembled stiffness is symmetric and rigid-body motions give zero force", "[lattice2d]") {
  for (auto shape : {DomainShape::disk, DomainShape::annulus}) {
    LatticeSpec spec;
    spec.domain = shape;
    spec.n_particles = 1500;
    const Lattice lattice = generate_lattice(spec);
    BeamParameters p;
    p.aspect = 0.6;
    const Eigen::SparseMatrix<double> K = assemble_stiffness(lattice, p);
    REQUIRE(K.rows() == 3 * lattice.n_particles());
    const Eigen::SparseMatrix<double> asym = K - Eigen::SparseMatrix<double>(K.transpose());
    const double scale = K.coeffs().cwiseAbs().maxCoeff();
    // Round-off of summed element matrices with O(1) entries.
    CHECK(asym.coeffs().cwiseAbs().maxCoeff() <= 1e-14 * scale);
    for (int mode = 0; mode < 3; ++mode) {
      const Eigen::VectorXd u = rigid_motion(lattice.points, mode);
      INFO("mode " << mode);
      // Round-off: each row sums ~40 products of O(1) entries and O(1) displacements.
      CHECK((K * u).cwiseAbs().maxCoeff() < 1e-13 * scale);
    }
    // A uniform stretch u = eps x (omega = 0) is not rigid: it loads every beam in tension.
    Eigen::VectorXd stretch = Eigen::VectorXd::Zero(K.rows());
    for (int i = 0; i < lattice.n_particles(); ++i) {
      stretch[dof_index(i, 0)] = lattice.points(0, i);
      stretch[dof_index(i, 1)] = lattice.points(1, i);
    }
    CHECK(stretch.dot(K * stretch) > 0.0);
  }
}

TEST_CASE("The stiffness with the boundary particles held is positive definite", "[lattice2d]") {
  LatticeSpec spec;
  spec.domain = DomainShape::annulus;
  spec.n_particles = 1000;
  const Lattice lattice = generate_lattice(spec);
  std::vector<BeamState> states(static_cast<std::size_t>(lattice.n_beams()), BeamState::intact);
  for (std::size_t e = 0; e < states.size(); e += 10) states[e] = BeamState::contact;  // mixed states
  const Eigen::SparseMatrix<double> K = assemble_stiffness(lattice, BeamParameters{}, states);
  // Keep the free (interior-particle) dofs only.
  std::vector<int> free;
  for (int i = 0; i < lattice.n_particles(); ++i)
    if (lattice.boundary[static_cast<std::size_t>(i)] == BoundaryTag::interior)
      for (int c = 0; c < 3; ++c) free.push_back(dof_index(i, c));
  Eigen::SparseMatrix<double> select(K.rows(), static_cast<Eigen::Index>(free.size()));
  for (std::size_t k = 0; k < free.size(); ++k) select.insert(free[k], static_cast<Eigen::Index>(k)) = 1.0;
  const Eigen::SparseMatrix<double> K_ff = Eigen::SparseMatrix<double>(select.transpose()) * K * select;
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> llt(K_ff);
  CHECK(llt.info() == Eigen::Success);
}
