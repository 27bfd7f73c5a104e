#include <catch2/catch.hpp>

#include <cmath>
#include <numeric>
#include <vector>

#include "approx.hpp"
#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/io/radial_average.hpp"

using namespace hm::lattice2d;

namespace {

Lattice make_lattice(DomainShape shape, long long n) {
  LatticeSpec spec;
  spec.domain = shape;
  spec.n_particles = n;
  spec.seed = 4;
  return generate_lattice(spec);
}

}  // namespace

TEST_CASE("Uniform shell edges run exactly from r_min to r_max", "[lattice2d]") {
  const std::vector<double> edges = uniform_shell_edges(0.138, 1.0, 7);
  REQUIRE(edges.size() == 8);
  CHECK(edges.front() == 0.138);
  CHECK(edges.back() == 1.0);
  for (std::size_t k = 0; k + 1 < edges.size(); ++k)
    CHECK(edges[k + 1] - edges[k] == hm::test::roundoff((1.0 - 0.138) / 7));
}

TEST_CASE("The shells partition the triangles and their area", "[lattice2d]") {
  for (auto shape : {DomainShape::disk, DomainShape::annulus}) {
    DYNAMIC_SECTION(hm::core::name_of(shape)) {
      const Lattice lattice = make_lattice(shape, 5000);
      const DualGraph dual = build_dual_graph(lattice);
      const Eigen::VectorXd ones = Eigen::VectorXd::Ones(lattice.n_triangles());
      // Edges that cover every centroid: nothing outside, every triangle in exactly one shell.
      const RadialProfile all = radial_average(dual, ones, uniform_shell_edges(0.0, 1.0, 13));
      CHECK(all.n_outside == 0);
      int n_binned = 0;
      double binned_area = 0.0;
      for (const RadialShell& shell : all.shells) {
        n_binned += shell.n_triangles;
        binned_area += shell.area;
        if (shell.n_triangles > 0) CHECK(shell.mean == hm::test::roundoff(1.0));
      }
      CHECK(n_binned == lattice.n_triangles());
      CHECK(binned_area == hm::test::roundoff(dual.triangle_area.sum()));
      // Edges covering part of the domain: binned + outside = all.
      const RadialProfile part = radial_average(dual, ones, {0.3, 0.5, 0.7});
      int n_part = part.n_outside;
      for (const RadialShell& shell : part.shells) n_part += shell.n_triangles;
      CHECK(n_part == lattice.n_triangles());
    }
  }
}

TEST_CASE("A field affine in the centroid radius averages to its value at the shell's mean radius", "[lattice2d]") {
  const Lattice lattice = make_lattice(DomainShape::annulus, 5000);
  const DualGraph dual = build_dual_graph(lattice);
  Eigen::VectorXd values(lattice.n_triangles());
  for (int s = 0; s < lattice.n_triangles(); ++s) values[s] = 0.3 - 2.0 * dual.centroid.col(s).norm();
  const RadialProfile profile = radial_average(dual, values, uniform_shell_edges(0.138, 1.0, 10));
  for (const RadialShell& shell : profile.shells) {
    REQUIRE(shell.n_triangles > 0);
    CHECK(shell.r_mean >= shell.r_inner);
    CHECK(shell.r_mean < shell.r_outer);
    // Exact up to round-off: the weighted mean of a + c r is a + c (weighted mean of r).
    CHECK(shell.mean == hm::test::roundoff(0.3 - 2.0 * shell.r_mean));
  }
}

TEST_CASE("A field constant on each shell is reproduced exactly", "[lattice2d]") {
  const Lattice lattice = make_lattice(DomainShape::disk, 5000);
  const DualGraph dual = build_dual_graph(lattice);
  const std::vector<double> edges = uniform_shell_edges(0.0, 1.0, 8);
  Eigen::VectorXd values(lattice.n_triangles());
  for (int s = 0; s < lattice.n_triangles(); ++s)
    values[s] = std::pow(2.0, std::floor(dual.centroid.col(s).norm() * 8.0));  // 2^k in shell k
  const RadialProfile profile = radial_average(dual, values, edges);
  for (std::size_t k = 0; k < profile.shells.size(); ++k)
    CHECK(profile.shells[k].mean == hm::test::roundoff(std::pow(2.0, k)));
}

TEST_CASE("Shells are half-open with the last one closed, and an empty shell reports NaN", "[lattice2d]") {
  // Four unit-area "triangles" with centroids at chosen radii about the centre (1, 1).
  Eigen::Matrix2Xd centroid(2, 4);
  centroid << 1.5, 2.0, 1.0, 4.0,  //
      1.0, 1.0, 3.0, 1.0;          // radii 0.5, 1, 2, 3
  const Eigen::VectorXd area = Eigen::VectorXd::Ones(4);
  const Eigen::VectorXd values = (Eigen::VectorXd(4) << 10.0, 20.0, 30.0, 40.0).finished();
  const RadialProfile profile = radial_average(centroid, area, values, {0.0, 1.0, 1.5, 2.0}, Eigen::Vector2d(1.0, 1.0));
  REQUIRE(profile.shells.size() == 3);
  CHECK(profile.shells[0].n_triangles == 1);  // r = 0.5
  CHECK(profile.shells[0].mean == 10.0);
  CHECK(profile.shells[1].n_triangles == 1);  // r = 1 sits on an edge: the upper shell
  CHECK(profile.shells[1].mean == 20.0);
  CHECK(profile.shells[2].n_triangles == 1);  // r = 2 = last edge: the last shell is closed
  CHECK(profile.shells[2].r_mean == 2.0);
  CHECK(profile.n_outside == 1);  // r = 3
  const RadialProfile sparse = radial_average(centroid, area, values, {0.0, 0.25, 0.75});
  CHECK(sparse.shells[0].n_triangles == 0);
  CHECK(std::isnan(sparse.shells[0].mean));
  CHECK(std::isnan(sparse.shells[0].r_mean));
}
