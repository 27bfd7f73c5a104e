// See checkpoint.hpp.
#include "hm/case/checkpoint.hpp"

#include <fstream>
#include <iterator>

#include <boost/crc.hpp>

#include "hm/case/provenance.hpp"
#include "hm/core/file_output.hpp"
#include "hm/core/input_error.hpp"

namespace hm::cases {

namespace {

// What must be equal for a continuation to be bitwise: the binary (version, commit, build type).
std::string build_identity() {
  const Provenance p = make_provenance("");
  return p.version + " " + p.git_commit + " " + p.build_type;
}

std::string crc_of(const std::string& text) {
  boost::crc_32_type crc;
  crc.process_bytes(text.data(), text.size());
  char hex[9];
  std::snprintf(hex, sizeof hex, "%08x", crc.checksum());
  return hex;
}

}  // namespace

void write_checkpoint(const std::filesystem::path& dir, const std::string& case_text,
                      const hm::lattice2d::CoupledModel& model, RunRecorder& recorder) {
  // Streamed to the file: the state is as large as the model's factors, and a copy of it in memory
  // would be most of a large run's peak memory.
  core::write_file_atomically(dir / checkpoint_file_name, [&](std::ostream& out) {
    core::StateWriter w(out);
    w.put("build", build_identity());
    w.put("case", case_text);
    model.save_state(w);
    recorder.save_state(w);
    w.finish();
  });
}

core::StateReader read_checkpoint(const std::filesystem::path& dir, const std::string& case_text,
                                  hm::lattice2d::CoupledModel& model) {
  const std::filesystem::path path = dir / checkpoint_file_name;
  // Only a regular file: a pipe or a link to a device would be read forever (or block).
  std::error_code ec;
  const std::filesystem::file_type type = std::filesystem::status(path, ec).type();
  if (type != std::filesystem::file_type::regular && type != std::filesystem::file_type::not_found)
    throw InputError("'" + path.string() + "' is not a regular file (" +
                     (type == std::filesystem::file_type::directory ? std::string("a folder")
                                                                    : std::string("a device, pipe or socket")) +
                     "); allowed: the checkpoint file the run wrote");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("'" + path.string() + "' cannot be read: the run wrote no checkpoint before it stopped");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::string source = path.string();  // quoted by insert: GCC 12's -Wrestrict misfires on "'" + s + "'"
  source.insert(source.begin(), '\'');
  source.push_back('\'');
  core::StateReader r(std::move(bytes), std::move(source));
  std::string build, stored_case;
  r.get("build", build);
  if (build != build_identity())
    throw InputError(r.source() + " was written by hmlattice " + core::echo(build) + ", allowed: the same build (" +
                     build_identity() + "); rerun from its config.toml instead");
  r.get("case", stored_case);
  if (stored_case != case_text)
    throw InputError(r.source() + " is of another case (checksum " + crc_of(stored_case) + ", config.toml's " +
                     crc_of(case_text) + "): config.toml was changed; allowed: the case the run started with");
  model.restore_state(r);
  return r;
}

}  // namespace hm::cases
