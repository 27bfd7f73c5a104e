// Damaged checkpoints whose checksum still matches: every value of a stopped run's checkpoint.bin is
// changed in turn (an element set to -1, 0, a huge value, NaN or, for integers, 7; one element dropped
// or added), the CRC recomputed, and the run resumed. Each must end as a run (exit 0), a numerical failure
// (exit 1) or a refused input (exit 2, one line), never a crash, a signal or a hang, and the run
// folder stays. The seed is fixed; a failure prints the value and the change.
#include <catch2/catch.hpp>

#include <boost/crc.hpp>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "run_command.hpp"

using hm::test::count_lines;
using hm::test::run_hmlattice;
using hm::test::slurp;
using hm::test::TempDir;

namespace fs = std::filesystem;

namespace {

// One tagged value of the state archive (core/state_archive.cpp: [u16 tag length][tag][kind][u64
// count][count elements], after a header line; a CRC-32 of everything before it ends the file).
struct Record {
  std::string tag;
  char kind = 0;
  std::uint64_t count = 0;
  std::string data;
};

constexpr std::string_view header = "hmlattice state, format 1\n";

std::size_t element_size(char kind) { return kind == 'c' ? 1 : kind == 'i' ? 4 : 8; }

std::vector<Record> parse(const std::string& bytes) {
  REQUIRE(bytes.compare(0, header.size(), header) == 0);
  std::vector<Record> out;
  std::size_t at = header.size();
  const std::size_t end = bytes.size() - 4;
  while (at < end) {
    Record r;
    std::uint16_t length = 0;
    std::memcpy(&length, bytes.data() + at, 2);
    r.tag = bytes.substr(at + 2, length);
    at += 2 + length;
    r.kind = bytes[at++];
    std::memcpy(&r.count, bytes.data() + at, 8);
    at += 8;
    r.data = bytes.substr(at, r.count * element_size(r.kind));
    at += r.data.size();
    out.push_back(r);
  }
  REQUIRE(at == end);
  return out;
}

std::string serialise(const std::vector<Record>& records) {
  std::string out(header);
  for (const Record& r : records) {
    const auto length = static_cast<std::uint16_t>(r.tag.size());
    out.append(reinterpret_cast<const char*>(&length), 2);
    out += r.tag;
    out += r.kind;
    out.append(reinterpret_cast<const char*>(&r.count), 8);
    out += r.data;
  }
  boost::crc_32_type crc;
  crc.process_bytes(out.data(), out.size());
  const std::uint32_t sum = crc.checksum();
  out.append(reinterpret_cast<const char*>(&sum), 4);
  return out;
}

// `r` with one change picked by `rng`; `what` describes it.
Record mutated(Record r, std::mt19937& rng, std::string& what) {
  const std::size_t size = element_size(r.kind);
  const auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
  const std::size_t change = r.count == 0 ? 1 : pick(r.kind == 'd' ? 6 : 7);
  if (change == 0) {
    r.data.resize(r.data.size() - size);
    --r.count;
    what = "last element dropped";
    return r;
  }
  if (change == 1) {
    const std::size_t n = r.data.size();  // the last element repeated (zeros for an empty value)
    r.data.resize(n + size, '\0');
    if (n >= size) std::memcpy(r.data.data() + n, r.data.data() + n - size, size);
    ++r.count;
    what = "an element added";
    return r;
  }
  const std::size_t k = pick(r.count);
  char* at = r.data.data() + k * size;
  // A real keeps its structure whatever its value; a plausible wrong one (7) would only make another,
  // bounded, computation (a pressure load of 7 E R breaks beams for minutes before failing), so reals get
  // the absurd values and integers all five.
  const int value = static_cast<int>(change) - 2;  // 0 .. 4 (0 .. 3 for reals)
  what = "element " + std::to_string(k);           // one append at a time: GCC 12's -Wrestrict misfires on a + chain
  what += ", change ";
  what += std::to_string(value);
  if (r.kind == 'd') {
    const double v[] = {-1.0, 0.0, 1e300, std::numeric_limits<double>::quiet_NaN(), 7.0};
    std::memcpy(at, &v[value], 8);
  } else if (r.kind == 'l') {
    const std::int64_t v[] = {-1, 0, std::int64_t{1} << 40, std::numeric_limits<std::int64_t>::max(), 7};
    std::memcpy(at, &v[value], 8);
  } else if (r.kind == 'i') {
    const std::int32_t v[] = {-1, 0, 1 << 30, std::numeric_limits<std::int32_t>::max(), 7};
    std::memcpy(at, &v[value], 4);
  } else {
    const char v[] = {'\xff', '\0', '\x7f', '\x02', '7'};
    *at = v[value];
  }
  return r;
}

// A run of `case_text` stopped after `steps` steps (breaks logged), whose checkpoint each mutant
// replaces in a copy of the folder; `tags` chooses the records to change (empty: every one but the
// build and the case, which are compared as wholes).
void fuzz_checkpoint(const std::string& name, const std::string& case_text, int steps,
                     const std::vector<std::string>& tag_prefixes, int mutants_per_record, unsigned seed) {
  TempDir dir(name);
  dir.write("case.toml", case_text);
  const auto stopped = run_hmlattice("run case.toml --out part --stop-after-steps " + std::to_string(steps), dir.path);
  REQUIRE(stopped.exit_code == 0);
  REQUIRE(count_lines(slurp(dir.path / "part/breaks.csv")) > 1);  // the state holds breaks
  const std::vector<Record> records = parse(slurp(dir.path / "part/checkpoint.bin"));
  std::mt19937 rng(seed);
  int n_runs = 0, n_refused = 0;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const std::string& tag = records[i].tag;
    if (tag == "build" || tag == "case") continue;
    bool chosen = tag_prefixes.empty();
    for (const auto& prefix : tag_prefixes) chosen = chosen || tag.rfind(prefix, 0) == 0;
    if (!chosen) continue;
    for (int m = 0; m < mutants_per_record; ++m) {
      std::vector<Record> changed = records;
      std::string what;
      changed[i] = mutated(records[i], rng, what);
      fs::remove_all(dir.path / "m");
      fs::copy(dir.path / "part", dir.path / "m", fs::copy_options::recursive);
      std::ofstream(dir.path / "m/checkpoint.bin", std::ios::binary | std::ios::trunc) << serialise(changed);
      // A hang is a failure too: 60 s of CPU is ~50x what the rest of the run takes.
      const auto r = run_hmlattice("run --resume m", dir.path, "ulimit -t 60; ");
      INFO("'" << tag << "', " << what << ": exit " << r.exit_code << ", stderr: " << r.err);
      CHECK((r.exit_code == 0 || ((r.exit_code == 1 || r.exit_code == 2) && count_lines(r.err) == 1)));
      CHECK(fs::exists(dir.path / "m/config.toml"));
      ++n_runs;
      n_refused += r.exit_code == 2;
    }
  }
  // The checks must have met the mutants: most changes of sizes and indices are refused.
  CHECK(n_runs >= 20);
  CHECK(n_refused >= n_runs / 4);
}

// The annulus case of only the required keys with fracture on (N = 1000): stopped after 30 steps,
// 25 beams are broken, so the break log, the contact states and a downdated factor are in the state.
const std::string brittle_case =
    "model = \"lattice2d\"\n[physics]\nQ = 0.01\nb = 0.2\n[lattice]\ndomain = \"annulus\"\nn_particles = 1000\n"
    "[numerics]\nt_end = 0.004\n[fracture]\nenabled = true\n";

}  // namespace

TEST_CASE("A checkpoint damaged in any value, its checksum recomputed, is resumed or refused, never crashes",
          "[verification][cli][fuzz]") {
  fuzz_checkpoint("fuzz-checkpoint", brittle_case, 30, {}, 1, 20261205);
}

TEST_CASE("A saw-tooth run's damaged checkpoint (tooth counters and log) is resumed or refused, never crashes",
          "[verification][cli][fuzz]") {
  const std::string sawtooth_case = hm::test::edited(
      brittle_case, {{"enabled = true\n", "enabled = true\nlaw = \"sawtooth\"\nfracture_energy = 2e-9\n"}});
  fuzz_checkpoint("fuzz-checkpoint-sawtooth", sawtooth_case, 30,
                  {"sawtooth.", "teeth.", "mechanics.softening", "mechanics.closed"}, 5, 7);
}
