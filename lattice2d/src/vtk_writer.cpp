#include "hm/lattice2d/vtk_writer.hpp"

#include <charconv>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <type_traits>

namespace hm::lattice2d {

namespace fs = std::filesystem;

void write_file_atomically(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  fs::path partial = path;
  partial += ".partial";
  try {
    {
      std::ofstream out(partial, std::ios::binary | std::ios::trunc);
      if (!out) throw std::runtime_error("cannot open '" + partial.string() + "' for writing");
      write(out);
      out.close();
      if (!out) throw std::runtime_error("writing '" + partial.string() + "' failed (disk full?)");
    }
    fs::rename(partial, path);
  } catch (...) {
    std::error_code ec;  // best effort: the original error is the one to report
    fs::remove(partial, ec);
    throw;
  }
}

namespace {

// Names and file names go into XML attributes.
std::string xml_escape(const std::string& text) {
  std::string out;
  for (char ch : text) {
    switch (ch) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += ch;
    }
  }
  return out;
}

// Shortest round-trip form: exact and compact (VTK's ASCII reader parses it with >>).
void put(std::ostream& out, double value) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
  out.write(buf, end - buf);
}

constexpr const char* reserved_names[] = {"displacement", "rotation", "stress", "particle_area", "boundary",
                                          "cell_kind",    "pressure", "state",  "broken"};

void check_fields(const std::vector<NamedField>& fields, long size, const char* what) {
  for (const NamedField& f : fields) {
    if (f.name.empty()) throw std::invalid_argument(std::string("write_vtu: empty name in ") + what);
    for (const char* r : reserved_names)
      if (f.name == r) throw std::invalid_argument("write_vtu: " + f.name + " is a reserved array name");
    if (f.values.size() != size)
      throw std::invalid_argument("write_vtu: " + std::string(what) + " '" + f.name + "' has " +
                                  std::to_string(f.values.size()) + " values, expected " + std::to_string(size));
  }
}

void check_sizes(const Lattice& lattice, const DualGraph& dual, const LatticeSnapshot& s) {
  const long n = lattice.n_particles(), n_beams = lattice.n_beams(), n_tri = lattice.n_triangles();
  const auto require = [](bool ok, const std::string& message) {
    if (!ok) throw std::invalid_argument("write_vtu: " + message);
  };
  require(dual.particle_area.size() == n, "dual graph has a different particle count");
  require(s.displacement.size() == 0 || s.displacement.size() == 3 * n, "displacement size != 3 n_particles");
  require(s.particle_stress.cols() == 0 || s.particle_stress.cols() == n, "particle_stress columns != n_particles");
  require(s.beam_states.empty() || static_cast<long>(s.beam_states.size()) == n_beams, "beam_states size != n_beams");
  require(s.pressure.size() == 0 || s.pressure.size() == n_tri, "pressure size != n_triangles");
  check_fields(s.particle_fields, n, "particle field");
  check_fields(s.beam_fields, n_beams, "beam field");
  check_fields(s.triangle_fields, n_tri, "triangle field");
}

// One DataArray with values produced by value(k, c) for tuple k and component c.
// Field data (no points or cells to count them by) also states NumberOfTuples, as VTK's own writers do.
template <typename Value>
void data_array(std::ostream& out, const char* type, const std::string& name, int n_components, long n_tuples,
                Value value, bool field_data = false) {
  out << "        <DataArray type=\"" << type << "\" Name=\"" << xml_escape(name) << "\"";
  if (n_components > 1) out << " NumberOfComponents=\"" << n_components << "\"";
  if (field_data) out << " NumberOfTuples=\"" << n_tuples << "\"";
  out << " format=\"ascii\">\n";
  for (long k = 0; k < n_tuples; ++k) {
    out << "          ";
    for (int c = 0; c < n_components; ++c) {
      if (c) out << ' ';
      if constexpr (std::is_integral_v<decltype(value(k, c))>) out << value(k, c);
      else put(out, value(k, c));
    }
    out << '\n';
  }
  out << "        </DataArray>\n";
}

}  // namespace

void write_vtu(const fs::path& path, const Lattice& lattice, const DualGraph& dual, const LatticeSnapshot& s) {
  check_sizes(lattice, dual, s);
  const long n = lattice.n_particles(), n_beams = lattice.n_beams(), n_tri = lattice.n_triangles();
  const long n_cells = n_tri + n_beams;
  const auto state = [&](long e) -> int {
    return s.beam_states.empty() ? 0 : static_cast<int>(s.beam_states[static_cast<std::size_t>(e)]);
  };
  write_file_atomically(path, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
           "  <UnstructuredGrid>\n"
           "    <FieldData>\n";
    data_array(out, "Float64", "TimeValue", 1, 1, [&](long, int) { return s.time; }, true);
    out << "    </FieldData>\n"
        << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << n_cells << "\">\n"
        << "      <PointData Vectors=\"displacement\" Tensors=\"stress\">\n";
    data_array(out, "Float64", "displacement", 3, n, [&](long i, int c) {
      return (c == 2 || s.displacement.size() == 0) ? 0.0 : s.displacement[3 * i + c];
    });
    data_array(out, "Float64", "rotation", 1, n,
               [&](long i, int) { return s.displacement.size() == 0 ? 0.0 : s.displacement[3 * i + 2]; });
    data_array(out, "Float64", "stress", 9, n, [&](long i, int c) {
      if (s.particle_stress.cols() == 0) return 0.0;
      switch (c) {  // row-major 3 x 3: xx xy xz / yx yy yz / zx zy zz
        case 0: return s.particle_stress(0, i);
        case 4: return s.particle_stress(1, i);
        case 1: case 3: return s.particle_stress(2, i);
        default: return 0.0;
      }
    });
    data_array(out, "Float64", "particle_area", 1, n, [&](long i, int) { return dual.particle_area[i]; });
    data_array(out, "Int32", "boundary", 1, n,
               [&](long i, int) { return static_cast<int>(lattice.boundary[static_cast<std::size_t>(i)]); });
    for (const NamedField& f : s.particle_fields)
      data_array(out, "Float64", f.name, 1, n, [&](long i, int) { return f.values[i]; });
    out << "      </PointData>\n"
        << "      <CellData Scalars=\"cell_kind\">\n";
    data_array(out, "Int32", "cell_kind", 1, n_cells, [&](long k, int) { return k < n_tri ? 0 : 1; });
    data_array(out, "Float64", "pressure", 1, n_cells,
               [&](long k, int) { return (k < n_tri && s.pressure.size() != 0) ? s.pressure[k] : 0.0; });
    data_array(out, "Int32", "state", 1, n_cells, [&](long k, int) { return k < n_tri ? -1 : state(k - n_tri); });
    data_array(out, "Int32", "broken", 1, n_cells,
               [&](long k, int) { return k < n_tri ? -1 : (state(k - n_tri) != 0 ? 1 : 0); });
    for (const NamedField& f : s.triangle_fields)
      data_array(out, "Float64", f.name, 1, n_cells, [&](long k, int) { return k < n_tri ? f.values[k] : 0.0; });
    for (const NamedField& f : s.beam_fields)
      data_array(out, "Float64", f.name, 1, n_cells,
                 [&](long k, int) { return k < n_tri ? 0.0 : f.values[k - n_tri]; });
    out << "      </CellData>\n"
        << "      <Points>\n";
    data_array(out, "Float64", "points", 3, n,
               [&](long i, int c) { return c == 2 ? 0.0 : lattice.points(c, i); });
    out << "      </Points>\n"
        << "      <Cells>\n";
    // Connectivity: 3 indices per triangle, then 2 per beam; offsets are the running ends.
    out << "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (const auto& t : lattice.triangles) out << "          " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    for (const auto& b : lattice.beams) out << "          " << b[0] << ' ' << b[1] << '\n';
    out << "        </DataArray>\n";
    data_array(out, "Int64", "offsets", 1, n_cells,
               [&](long k, int) -> long { return k < n_tri ? 3 * (k + 1) : 3 * n_tri + 2 * (k - n_tri + 1); });
    data_array(out, "UInt8", "types", 1, n_cells, [&](long k, int) { return k < n_tri ? 5 : 3; });
    out << "      </Cells>\n"
        << "    </Piece>\n"
        << "  </UnstructuredGrid>\n"
        << "</VTKFile>\n";
  });
}

void write_pvd(const fs::path& path, const std::vector<PvdEntry>& entries) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "  <Collection>\n";
    for (const PvdEntry& e : entries) {
      out << "    <DataSet timestep=\"";
      put(out, e.time);
      out << "\" group=\"\" part=\"0\" file=\"" << xml_escape(e.file) << "\"/>\n";
    }
    out << "  </Collection>\n"
           "</VTKFile>\n";
  });
}

VtkSeries::VtkSeries(fs::path folder, std::string name) : folder_(std::move(folder)), name_(std::move(name)) {
  fs::create_directories(folder_);
}

fs::path VtkSeries::write(const Lattice& lattice, const DualGraph& dual, const LatticeSnapshot& snapshot) {
  char index[16];
  std::snprintf(index, sizeof index, "_%04zu.vtu", entries_.size());
  const std::string file = name_ + index;
  write_vtu(folder_ / file, lattice, dual, snapshot);
  entries_.push_back({snapshot.time, file});
  write_pvd(pvd_path(), entries_);
  return folder_ / file;
}

}  // namespace hm::lattice2d
