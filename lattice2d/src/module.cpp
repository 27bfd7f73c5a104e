// Anchor translation unit: keeps the library non-empty while the module grows.
namespace hm::lattice2d {
const char* module_name() { return "lattice2d"; }
}  // namespace hm::lattice2d
