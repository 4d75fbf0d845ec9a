// The meshes a script names, read while it is evaluated: a bad file is an error of the script
// (at its `file ->` attribute; for OBJ with a note at the file's line), so `crtc --check` and
// the language server report it, and the renderer draws the data that was checked. And the
// meshes a script writes, vertices and faces (POV-Ray's mesh2), checked the same way.
#include "interpreter_impl.hpp"
#include "object_builder.hpp"

#include "scene/mesh_closure.hpp"
#include "scene/mesh_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace crt::lang {

namespace {

/// The error of a mesh file that cannot be read: "bad mesh 'NAME': why", and the option that
/// raises the limit when the mesh is over it.
std::string badMesh(const ObjectBuilder& b, std::string_view why, bool overLimit) {
    return fmt::format("bad mesh '{}': {}{}", b.text("file", ""), why,
                       overLimit ? "; raise the limit with --max-mesh-size" : "");
}

} // namespace

scene::Shape Interpreter::meshShape(ObjectBuilder& b) {
    scene::MeshShape s;
    s.file = b.text("file", s.file);
    auto given = [&](std::string_view name) { return b.get(name) && !b.get(name)->list->empty(); };
    const bool written = given("vertices") || given("faces");
    if (written && !s.file.empty()) fail(b.where("vertices"), "a Mesh takes a file or vertices and faces, not both");
    if (!written && s.file.empty())
        fail(b.typeRange, "a Mesh needs a file, or vertices and faces");
    if (written) {
        scene_.writtenMeshes.push_back(writtenMesh(b));
        s.written = static_cast<int32_t>(scene_.writtenMeshes.size() - 1);
        return s;
    }
    s.resolvedFile = findFile(b, "file", "mesh");
    if (!s.resolvedFile.empty()) readMesh(b, s.resolvedFile);
    return s;
}

std::shared_ptr<const scene::MeshData> Interpreter::writtenMesh(ObjectBuilder& b) {
    auto list = [&](std::string_view name) -> const std::vector<Value>& {
        static const std::vector<Value> kNone;
        const Value* v = b.get(name);
        return v ? *v->list : kNone;
    };
    const std::vector<Value>& vertices = list("vertices");
    const std::vector<Value>& faces = list("faces");
    const std::vector<Value>& normals = list("normals");
    const std::vector<Value>& uvs = list("uvs");
    for (auto [name, count] : {std::pair{"vertices", vertices.size()}, {"faces", faces.size()},
                               {"normals", normals.size()}, {"uvs", uvs.size()}}) {
        if (count > options_.limits.maxMeshSize)
            fail(b.where(name), fmt::format("a Mesh of more than {} {}; raise the limit with --max-mesh-size",
                                            options_.limits.maxMeshSize, name));
    }
    if (faces.empty()) fail(b.where("vertices"), "a Mesh with vertices needs faces too");
    for (auto [name, count] : {std::pair{"normals", normals.size()}, {"uvs", uvs.size()}}) {
        if (count != 0 && count != vertices.size())
            fail(b.where(name), fmt::format("a Mesh has one of its {} at each vertex: {}, not {}", name,
                                            vertices.size(), count));
    }
    auto mesh = std::make_shared<scene::MeshData>();
    auto point = [](const Value& v) { return glm::dvec3(v.v[0], v.v[1], v.v[2]); };
    for (const Value& v : vertices) mesh->positions.push_back(point(v));
    // Each of unit length, as POV-Ray makes them: only their directions are blended.
    for (const Value& n : normals) {
        const double length = glm::length(point(n));
        mesh->normals.push_back(length > 0 ? point(n) / length : point(n));
    }
    for (size_t i = 0; i < uvs.size(); ++i) {
        if (uvs[i].v[2] != 0) fail(b.whereItem("uvs", i), fmt::format("uv {} is not in the u-v plane: its z is not 0", i + 1));
        mesh->uvs.emplace_back(uvs[i].v[0], uvs[i].v[1]);
    }
    for (size_t i = 0; i < faces.size(); ++i) {
        scene::MeshData::Triangle t{};
        for (int k = 0; k < 3; ++k) {
            const int64_t corner = (*faces[i].list)[k].i;
            if (corner >= static_cast<int64_t>(vertices.size()))
                fail(b.whereItem("faces", i), fmt::format("face {} names vertex {}, but the Mesh has {} (numbered from 0)",
                                                          i + 1, corner, vertices.size()));
            t.v[k] = static_cast<int32_t>(corner);
            t.n[k] = normals.empty() ? -1 : t.v[k];
            t.uv[k] = uvs.empty() ? -1 : t.v[k];
        }
        mesh->triangles.push_back(t);
    }
    scene::markClosure(*mesh);
    charge(mesh->byteSize());
    storeTriangles(*mesh, b.where("faces"));
    return mesh;
}

void Interpreter::storeTriangles(const scene::MeshData& mesh, SourceRange where) {
    meshTriangles_ = scene::saturatingAdd(meshTriangles_, mesh.triangles.size());
    const uint64_t limit = options_.limits.render.maxPrimitives;
    if (meshTriangles_ > limit) {
        failAtLimit(where, fmt::format("the scene stores more than {} primitives with the {} "
                                       "triangles of this mesh (stored once however often it is "
                                       "drawn); raise the limit with --max-primitives",
                                       limit, mesh.triangles.size()));
    }
}

void Interpreter::readMesh(const ObjectBuilder& b, const std::string& path) {
    if (scene_.meshes.contains(path)) return;
    std::error_code error;
    const uintmax_t fileSize = std::filesystem::file_size(path, error);
    if (!error) checkRoom(fileSize); // the file is held while it is read
    scene::MeshData mesh =
        scene::isAssimpMeshFile(path) ? readAssimpMesh(b, path) : readObjMesh(b, path);
    charge(mesh.byteSize());
    storeTriangles(mesh, b.where("file"));
    scene_.meshes.emplace(path, std::make_shared<const scene::MeshData>(std::move(mesh)));
}

scene::MeshData Interpreter::readObjMesh(const ObjectBuilder& b, const std::string& path) {
    const SourceRange where = b.where("file");
    std::optional<std::string> text = readFile(path);
    if (!text) fail(where, fmt::format("cannot read mesh '{}': {}", path, std::strerror(errno)));
    scene::ObjError problem;
    std::optional<scene::MeshData> mesh = parseObj(*text, options_.limits.maxMeshSize, problem);
    if (!mesh) {
        Diagnostic& d =
            diagnostics_.error(where, badMesh(b, problem.message, problem.overLimit));
        // The file's line is shown as a note when the file can be a source (a text under 4 GiB).
        if (problem.line != 0 && problem.end <= std::numeric_limits<uint32_t>::max()) {
            const uint32_t file = compilation_.sources.add(path, std::move(*text));
            d.notes.push_back({{file, uint32_t(problem.begin), uint32_t(problem.end)},
                               fmt::format("line {} of the mesh", problem.line)});
        }
        throw EvalError{};
    }
    return std::move(*mesh);
}

scene::MeshData Interpreter::readAssimpMesh(const ObjectBuilder& b, const std::string& path) {
    // A glTF's buffers are read as the mesh is: where the script may read.
    const scene::FileGate gate = [&](const std::string& file) {
        const FileCheck check = fileAccess().check(file);
        return check.refused() ? check.reason : std::string();
    };
    scene::MeshFileError problem;
    std::optional<scene::MeshData> mesh =
        scene::readAssimpMesh(path, options_.limits.maxMeshSize, gate, problem);
    if (!mesh) {
        fail(b.where("file"), badMesh(b, problem.message, problem.overLimit));
    }
    return std::move(*mesh);
}

const scene::MeshData* Interpreter::meshDataOf(const scene::MeshShape& mesh) const {
    if (mesh.written >= 0) return scene_.writtenMeshes[static_cast<size_t>(mesh.written)].get();
    auto found = scene_.meshes.find(mesh.resolvedFile);
    return found == scene_.meshes.end() ? nullptr : found->second.get();
}

std::string Interpreter::openMeshReason(uint32_t entity) const {
    const scene::Shape* shape = &scene_.entities[entity].shape;
    while (auto* moved = std::get_if<scene::TransformNode>(shape))
        shape = &scene_.entities[static_cast<size_t>(moved->child)].shape;
    const auto* mesh = std::get_if<scene::MeshShape>(shape);
    const scene::MeshData* data = mesh ? meshDataOf(*mesh) : nullptr;
    if (!data || data->closed) return {};
    const scene::MeshClosure closure = scene::meshClosure(*data);
    if (closure.edgeFrom < 0) return fmt::format("it {}", closure.problem);
    auto corner = [&](int32_t v) {
        const glm::dvec3& p = data->positions[static_cast<size_t>(v)];
        return fmt::format("vertex {} ({:g}, {:g}, {:g})", v, p.x, p.y, p.z);
    };
    return fmt::format("its edge from {} to {} {}", corner(closure.edgeFrom),
                       corner(closure.edgeTo), closure.problem);
}

} // namespace crt::lang
