// libFuzzer target for the Wavefront OBJ reader: arbitrary bytes as an OBJ file's text.
#include "mesh_promise.hpp"

#include "scene/obj_mesh.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

namespace {

/// Small, so that the limit's refusal is reached too.
constexpr uint64_t kMaxSize = 4096;

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    crt::scene::ObjError error;
    std::optional<crt::scene::MeshData> mesh = crt::scene::parseObj(text, kMaxSize, error);
    if (!mesh) {
        // A rejected file always says why; a line's problem points at bytes of that line.
        if (error.message.empty() || error.begin > error.end || error.end > size) std::abort();
        if (error.line != 0 && text.substr(error.begin, error.end - error.begin).find('\n') !=
                                   std::string_view::npos)
            std::abort();
        return 0;
    }
    if (!crt::fuzz::keepsMeshPromise(*mesh, kMaxSize)) std::abort();
    return 0;
}
