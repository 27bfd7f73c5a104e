// How `hmlattice run` fares when another process holds a core: the Fig. 12 quick case (b = 0.2) at
// N particles to t* = 4.5e-3, run as a user runs it, with OpenMP's threads spinning between regions
// (OMP_WAIT_POLICY=active, libgomp's behaviour before hmlattice chose for it), asleep (the program's
// default: passive) and on one thread, on an idle machine and beside a busy loop on one core.
//
//   build/bench/bench_busy_machine [N] [repeats]   (defaults 10000 and 3: ~6 min on this project's 2-core machine)
//
// Prints the median wall time of each way and its ratio to the one-thread run's in the same state of
// the machine.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void replace(std::string& text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error("'" + from + "' is not in the Fig. 12 quick case");
  text.replace(at, from.size(), to);
}

// Wall seconds of `hmlattice run case.toml` in `dir` with the environment assignments `env`.
double timed_run(const fs::path& dir, const std::string& env) {
  fs::remove_all(dir / "out");
  const std::string cmd =
      "cd '" + dir.string() + "' && env " + env + " '" HMLATTICE_EXE "' run case.toml --out out > run.log 2>&1";
  const auto start = std::chrono::steady_clock::now();
  if (std::system(cmd.c_str()) != 0) throw std::runtime_error("the run failed: see " + (dir / "run.log").string());
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  const long n = argc > 1 ? std::strtol(argv[1], nullptr, 10) : 10000;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 3;
  const fs::path dir = fs::temp_directory_path() / ("hmlattice-bench-busy-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::string text = read(fs::path(HM_SOURCE_DIR) / "cases/fig12_b0.2_quick.toml");
  replace(text, "n_particles = 3000", "n_particles = " + std::to_string(n));
  replace(text, "t_end = 0.0272", "t_end = 0.0045");
  replace(text, "times = [0.0045, 0.009, 0.0272]", "times = [0.0045]");
  replace(text, "vtk = true", "vtk = false");
  std::ofstream(dir / "case.toml") << text;

  struct Mode {
    const char* name;
    const char* env;
  };
  const std::vector<Mode> modes = {{"one thread (OMP_NUM_THREADS=1)", "OMP_NUM_THREADS=1"},
                                   {"default (asleep between regions)", "HM_BENCH=1"},
                                   {"spinning (OMP_WAIT_POLICY=active)", "OMP_WAIT_POLICY=active"}};
  std::printf(
      "Fig. 12 quick case, b = 0.2, N = %ld, to t* = 4.5e-3; %ld cores; median of %d runs per row, the\n"
      "modes interleaved (a shared machine's speed drifts)\n",
      n, sysconf(_SC_NPROCESSORS_ONLN), repeats);
  std::printf("%-8s %-34s %9s %14s   %s\n", "machine", "threads", "wall [s]", "/ one thread", "runs [s]");
  for (const bool busy : {false, true}) {
    pid_t loop = 0;
    if (busy) {
      loop = fork();
      if (loop == 0) {
        volatile unsigned long k = 0;
        for (;;) k = k + 1;
      }
    }
    std::vector<std::vector<double>> seconds(modes.size());
    for (int r = 0; r < repeats; ++r)
      for (std::size_t m = 0; m < modes.size(); ++m) seconds[m].push_back(timed_run(dir, modes[m].env));
    if (busy) {
      kill(loop, SIGKILL);
      waitpid(loop, nullptr, 0);
    }
    const auto median = [](std::vector<double> v) {
      std::sort(v.begin(), v.end());
      return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
    };
    const double one = median(seconds[0]);
    for (std::size_t m = 0; m < modes.size(); ++m) {
      std::string runs;
      for (double s : seconds[m]) {
        char run[16];
        std::snprintf(run, sizeof run, " %.2f", s);
        runs += run;
      }
      std::printf("%-8s %-34s %9.2f %14.2f  %s\n", busy ? "busy" : "idle", modes[m].name, median(seconds[m]),
                  median(seconds[m]) / one, runs.c_str());
    }
    std::fflush(stdout);
  }
  fs::remove_all(dir);
}
