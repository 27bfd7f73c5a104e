#include "hm/lattice2d/io/vtk_writer.hpp"

#include <bit>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <type_traits>

#include "hm/core/file_output.hpp"

namespace hm::lattice2d {

namespace fs = std::filesystem;

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

constexpr char base64_alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

// Standard base64 with '=' padding, appended to out.
void put_base64(std::ostream& out, const unsigned char* data, std::size_t size) {
  std::string text;
  text.reserve(4 * ((size + 2) / 3));
  for (std::size_t k = 0; k < size; k += 3) {
    const unsigned b0 = data[k], b1 = k + 1 < size ? data[k + 1] : 0u, b2 = k + 2 < size ? data[k + 2] : 0u;
    const unsigned triple = (b0 << 16) | (b1 << 8) | b2;
    text += base64_alphabet[(triple >> 18) & 63];
    text += base64_alphabet[(triple >> 12) & 63];
    text += k + 1 < size ? base64_alphabet[(triple >> 6) & 63] : '=';
    text += k + 2 < size ? base64_alphabet[triple & 63] : '=';
  }
  out << text;
}

// Writes DataArrays in the chosen format. T is the C++ type of the VTK type name given with it.
class ArrayWriter {
 public:
  ArrayWriter(std::ostream& out, VtkFormat format) : out_(out), format_(format) {}

  // One DataArray of n_tuples x n_components values value(k, c). Field data (no points or cells to
  // count them by) also states NumberOfTuples, as VTK's own writers do.
  template <typename T, typename Value>
  void array(const char* type, const std::string& name, int n_components, long n_tuples, Value value,
             bool field_data = false) {
    out_ << "        <DataArray type=\"" << type << "\" Name=\"" << xml_escape(name) << "\"";
    if (n_components > 1) out_ << " NumberOfComponents=\"" << n_components << "\"";
    if (field_data) out_ << " NumberOfTuples=\"" << n_tuples << "\"";
    if (format_ == VtkFormat::ascii) {
      out_ << " format=\"ascii\">\n";
      for (long k = 0; k < n_tuples; ++k) {
        out_ << "          ";
        for (int c = 0; c < n_components; ++c) {
          if (c) out_ << ' ';
          if constexpr (std::is_floating_point_v<T>)
            put(out_, static_cast<T>(value(k, c)));
          else
            out_ << static_cast<long long>(value(k, c));
        }
        out_ << '\n';
      }
    } else {
      // Inline binary: base64 of [UInt64 byte count][raw values], encoded as one stream (as meshio and
      // VTK's reader expect for uncompressed data).
      const std::size_t n_values = static_cast<std::size_t>(n_tuples) * static_cast<std::size_t>(n_components);
      const std::uint64_t n_bytes = n_values * sizeof(T);
      std::vector<unsigned char> buffer(sizeof n_bytes + n_bytes);
      std::memcpy(buffer.data(), &n_bytes, sizeof n_bytes);
      std::size_t at = sizeof n_bytes;
      for (long k = 0; k < n_tuples; ++k)
        for (int c = 0; c < n_components; ++c, at += sizeof(T)) {
          const T v = static_cast<T>(value(k, c));
          std::memcpy(buffer.data() + at, &v, sizeof(T));
        }
      out_ << " format=\"binary\">\n          ";
      put_base64(out_, buffer.data(), buffer.size());
      out_ << '\n';
    }
    out_ << "        </DataArray>\n";
  }

 private:
  std::ostream& out_;
  VtkFormat format_;
};

}  // namespace

void write_vtu(const fs::path& path, const Lattice& lattice, const DualGraph& dual, const LatticeSnapshot& s,
               VtkFormat format) {
  check_sizes(lattice, dual, s);
  const long n = lattice.n_particles(), n_beams = lattice.n_beams(), n_tri = lattice.n_triangles();
  const long n_cells = n_tri + n_beams;
  const auto state = [&](long e) -> int {
    return s.beam_states.empty() ? 0 : static_cast<int>(s.beam_states[static_cast<std::size_t>(e)]);
  };
  core::write_file_atomically(path, [&](std::ostream& out) {
    ArrayWriter w(out, format);
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\""
        << (std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian")
        << "\" header_type=\"UInt64\">\n"
           "  <UnstructuredGrid>\n"
           "    <FieldData>\n";
    w.array<double>(
        "Float64", "TimeValue", 1, 1, [&](long, int) { return s.time; }, true);
    out << "    </FieldData>\n"
        << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << n_cells << "\">\n"
        << "      <PointData Vectors=\"displacement\" Tensors=\"stress\">\n";
    w.array<double>("Float64", "displacement", 3, n, [&](long i, int c) {
      return (c == 2 || s.displacement.size() == 0) ? 0.0 : s.displacement[3 * i + c];
    });
    w.array<double>("Float64", "rotation", 1, n,
                    [&](long i, int) { return s.displacement.size() == 0 ? 0.0 : s.displacement[3 * i + 2]; });
    w.array<double>("Float64", "stress", 9, n, [&](long i, int c) {
      if (s.particle_stress.cols() == 0) return 0.0;
      switch (c) {  // row-major 3 x 3: xx xy xz / yx yy yz / zx zy zz
        case 0: return s.particle_stress(0, i);
        case 4: return s.particle_stress(1, i);
        case 1:
        case 3: return s.particle_stress(2, i);
        default: return 0.0;
      }
    });
    w.array<double>("Float64", "particle_area", 1, n, [&](long i, int) { return dual.particle_area[i]; });
    w.array<std::int32_t>("Int32", "boundary", 1, n,
                          [&](long i, int) { return static_cast<int>(lattice.boundary[static_cast<std::size_t>(i)]); });
    for (const NamedField& f : s.particle_fields)
      w.array<double>("Float64", f.name, 1, n, [&](long i, int) { return f.values[i]; });
    out << "      </PointData>\n"
        << "      <CellData Scalars=\"cell_kind\">\n"
        << "        <!-- cell_kind: 0 flow triangle, 1 beam. state: -1 triangle, 0 intact beam, 1 broken beam in\n"
        << "             contact (normal spring), 2 broken beam open (no force). broken: -1 triangle, 0/1 beam. -->\n";
    w.array<std::int32_t>("Int32", "cell_kind", 1, n_cells, [&](long k, int) { return k < n_tri ? 0 : 1; });
    w.array<double>("Float64", "pressure", 1, n_cells,
                    [&](long k, int) { return (k < n_tri && s.pressure.size() != 0) ? s.pressure[k] : 0.0; });
    w.array<std::int32_t>("Int32", "state", 1, n_cells, [&](long k, int) { return k < n_tri ? -1 : state(k - n_tri); });
    w.array<std::int32_t>("Int32", "broken", 1, n_cells,
                          [&](long k, int) { return k < n_tri ? -1 : (state(k - n_tri) != 0 ? 1 : 0); });
    for (const NamedField& f : s.triangle_fields)
      w.array<double>("Float64", f.name, 1, n_cells, [&](long k, int) { return k < n_tri ? f.values[k] : 0.0; });
    for (const NamedField& f : s.beam_fields)
      w.array<double>("Float64", f.name, 1, n_cells,
                      [&](long k, int) { return k < n_tri ? 0.0 : f.values[k - n_tri]; });
    out << "      </CellData>\n"
        << "      <Points>\n";
    w.array<double>("Float64", "points", 3, n, [&](long i, int c) { return c == 2 ? 0.0 : lattice.points(c, i); });
    out << "      </Points>\n"
        << "      <Cells>\n";
    // Connectivity: 3 indices per triangle, then 2 per beam; offsets are the running ends.
    w.array<std::int64_t>("Int64", "connectivity", 1, 3 * n_tri + 2 * n_beams, [&](long k, int) -> long {
      if (k < 3 * n_tri) return lattice.triangles[static_cast<std::size_t>(k / 3)][static_cast<std::size_t>(k % 3)];
      const long b = k - 3 * n_tri;
      return lattice.beams[static_cast<std::size_t>(b / 2)][static_cast<std::size_t>(b % 2)];
    });
    w.array<std::int64_t>("Int64", "offsets", 1, n_cells, [&](long k, int) -> long {
      return k < n_tri ? 3 * (k + 1) : 3 * n_tri + 2 * (k - n_tri + 1);
    });
    w.array<std::uint8_t>("UInt8", "types", 1, n_cells, [&](long k, int) { return k < n_tri ? 5 : 3; });
    out << "      </Cells>\n"
        << "    </Piece>\n"
        << "  </UnstructuredGrid>\n"
        << "</VTKFile>\n";
  });
}

void write_pvd(const fs::path& path, const std::vector<PvdEntry>& entries) {
  core::write_file_atomically(path, [&](std::ostream& out) {
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

VtkSeries::VtkSeries(fs::path folder, std::string name, VtkFormat format, std::vector<PvdEntry> written)
    : folder_(std::move(folder)), name_(std::move(name)), format_(format), entries_(std::move(written)) {
  fs::create_directories(folder_);
}

fs::path VtkSeries::write(const Lattice& lattice, const DualGraph& dual, const LatticeSnapshot& snapshot) {
  char index[16];
  std::snprintf(index, sizeof index, "_%04zu.vtu", entries_.size());
  const std::string file = name_ + index;
  write_vtu(folder_ / file, lattice, dual, snapshot, format_);
  entries_.push_back({snapshot.time, file});
  write_pvd(pvd_path(), entries_);
  return folder_ / file;
}

}  // namespace hm::lattice2d
