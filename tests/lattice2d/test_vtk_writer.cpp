#include <catch2/catch.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "hm/lattice2d/geometry/dual_graph.hpp"
#include "hm/lattice2d/geometry/lattice.hpp"
#include "hm/lattice2d/io/vtk_writer.hpp"

using namespace hm::lattice2d;
namespace fs = std::filesystem;

namespace {

struct TempFolder {
  fs::path path;
  explicit TempFolder(const std::string& name)
      : path(fs::temp_directory_path() / ("hm-test-" + name + "-" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempFolder() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

// Runs `python script args` and returns its output as key = value pairs (one "key value..." per line).
std::map<std::string, std::string> run_python(const fs::path& script, const std::string& args) {
  const std::string command = std::string(HM_PYTHON) + " " + script.string() + " " + args + " 2>&1";
  std::map<std::string, std::string> out;
  FILE* pipe = ::popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  std::string text;
  std::array<char, 4096> buf{};
  while (std::fgets(buf.data(), static_cast<int>(buf.size()), pipe)) text += buf.data();
  const int status = ::pclose(pipe);
  INFO("python output:\n" << text);
  REQUIRE(status == 0);
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const auto space = line.find(' ');
    if (space != std::string::npos) out[line.substr(0, space)] = line.substr(space + 1);
  }
  return out;
}

std::vector<double> numbers(const std::string& text) {
  std::istringstream in(text);
  std::vector<double> v;
  for (double x; in >> x;) v.push_back(x);
  return v;
}

// meshio reads the .vtu; prints counts and a few values with repr (exact round trip of doubles).
constexpr const char* read_vtu_script = R"(import sys
import meshio
import numpy as np
m = meshio.read(sys.argv[1])
p = int(sys.argv[2]); t = int(sys.argv[3]); b = int(sys.argv[4])
blocks = [c.type for c in m.cells]
print("blocks", " ".join(blocks))
print("n_points", len(m.points))
for kind in ("triangle", "line"):
    print("n_" + kind, sum(len(c.data) for c in m.cells if c.type == kind))
tri = blocks.index("triangle"); line = blocks.index("line")
print("triangle_vertices", " ".join(str(v) for v in m.cells[tri].data[t]))
print("beam_vertices", " ".join(str(v) for v in m.cells[line].data[b]))
print("point", " ".join(repr(float(x)) for x in m.points[p]))
print("displacement", " ".join(repr(float(x)) for x in m.point_data["displacement"][p]))
print("rotation", repr(float(m.point_data["rotation"][p])))
print("stress", " ".join(repr(float(x)) for x in np.ravel(m.point_data["stress"][p])))
print("particle_area", repr(float(m.point_data["particle_area"][p])))
print("boundary", int(m.point_data["boundary"][p]))
print("pressure", repr(float(m.cell_data["pressure"][tri][t])), repr(float(m.cell_data["pressure"][line][b])))
print("state", int(m.cell_data["state"][tri][t]), int(m.cell_data["state"][line][b]))
print("broken", int(m.cell_data["broken"][tri][t]), int(m.cell_data["broken"][line][b]))
print("cell_kind", int(m.cell_data["cell_kind"][tri][t]), int(m.cell_data["cell_kind"][line][b]))
print("failure_ratio", repr(float(m.cell_data["failure_ratio"][line][b])))
print("time", repr(float(np.ravel(m.field_data["TimeValue"])[0])))
)";

// The .pvd parsed as XML: its datasets in order, and whether each file exists.
constexpr const char* read_pvd_script = R"(import os, sys
import xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
assert root.tag == "VTKFile" and root.get("type") == "Collection", root.tag
sets = root.find("Collection").findall("DataSet")
print("n", len(sets))
for k, d in enumerate(sets):
    f = d.get("file")
    print("set%d" % k, d.get("timestep"), f, int(os.path.isfile(os.path.join(os.path.dirname(sys.argv[1]), f))))
)";

}  // namespace

TEST_CASE("A snapshot written as .vtu reads back with meshio: the .pvd lists the series", "[lattice2d]") {
  LatticeSpec spec;
  spec.domain = DomainShape::rectangle;
  spec.n_particles = 500;
  const Lattice lattice = generate_lattice(spec);
  const DualGraph dual = build_dual_graph(lattice);
  const int n = lattice.n_particles();

  LatticeSnapshot snap;
  snap.time = 0.125;
  snap.displacement.resize(3 * n);
  snap.particle_stress.resize(3, n);
  for (int i = 0; i < n; ++i) {
    snap.displacement.segment<3>(3 * i) << 0.1 * lattice.points(0, i), -0.05 * lattice.points(1, i) + 1.0 / 3.0,
        1e-3 * i;
    snap.particle_stress.col(i) << 1e-4 * i, -2e-4, std::sqrt(2.0) * 1e-5;
  }
  snap.beam_states.assign(static_cast<std::size_t>(lattice.n_beams()), BeamState::intact);
  snap.beam_states[11] = BeamState::open;
  snap.beam_states[12] = BeamState::contact;
  snap.pressure = Eigen::VectorXd::LinSpaced(lattice.n_triangles(), 0.0, 1e-3);
  snap.beam_fields.push_back({"failure_ratio", Eigen::VectorXd::LinSpaced(lattice.n_beams(), 0.0, 2.0)});

  const VtkFormat format = GENERATE(VtkFormat::binary, VtkFormat::ascii);
  INFO("format " << (format == VtkFormat::binary ? "binary" : "ascii"));
  const TempFolder folder("vtk");
  VtkSeries series(folder.path / "out", "run", format);
  const fs::path first = series.write(lattice, dual, snap);
  snap.time = 0.25;
  const fs::path second = series.write(lattice, dual, snap);
  CHECK(first.filename() == "run_0000.vtu");
  CHECK(second.filename() == "run_0001.vtu");
  CHECK(fs::exists(series.pvd_path()));
  for (const auto& entry : fs::directory_iterator(folder.path / "out"))
    CHECK(entry.path().extension() != ".partial");  // temp + rename: no leftovers

  if (std::string(HM_PYTHON).empty()) {
    WARN("HM_PYTHON is empty (no python3 found by CMake): meshio read-back skipped; run scripts/install-deps.sh");
    return;
  }
  std::ofstream(folder.path / "read_vtu.py") << read_vtu_script;
  std::ofstream(folder.path / "read_pvd.py") << read_pvd_script;

  const int p = 7, t = 4, b = 12;
  const auto vtu = run_python(folder.path / "read_vtu.py", second.string() + " " + std::to_string(p) + " " +
                                                               std::to_string(t) + " " + std::to_string(b));
  // Counts and cell order: all triangles, then all beams.
  CHECK(vtu.at("blocks") == "triangle line");
  CHECK(std::stoi(vtu.at("n_points")) == n);
  CHECK(std::stoi(vtu.at("n_triangle")) == lattice.n_triangles());
  CHECK(std::stoi(vtu.at("n_line")) == lattice.n_beams());
  const auto tv = numbers(vtu.at("triangle_vertices")), bv = numbers(vtu.at("beam_vertices"));
  for (int k = 0; k < 3; ++k)
    CHECK(tv[static_cast<std::size_t>(k)] == lattice.triangles[t][static_cast<std::size_t>(k)]);
  CHECK(bv[0] == lattice.beams[b][0]);
  CHECK(bv[1] == lattice.beams[b][1]);
  // Values: raw bytes (binary) or shortest round-trip text (ascii), so doubles come back bitwise.
  const auto x = numbers(vtu.at("point")), u = numbers(vtu.at("displacement")), s = numbers(vtu.at("stress"));
  CHECK(x[0] == lattice.points(0, p));
  CHECK(x[1] == lattice.points(1, p));
  CHECK(x[2] == 0.0);
  CHECK(u[0] == snap.displacement[3 * p]);
  CHECK(u[1] == snap.displacement[3 * p + 1]);
  CHECK(u[2] == 0.0);
  CHECK(std::stod(vtu.at("rotation")) == snap.displacement[3 * p + 2]);
  REQUIRE(s.size() == 9);
  CHECK(s[0] == snap.particle_stress(0, p));
  CHECK(s[4] == snap.particle_stress(1, p));
  CHECK(s[1] == snap.particle_stress(2, p));
  CHECK(s[3] == snap.particle_stress(2, p));
  CHECK(s[8] == 0.0);
  CHECK(std::stod(vtu.at("particle_area")) == dual.particle_area[p]);
  CHECK(std::stoi(vtu.at("boundary")) == static_cast<int>(lattice.boundary[p]));
  CHECK(numbers(vtu.at("pressure")) == std::vector<double>{snap.pressure[t], 0.0});
  CHECK(numbers(vtu.at("state")) == std::vector<double>{-1.0, 1.0});  // triangle: n/a; beam 12: contact
  CHECK(numbers(vtu.at("broken")) == std::vector<double>{-1.0, 1.0});
  CHECK(numbers(vtu.at("cell_kind")) == std::vector<double>{0.0, 1.0});
  CHECK(std::stod(vtu.at("failure_ratio")) == snap.beam_fields[0].values[b]);
  CHECK(std::stod(vtu.at("time")) == 0.25);

  const auto pvd = run_python(folder.path / "read_pvd.py", series.pvd_path().string());
  CHECK(pvd.at("n") == "2");
  CHECK(pvd.at("set0") == "0.125 run_0000.vtu 1");
  CHECK(pvd.at("set1") == "0.25 run_0001.vtu 1");
}

TEST_CASE("The VTK writer rejects mismatched fields before writing anything", "[lattice2d]") {
  LatticeSpec spec;
  spec.domain = DomainShape::rectangle;
  spec.n_particles = 500;
  const Lattice lattice = generate_lattice(spec);
  const DualGraph dual = build_dual_graph(lattice);
  const TempFolder folder("vtk-bad");
  const fs::path path = folder.path / "bad.vtu";
  LatticeSnapshot snap;
  snap.pressure = Eigen::VectorXd::Zero(lattice.n_triangles() + 1);
  CHECK_THROWS_WITH(write_vtu(path, lattice, dual, snap), Catch::Contains("pressure"));
  snap = {};
  snap.beam_fields.push_back({"state", Eigen::VectorXd::Zero(lattice.n_beams())});
  CHECK_THROWS_WITH(write_vtu(path, lattice, dual, snap), Catch::Contains("reserved"));
  snap = {};
  snap.displacement = Eigen::VectorXd::Zero(2 * lattice.n_particles());
  CHECK_THROWS_AS(write_vtu(path, lattice, dual, snap), std::invalid_argument);
  CHECK(fs::is_empty(folder.path));
  // An unwritable place: std::runtime_error naming the path, no partial file.
  CHECK_THROWS_WITH(write_vtu(folder.path / "no" / "such.vtu", lattice, dual, LatticeSnapshot{}),
                    Catch::Contains("such.vtu"));
  CHECK(fs::is_empty(folder.path));
}
