// Study (an executable, not a test; it asserts nothing): how much of a straight crack's parallel-plate
// transmissivity w^3/12 does the lattice's cubic law carry? A disk is cut along y = 0, |x| < 0.8
// (fracture/notch.hpp's beams_crossing), the half above is moved up rigidly by w; the cut beams' Voronoi
// facets form one chain from end to end, each conducting a^3/(12 d) (d its flow distance, a its
// aperture), in series (tests/lattice2d/test_flow_network.cpp checks that the network is that series).
// Per lattice:
//   tortuosity   sum d / L, L = sum d |n_y| the chain's length projected on the crack's line (n the beam's
//                unit vector, the facet's normal): the Voronoi path against the straight one;
//   stored       sum a d / (w L): the crack's fluid volume against w L (the axial opening is a = w |n_y|);
//   h (axial)    L / sum (d (w/a)^3): the transmissivity with a the axial opening (the model's), over w^3/12;
//   h (jump)     L / sum d = 1/tortuosity: the same with a = |jump| = w (the facet's full displacement jump);
//   worst facet  the smallest |n_y| on the chain: a facet nearly along the opening, a pinch of the axial law.
// Run: build/studies/study_crack_hydraulic_aperture [N ...] (default 3000 10000 30000 100000), seeds 1-5
// each, one markdown row per lattice, then the mean and standard deviation per N. Findings: docs/flow.md,
// "The cubic law on a lattice crack".
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <Eigen/Core>

#include "hm/lattice2d/fracture/notch.hpp"
#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "hm/lattice2d/mechanics/beam_stiffness.hpp"
#include "lattice2d/lattice_fixtures.hpp"

namespace {

struct ChainMeasures {
  int facets = 0;
  double tortuosity = 0.0, stored = 0.0, h_axial = 0.0, h_jump = 0.0, worst = 1.0;
};

ChainMeasures measure(const hm::lattice2d::Lattice& lattice) {
  using namespace hm::lattice2d;
  const DualGraph dual = build_dual_graph(lattice);
  const std::vector<int> cut = beams_crossing(lattice, NotchSegment{{-0.8, 0.0}, {0.8, 0.0}});
  const double w = 1e-3;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * lattice.n_particles());
  for (int i = 0; i < lattice.n_particles(); ++i)
    if (lattice.points(1, i) > 0.0) u[3 * i + 1] = w;
  ChainMeasures m;
  double path = 0.0, projected = 0.0, volume = 0.0, resistance = 0.0;
  for (const int e : cut) {
    const auto [i, j] = lattice.beams[static_cast<std::size_t>(e)];
    const double n_y = std::abs(lattice.points(1, j) - lattice.points(1, i)) / lattice.length[e];
    const double d = dual.flow_distance[e];
    const double a = normal_elongation(lattice, u, e);
    path += d;
    projected += d * n_y;
    volume += a * d;
    resistance += d * std::pow(w / a, 3);
    m.worst = std::min(m.worst, n_y);
  }
  m.facets = static_cast<int>(cut.size());
  m.tortuosity = path / projected;
  m.stored = volume / (w * projected);
  m.h_axial = projected / resistance;
  m.h_jump = projected / path;
  return m;
}

void mean_sd(const std::vector<double>& x, double& mean, double& sd) {
  mean = 0.0;
  for (const double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  double s = 0.0;
  for (const double v : x) s += (v - mean) * (v - mean);
  sd = x.size() > 1 ? std::sqrt(s / static_cast<double>(x.size() - 1)) : 0.0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<long long> sizes;
  for (int a = 1; a < argc; ++a) {
    char* end = nullptr;
    const long long n = std::strtoll(argv[a], &end, 10);
    if (*end != '\0' || n < 100) {
      std::fprintf(stderr, "study_crack_hydraulic_aperture: N = %s, allowed: an integer >= 100\n", argv[a]);
      return 2;
    }
    sizes.push_back(n);
  }
  if (sizes.empty()) sizes = {3000, 10000, 30000, 100000};
  std::printf("| N | seed | facets | tortuosity | stored | h (axial) | h (jump) | worst facet |n_y| |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  std::vector<std::vector<double>> summary;
  for (const long long n : sizes) {
    std::vector<double> tortuosity, h_axial, h_jump;
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      const ChainMeasures m = measure(hm::test::make_lattice(hm::lattice2d::DomainShape::disk, n, seed));
      std::printf("| %lld | %llu | %d | %.4f | %.6f | %.4f | %.4f | %.3f |\n", n, static_cast<unsigned long long>(seed),
                  m.facets, m.tortuosity, m.stored, m.h_axial, m.h_jump, m.worst);
      std::fflush(stdout);
      tortuosity.push_back(m.tortuosity);
      h_axial.push_back(m.h_axial);
      h_jump.push_back(m.h_jump);
    }
    std::vector<double> row{static_cast<double>(n)};
    for (const auto* x : {&tortuosity, &h_axial, &h_jump}) {
      double mean = 0.0, sd = 0.0;
      mean_sd(*x, mean, sd);
      row.push_back(mean);
      row.push_back(sd);
    }
    summary.push_back(row);
  }
  std::printf("\n| N | tortuosity | h (axial) | h (jump) |\n|---|---|---|---|\n");
  for (const auto& r : summary)
    std::printf("| %.0f | %.4f ± %.4f | %.4f ± %.4f | %.4f ± %.4f |\n", r[0], r[1], r[2], r[3], r[4], r[5], r[6]);
  return 0;
}
