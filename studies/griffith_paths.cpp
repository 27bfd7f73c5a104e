// Study (an executable, not a test; it asserts nothing): how far is the saw-tooth law's toughness from
// Griffith's because of its teeth, and how far because of the resolution? The dry crack of
// lattice2d.griffith_growth (a notch |x| < 0.05 in a free disk of radius 1, grown by its volume) is grown
// on the law's teeth, one event at a time, and on the envelope the teeth approximate, followed by secant
// iterations (the teeth's limit), for each N; one row per growth:
//   K / K_c (median p sqrt(pi c) over c in [0.1, 0.3]), and per unit crack length over G_f what the law
//   booked, what the growth cost (W - pV/2) and what the rock dissipated (the pressure's work on the
//   solid - pV/2; the difference is the fluid filling facets that opened before they were wetted).
// Run: OMP_NUM_THREADS=1 build/studies/study_griffith_paths [N ...] (default 6000 15000), one markdown
// row per growth as it finishes. Knobs (environment): HM_GRIFFITH_KAPPA the law's strength factor
// (default the calibrated one), HM_GRIFFITH_LCH l_ch = E G_f / T_u^2 over R (default 0.04, the
// benchmark's), HM_GRIFFITH_PATHS a subset of "teeth,continuous" (default both), HM_GRIFFITH_FACES
// "wet" (process zone pressurised by its damage, default) or "dry", HM_GRIFFITH_SEED lattice and strength
// seed (default 1), HM_GRIFFITH_STEP and HM_GRIFFITH_TOL the continuous path's volume step and history
// tolerance (defaults 0.005, 1e-3). Findings: docs/fracture_law.md, "Teeth or resolution".
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "crack_growth.hpp"

namespace {

double env_or(const char* name, double fallback) {
  const char* v = std::getenv(name);
  if (!v) return fallback;
  char* end = nullptr;
  const double x = std::strtod(v, &end);
  if (*end != '\0' || !(x > 0.0 && std::isfinite(x))) {
    std::fprintf(stderr, "study_griffith_paths: %s = %s, allowed: a number > 0, finite\n", name, v);
    std::exit(2);
  }
  return x;
}

std::string env_or(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return v ? std::string(v) : fallback;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace hm::verification;
  std::vector<long long> sizes;
  for (int a = 1; a < argc; ++a) {
    char* end = nullptr;
    const long long n = std::strtoll(argv[a], &end, 10);
    if (*end != '\0' || n < 100) {
      std::fprintf(stderr, "study_griffith_paths: N = %s, allowed: an integer >= 100\n", argv[a]);
      return 2;
    }
    sizes.push_back(n);
  }
  if (sizes.empty()) sizes = {6000, 15000};
  const double t_u = hm::lattice2d::StrengthSpec{}.tensile_strength;
  const double g_f = env_or("HM_GRIFFITH_LCH", kGrowthCharacteristicLength) * t_u * t_u;
  const double k_c = griffith_constants(g_f).k_c;
  const std::string paths = env_or("HM_GRIFFITH_PATHS", std::string("teeth,continuous"));
  const std::string faces = env_or("HM_GRIFFITH_FACES", std::string("wet"));
  if (faces != "wet" && faces != "dry") {
    std::fprintf(stderr, "study_griffith_paths: HM_GRIFFITH_FACES = %s, allowed: wet, dry\n", faces.c_str());
    return 2;
  }
  if (paths.find("teeth") == std::string::npos && paths.find("continuous") == std::string::npos) {
    std::fprintf(stderr, "study_griffith_paths: HM_GRIFFITH_PATHS = %s, allowed: teeth, continuous or both\n",
                 paths.c_str());
    return 2;
  }
  const bool wet = faces == "wet";
  // Every knob read (and refused) before anything is printed; the rest of the spec is the benchmark's.
  CrackGrowthSpec base;
  base.lattice_seed = base.strength_seed = static_cast<std::uint64_t>(env_or("HM_GRIFFITH_SEED", 1.0));
  base.fracture_energy = g_f;
  base.strength_factor = env_or("HM_GRIFFITH_KAPPA", base.strength_factor);
  base.faces = wet ? PressurisedFaces::with_softening : PressurisedFaces::broken;
  base.volume_step = env_or("HM_GRIFFITH_STEP", base.volume_step);
  base.history_tolerance = env_or("HM_GRIFFITH_TOL", base.history_tolerance);
  std::printf(
      "| path | faces | kappa | N | seed | K / K_c | booked / G_f | cost (W - pV/2) / G_f | rock / G_f | broken | "
      "solves | s |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (long long n : sizes)
    for (const std::string path : {"teeth", "continuous"}) {
      if (paths.find(path) == std::string::npos) continue;
      CrackGrowthSpec spec = base;
      spec.n_particles = n;
      spec.path = path == "teeth" ? SofteningPath::teeth : SofteningPath::continuous;
      const CrackGrowthRun run = grow_pressurised_crack(spec);
      const GrowthMeasures m = measure_growth(run);
      std::printf("| %s | %s | %.3g | %lld | %llu | %.4f | %.4f | %.4f | %.4f | %d | %d | %.1f |\n", path.c_str(),
                  wet ? "wet" : "dry", spec.strength_factor, n, static_cast<unsigned long long>(spec.lattice_seed),
                  m.toughness / k_c, m.booked / g_f, m.released / g_f, m.rock / g_f, run.n_broken, run.n_solves,
                  run.seconds);
      std::fflush(stdout);
    }
  return 0;
}
