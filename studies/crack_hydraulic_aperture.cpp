// Study (an executable, not a test; it asserts nothing): how much of a straight crack's parallel-plate
// transmissivity w^3/12 does the lattice's cubic law carry, with each of the apertures a facet can take
// (CrackAperture, crack_facet_openings)? A disk is cut along y = 0, |x| < 0.8 (fracture/notch.hpp's
// beams_crossing) and the half above is moved rigidly by w; the cut beams' Voronoi facets form one chain
// from end to end, each conducting a^3/(12 d) (d its flow distance, a its aperture), in series
// (tests/lattice2d/test_flow_network.cpp checks that the network is that series). Per lattice:
//   tortuosity   sum d / L, L = sum d |n_y| the chain's length projected on the crack's line (n the beam's
//                unit vector, the facet's normal): the Voronoi path against the straight one;
//   stored       sum a d / (w L) with the axial opening a = w |n_y|: the crack's fluid volume against w L;
//   h (...)      L / sum (d (w/a)^3) for the half moved up by w (opened): the transmissivity over w^3/12,
//                with a the axial opening, the jump's length or the jump along the crack's local normal
//                (1/tortuosity where a = w on every facet);
//   slid (...)   the mean aperture over w for the half moved along the cut by w instead (slid): a crack
//                that slides along itself and opens nothing, where a facet's jump is still w;
//   worst facet  the smallest |n_y| on the chain: a facet nearly along the opening, a pinch of the axial law.
// Run: build/studies/study_crack_hydraulic_aperture [N ...] (default 3000 10000 30000 100000), seeds 1-5
// each, one markdown row per lattice, then the mean and standard deviation per N. Findings: docs/flow.md,
// "The cubic law on a lattice crack".
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <Eigen/Core>

#include "hm/lattice2d/coupled/coupling.hpp"
#include "hm/lattice2d/fracture/notch.hpp"
#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "lattice2d/lattice_fixtures.hpp"

namespace {

constexpr std::array kApertures{hm::lattice2d::CrackAperture::axial, hm::lattice2d::CrackAperture::jump,
                                hm::lattice2d::CrackAperture::crack_normal};

struct ChainMeasures {
  int facets = 0;
  double tortuosity = 0.0, stored = 0.0, worst = 1.0;
  std::array<double, kApertures.size()> h{}, slid{};
};

ChainMeasures measure(const hm::lattice2d::Lattice& lattice) {
  using namespace hm::lattice2d;
  const DualGraph dual = build_dual_graph(lattice);
  const std::vector<int> cut = beams_crossing(lattice, NotchSegment{{-0.8, 0.0}, {0.8, 0.0}});
  Eigen::VectorXd weight = Eigen::VectorXd::Zero(lattice.n_beams());
  for (const int e : cut) weight[e] = 1.0;
  const double w = 1e-3;
  const auto moved = [&](int component) {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(3 * lattice.n_particles());
    for (int i = 0; i < lattice.n_particles(); ++i)
      if (lattice.points(1, i) > 0.0) u[3 * i + component] = w;
    return u;
  };
  const Eigen::VectorXd opened = moved(1), slid = moved(0);
  ChainMeasures m;
  double path = 0.0, projected = 0.0;
  for (const int e : cut) {
    const double n_y = std::abs(lattice.direction(1, e));
    const double d = dual.flow_distance[e];
    path += d;
    projected += d * n_y;
    m.stored += w * n_y * d;
    m.worst = std::min(m.worst, n_y);
  }
  for (std::size_t k = 0; k < kApertures.size(); ++k) {
    const Eigen::VectorXd a = crack_facet_openings(lattice, dual, weight, opened, kApertures[k]);
    const Eigen::VectorXd a_slid = crack_facet_openings(lattice, dual, weight, slid, kApertures[k]);
    double resistance = 0.0, slid_sum = 0.0;
    for (const int e : cut) {
      resistance += dual.flow_distance[e] * std::pow(w / std::max(a[e], 0.0), 3);
      slid_sum += std::max(a_slid[e], 0.0);
    }
    m.h[k] = projected / resistance;
    m.slid[k] = slid_sum / (w * static_cast<double>(cut.size()));
  }
  m.facets = static_cast<int>(cut.size());
  m.tortuosity = path / projected;
  m.stored /= w * projected;
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
  std::printf(
      "| N | seed | facets | tortuosity | stored | h (axial) | h (jump) | h (crack normal) | slid (axial) | "
      "slid (jump) | slid (crack normal) | worst facet |n_y| |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<std::vector<double>> summary;
  for (const long long n : sizes) {
    std::vector<std::vector<double>> columns(1 + 2 * kApertures.size());
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      const ChainMeasures m = measure(hm::test::make_lattice(hm::lattice2d::DomainShape::disk, n, seed));
      std::printf("| %lld | %llu | %d | %.4f | %.6f | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.3f |\n", n,
                  static_cast<unsigned long long>(seed), m.facets, m.tortuosity, m.stored, m.h[0], m.h[1], m.h[2],
                  m.slid[0], m.slid[1], m.slid[2], m.worst);
      std::fflush(stdout);
      columns[0].push_back(m.tortuosity);
      for (std::size_t k = 0; k < kApertures.size(); ++k) {
        columns[1 + k].push_back(m.h[k]);
        columns[1 + kApertures.size() + k].push_back(m.slid[k]);
      }
    }
    std::vector<double> row{static_cast<double>(n)};
    for (const auto& x : columns) {
      double mean = 0.0, sd = 0.0;
      mean_sd(x, mean, sd);
      row.push_back(mean);
      row.push_back(sd);
    }
    summary.push_back(row);
  }
  std::printf(
      "\n| N | tortuosity | h (axial) | h (jump) | h (crack normal) | slid (axial) | slid (jump) | slid (crack normal) "
      "|\n"
      "|---|---|---|---|---|---|---|---|\n");
  for (const auto& r : summary) {
    std::printf("| %.0f |", r[0]);
    for (std::size_t c = 1; c + 1 < r.size(); c += 2) std::printf(" %.4f ± %.4f |", r[c], r[c + 1]);
    std::printf("\n");
  }
  return 0;
}
