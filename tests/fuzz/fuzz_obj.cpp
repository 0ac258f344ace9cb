// libFuzzer target: OBJ and MTL loading with rasterlab's validation. The
// input is OBJ text, optionally followed by a NUL byte and MTL text. A file is
// refused with a MeshError or loaded into a mesh whose every index is in
// range and every value finite; anything else is a finding.
// Run: build-fuzz/tests/fuzz/fuzz_obj tests/fuzz/corpus/obj
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "rasterlab/mesh.hpp"

namespace {

bool finite(rl::vec3 v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void check(const rl::Mesh& mesh) {
    for (const rl::vec3& p : mesh.positions)
        if (!finite(p)) std::abort();
    for (const rl::vec3& n : mesh.normals)
        if (!finite(n)) std::abort();
    for (const rl::vec2& t : mesh.uvs)
        if (!std::isfinite(t.x) || !std::isfinite(t.y)) std::abort();
    for (const rl::Face& t : mesh.faces) {
        for (const rl::Corner& c : t.corners) {
            if (c.position < 0 || c.position >= static_cast<int>(mesh.positions.size()))
                std::abort();
            if (c.uv < -1 || c.uv >= static_cast<int>(mesh.uvs.size())) std::abort();
            if (c.normal < -1 || c.normal >= static_cast<int>(mesh.normals.size())) std::abort();
        }
        if (t.material < -1 || t.material >= static_cast<int>(mesh.materials.size())) std::abort();
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    const std::size_t split = input.find('\0');
    const std::string_view obj = input.substr(0, split);
    const std::string_view mtl = split == std::string_view::npos ? "" : input.substr(split + 1);
    try {
        check(rl::parse_obj(obj, mtl, "fuzz.obj"));
    } catch (const rl::MeshError&) {
    }
    return 0;
}
