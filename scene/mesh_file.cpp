// Mesh files of every format crt reads (see mesh_file.hpp).
#include "scene/mesh_file.hpp"

#include "scene/assimp_guard.hpp"
#include "scene/child_process.hpp"
#include "scene/mesh_bytes.hpp"
#include "scene/mesh_closure.hpp"

#include <assimp/BaseImporter.h>
#include <assimp/DefaultIOSystem.h>
#include <assimp/Importer.hpp>
#include <assimp/importerdesc.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fmt/format.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <vector>

namespace crt::scene {

namespace {

std::string lowerExtension(std::string_view path) {
    const size_t dot = path.find_last_of('.');
    const size_t slash = path.find_last_of('/');
    if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash))
        return {};
    std::string extension(path.substr(dot + 1));
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

/// Assimp's own file system, asking the gate before it opens any file but the mesh itself;
/// remembers why it refused, for the error.
class GatedFiles : public Assimp::DefaultIOSystem {
  public:
    GatedFiles(const std::string& mesh, FileGate gate)
        : mesh_(std::filesystem::path(mesh).lexically_normal().string()), gate_(std::move(gate)) {}

    bool Exists(const char* file) const override {
        return allowed(file) && DefaultIOSystem::Exists(file);
    }
    Assimp::IOStream* Open(const char* file, const char* mode) override {
        if (std::strchr(mode, 'w') || std::strchr(mode, 'a') || !allowed(file)) return nullptr;
        return DefaultIOSystem::Open(file, mode);
    }
    const std::string& refusal() const { return refusal_; }

  private:
    bool allowed(const char* file) const {
        // Assimp joins folders as it likes ("a//b"): the gate sees the plain path.
        const std::string path = std::filesystem::path(file).lexically_normal().string();
        if (path == mesh_ || !gate_) return true;
        std::string why = gate_(path);
        if (why.empty()) return true;
        refusal_ = fmt::format("'{}' {}", path, why);
        return false;
    }

    std::string mesh_;
    FileGate gate_;
    mutable std::string refusal_;
};

/// An importer of the three formats only: Assimp would otherwise try every other reader it
/// has on a file whose extension's reader refuses it.
std::unique_ptr<Assimp::Importer> meshImporter() {
    auto importer = std::make_unique<Assimp::Importer>();
    std::vector<Assimp::BaseImporter*> others;
    for (size_t i = 0; i < importer->GetImporterCount(); ++i) {
        const std::string_view name = importer->GetImporterInfo(i)->mName;
        const bool wanted = name.starts_with("Stanford Polygon Library") ||
                            name.starts_with("Stereolithography") || name == "glTF2 Importer";
        if (!wanted) others.push_back(importer->GetImporter(i));
    }
    for (Assimp::BaseImporter* other : others) {
        importer->UnregisterLoader(other); // which hands it back to be deleted
        delete other;
    }
    return importer;
}

/// Only the check of Assimp's own data: its other steps (triangulation, transforms) assert on
/// damaged files, and Debian's Assimp aborts the process on a failed assertion.
constexpr unsigned kSteps = aiProcess_ValidateDataStructure;

/// One mesh of an imported scene where a node places it.
struct Placed {
    const aiMesh* mesh;
    aiMatrix4x4 toScene;
};

/// Every mesh the scene's nodes place, each with the transforms from the root down to it.
std::vector<Placed> placedMeshes(const aiScene& imported) {
    std::vector<Placed> out;
    std::vector<std::pair<const aiNode*, aiMatrix4x4>> pending;
    if (imported.mRootNode)
        pending.emplace_back(imported.mRootNode, imported.mRootNode->mTransformation);
    while (!pending.empty()) {
        const auto [node, toScene] = pending.back();
        pending.pop_back();
        for (unsigned i = 0; i < node->mNumMeshes; ++i)
            if (node->mMeshes[i] < imported.mNumMeshes)
                out.push_back({imported.mMeshes[node->mMeshes[i]], toScene});
        for (unsigned i = 0; i < node->mNumChildren; ++i)
            pending.emplace_back(node->mChildren[i], toScene * node->mChildren[i]->mTransformation);
    }
    return out;
}

/// Appends one placed mesh: positions moved, normals turned (unless `withNormals` is false),
/// polygons fan-triangulated, points and lines left out.
void appendPlaced(const Placed& placed, bool withNormals, MeshData& out) {
    const aiMesh& mesh = *placed.mesh;
    const auto base = static_cast<int32_t>(out.positions.size());
    const bool normals = withNormals && mesh.HasNormals(), uvs = mesh.HasTextureCoords(0);
    const auto normalBase = static_cast<int32_t>(out.normals.size());
    const auto uvBase = static_cast<int32_t>(out.uvs.size());
    const aiMatrix3x3 turn = aiMatrix3x3(placed.toScene).Inverse().Transpose();
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
        const aiVector3D p = placed.toScene * mesh.mVertices[v];
        out.positions.emplace_back(p.x, p.y, p.z);
        if (normals) {
            const aiVector3D turned = turn * mesh.mNormals[v];
            const glm::dvec3 n(turned.x, turned.y, turned.z);
            out.normals.push_back(glm::length(n) > 0 ? glm::normalize(n) : n);
        }
        if (uvs) out.uvs.emplace_back(mesh.mTextureCoords[0][v].x, mesh.mTextureCoords[0][v].y);
    }
    auto corner = [&](unsigned index, MeshData::Triangle& t, int k) {
        const auto i = static_cast<int32_t>(index);
        t.v[k] = base + i;
        t.n[k] = normals ? normalBase + i : -1;
        t.uv[k] = uvs ? uvBase + i : -1;
    };
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace& face = mesh.mFaces[f];
        for (unsigned k = 2; k < face.mNumIndices; ++k) {
            MeshData::Triangle t{};
            corner(face.mIndices[0], t, 0);
            corner(face.mIndices[k - 1], t, 1);
            corner(face.mIndices[k], t, 2);
            out.triangles.push_back(t);
        }
    }
}

/// Makes triangles that meet at a position share its vertex, as the other formats do: an STL
/// file stores three corners of its own for each triangle (and nothing else at them).
void joinCorners(MeshData& mesh) {
    const std::vector<int32_t> first = firstVertexAtPosition(mesh.positions);
    // The first vertex at each position stays, the others go; numbers close up.
    std::vector<int32_t> kept(first.size());
    std::vector<glm::dvec3> positions;
    for (size_t i = 0; i < first.size(); ++i) {
        if (first[i] != static_cast<int32_t>(i)) continue;
        kept[i] = static_cast<int32_t>(positions.size());
        positions.push_back(mesh.positions[i]);
    }
    for (MeshData::Triangle& t : mesh.triangles)
        for (int32_t& v : t.v) v = kept[static_cast<size_t>(first[static_cast<size_t>(v)])];
    mesh.positions = std::move(positions);
}

/// The triangles of every mesh the imported scene places, within the limit. An STL file's
/// facet normals are the triangles' own (where the file has them right), so they are dropped.
std::optional<MeshData> meshOf(const aiScene* imported, std::string_view extension,
                               uint64_t maxSize, MeshFileError& error) {
    const std::vector<Placed> placed = placedMeshes(*imported);
    uint64_t vertices = 0, triangles = 0;
    for (const Placed& p : placed) {
        vertices += p.mesh->mNumVertices;
        for (unsigned f = 0; f < p.mesh->mNumFaces; ++f) {
            const aiFace& face = p.mesh->mFaces[f];
            triangles += face.mNumIndices > 2 ? face.mNumIndices - 2 : 0;
            for (unsigned k = 0; k < face.mNumIndices; ++k) {
                if (face.mIndices[k] >= p.mesh->mNumVertices) {
                    error = {fmt::format("a face names vertex {} of a mesh of {}", face.mIndices[k],
                                         p.mesh->mNumVertices)};
                    return std::nullopt;
                }
            }
        }
    }
    const uint64_t limit = std::min<uint64_t>(maxSize, std::numeric_limits<int32_t>::max());
    if (vertices > limit || triangles > limit) {
        error = {fmt::format("more than {} {}", limit, vertices > limit ? "vertices" : "triangles"),
                 true};
        return std::nullopt;
    }
    if (triangles == 0) {
        error = {"no triangles"};
        return std::nullopt;
    }
    MeshData out;
    out.positions.reserve(vertices);
    out.triangles.reserve(triangles);
    const bool stl = extension == "stl";
    for (const Placed& p : placed) appendPlaced(p, !stl, out);
    if (stl) joinCorners(out);
    markClosure(out);
    return out;
}

std::optional<MeshData> importedMesh(Assimp::Importer& importer, const aiScene* imported,
                                     std::string_view extension, uint64_t maxSize,
                                     MeshFileError& error) {
    if (!imported) {
        error = {importer.GetErrorString()};
        if (error.message.empty()) error.message = "not a mesh Assimp can read";
        return std::nullopt;
    }
    return meshOf(imported, extension, maxSize, error);
}

} // namespace

bool isAssimpMeshFile(std::string_view path) {
    const std::string extension = lowerExtension(path);
    return extension == "ply" || extension == "stl" || extension == "gltf" || extension == "glb";
}

namespace {

/// readAssimpMesh in this process.
std::optional<MeshData> importFile(const std::string& path, uint64_t maxSize, const FileGate& gate,
                                   MeshFileError& error) {
    std::ifstream in(path, std::ios::binary);
    std::error_code failed;
    const uintmax_t size = std::filesystem::file_size(path, failed);
    if (!in || failed) {
        error = {fmt::format("cannot read it: {}", failed ? failed.message() : "cannot open it")};
        return std::nullopt;
    }
    const ByteReader read = [&](uint64_t offset, void* to, size_t n) {
        in.clear();
        in.seekg(static_cast<std::streamoff>(offset));
        in.read(static_cast<char*>(to), static_cast<std::streamsize>(n));
        return in.gcount() == static_cast<std::streamsize>(n);
    };
    if (std::string problem = assimpGuardProblem(lowerExtension(path), read, size);
        !problem.empty()) {
        error = {std::move(problem)};
        return std::nullopt;
    }
    std::unique_ptr<Assimp::Importer> importer = meshImporter();
    auto* files = new GatedFiles(path, gate); // the importer owns its file system
    importer->SetIOHandler(files);
    const aiScene* imported = importer->ReadFile(path, kSteps);
    std::optional<MeshData> mesh =
        importedMesh(*importer, imported, lowerExtension(path), maxSize, error);
    if (!mesh && !files->refusal().empty())
        error.message = fmt::format("{}; {}", error.message, files->refusal());
    return mesh;
}

} // namespace

std::optional<MeshData> readAssimpMesh(const std::string& path, uint64_t maxSize,
                                       const FileGate& gate, MeshFileError& error) {
    // In a child process: fuzzing found Assimp 5.2 writing through a stale pointer on some
    // damaged file, and aborting on failed assertions, which no check before it can rule out.
    std::string why;
    const std::optional<std::string> bytes = inChildProcess(
        [&] {
            MeshFileError problem;
            std::optional<MeshData> mesh = importFile(path, maxSize, gate, problem);
            return meshToBytes(mesh, problem);
        },
        meshBytesBound(maxSize), why);
    if (!bytes) {
        error = {fmt::format("Assimp could not read it: {}", why)};
        return std::nullopt;
    }
    return meshFromBytes(*bytes, error);
}

std::optional<MeshData> parseAssimpMesh(std::span<const uint8_t> bytes, std::string_view extension,
                                        uint64_t maxSize, MeshFileError& error) {
    const ByteReader read = [&](uint64_t offset, void* to, size_t n) {
        if (offset > bytes.size() || n > bytes.size() - offset) return false;
        std::memcpy(to, bytes.data() + offset, n);
        return true;
    };
    if (std::string problem = assimpGuardProblem(extension, read, bytes.size()); !problem.empty()) {
        error = {std::move(problem)};
        return std::nullopt;
    }
    std::unique_ptr<Assimp::Importer> importer = meshImporter();
    // Beside the bytes, a refusal of every file.
    importer->SetIOHandler(new GatedFiles("", [](const std::string&) { return "is not read"; }));
    const std::string hint(extension);
    const aiScene* imported =
        importer->ReadFileFromMemory(bytes.data(), bytes.size(), kSteps, hint.c_str());
    return importedMesh(*importer, imported, hint, maxSize, error);
}

std::optional<MeshData> readMeshFile(const std::string& path, uint64_t maxSize, std::string& error,
                                     const FileGate& gate) {
    if (!isAssimpMeshFile(path)) return readObj(path, maxSize, error);
    MeshFileError problem;
    std::optional<MeshData> mesh = readAssimpMesh(path, maxSize, gate, problem);
    if (!mesh) error = fmt::format("{}: {}", path, problem.message);
    return mesh;
}

} // namespace crt::scene
