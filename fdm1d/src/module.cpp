// Anchor translation unit: keeps the library non-empty while the module grows.
namespace hm::fdm1d {
const char* module_name() { return "fdm1d"; }
}  // namespace hm::fdm1d
