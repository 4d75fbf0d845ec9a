// The meshes a script names, read while it is evaluated: a bad OBJ file is an error of the
// script (at its `file ->` attribute, with a note at the file's line), so `crtc --check` and
// the language server report it, and the renderer draws the data that was checked.
#include "interpreter_impl.hpp"
#include "object_builder.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace crt::lang {

void Interpreter::readMesh(const ObjectBuilder& b, const std::string& path) {
    if (scene_.meshes.contains(path)) return;
    const SourceRange where = b.where("file");
    std::error_code error;
    const uintmax_t fileSize = std::filesystem::file_size(path, error);
    if (!error) checkRoom(fileSize); // the text is held while it is parsed
    std::optional<std::string> text = readFile(path);
    if (!text) fail(where, fmt::format("cannot read mesh '{}': {}", path, std::strerror(errno)));

    scene::ObjError problem;
    std::optional<scene::MeshData> mesh = parseObj(*text, options_.limits.maxMeshSize, problem);
    if (!mesh) {
        std::string message = fmt::format("bad mesh '{}': {}", b.text("file", ""), problem.message);
        if (problem.overLimit) message += "; raise the limit with --max-mesh-size";
        Diagnostic& d = diagnostics_.error(where, std::move(message));
        // The file's line is shown as a note when the file can be a source (a text under 4 GiB).
        if (problem.line != 0 && problem.end <= std::numeric_limits<uint32_t>::max()) {
            const uint32_t file = compilation_.sources.add(path, std::move(*text));
            d.notes.push_back({{file, uint32_t(problem.begin), uint32_t(problem.end)},
                               fmt::format("line {} of the mesh", problem.line)});
        }
        throw EvalError{};
    }
    charge(mesh->byteSize());
    scene_.meshes.emplace(path, std::make_shared<const scene::MeshData>(std::move(*mesh)));
}

} // namespace crt::lang
