// Reading Wavefront OBJ meshes: positions, normals, UVs and fan-triangulated polygons.
#include "scene/obj_mesh.hpp"

#include "scene/mesh_closure.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace crt::scene {

namespace {

/// Splits off the next whitespace-separated token of `rest`.
std::string_view nextToken(std::string_view& rest) {
    size_t start = rest.find_first_not_of(" \t\r\f\v");
    if (start == std::string_view::npos) {
        rest = {};
        return {};
    }
    size_t end = rest.find_first_of(" \t\r\f\v", start);
    if (end == std::string_view::npos) end = rest.size();
    std::string_view token = rest.substr(start, end - start);
    rest.remove_prefix(end);
    return token;
}

bool parseNumber(std::string_view token, double& value) {
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    return ec == std::errc() && end == token.data() + token.size() && std::isfinite(value);
}

bool parseIndex(std::string_view token, long& value) {
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    return ec == std::errc() && end == token.data() + token.size();
}

/// Triangles index their corners with int32_t: no list may be longer than this.
constexpr uint64_t kIndexLimit = uint64_t{1} << 31;

class Parser {
  public:
    Parser(std::string_view text, uint64_t maxSize, ObjError& error)
        : text_(text), maxSize_(std::min(maxSize, kIndexLimit)), error_(error) {}

    bool line(std::string_view text, uint32_t lineNumber);
    MeshData mesh;
    size_t statements = 0; ///< lines that start with an OBJ keyword
    size_t otherLines = 0; ///< lines with something else, which are skipped

  private:
    /// Fails with a message about `where`, a part of the current line.
    bool fail(std::string_view where, std::string message) {
        error_.message = std::move(message);
        error_.line = line_;
        error_.begin = size_t(where.data() - text_.data());
        error_.end = error_.begin + where.size();
        return false;
    }
    /// Room for one more element in a list of `size`.
    bool room(std::string_view where, size_t size, const char* what);
    /// Reads `count` numbers (at least `required`), ignoring any beyond `count`.
    bool numbers(std::string_view rest, double* out, int required, int count);
    /// Resolves a 1-based (or negative, relative) index into a vector of `size` elements.
    bool index(std::string_view token, size_t size, const char* what, int32_t& out);
    bool face(std::string_view rest);

    std::string_view text_;
    uint64_t maxSize_;
    ObjError& error_;
    std::string_view lineText_;
    uint32_t line_ = 0;
};

bool Parser::room(std::string_view where, size_t size, const char* what) {
    if (size < maxSize_) return true;
    error_.overLimit = true;
    return fail(where, fmt::format("more than {} {}", maxSize_, what));
}

bool Parser::numbers(std::string_view rest, double* out, int required, int count) {
    for (int i = 0; i < count; ++i) {
        std::string_view token = nextToken(rest);
        if (token.empty()) {
            if (i < required)
                return fail(lineText_, fmt::format("expected {} numbers, found {}", required, i));
            out[i] = 0;
            continue;
        }
        if (!parseNumber(token, out[i])) return fail(token, fmt::format("bad number '{}'", token));
    }
    return true;
}

bool Parser::index(std::string_view token, size_t size, const char* what, int32_t& out) {
    long value = 0;
    if (!parseIndex(token, value))
        return fail(token, fmt::format("bad {} index '{}'", what, token));
    long resolved = value > 0 ? value - 1 : long(size) + value;
    if (value == 0 || resolved < 0 || resolved >= long(size))
        return fail(token,
                    fmt::format("{} index {} out of range ({} defined)", what, value, size));
    out = int32_t(resolved);
    return true;
}

bool Parser::face(std::string_view rest) {
    struct Corner {
        int32_t v = -1, uv = -1, n = -1;
    };
    std::vector<Corner> corners;
    for (std::string_view token = nextToken(rest); !token.empty(); token = nextToken(rest)) {
        Corner c;
        size_t slash1 = token.find('/');
        std::string_view vPart = token.substr(0, slash1);
        if (!index(vPart, mesh.positions.size(), "vertex", c.v)) return false;
        if (slash1 != std::string_view::npos) {
            std::string_view after = token.substr(slash1 + 1);
            size_t slash2 = after.find('/');
            std::string_view uvPart = after.substr(0, slash2);
            if (!uvPart.empty() && !index(uvPart, mesh.uvs.size(), "texture coordinate", c.uv))
                return false;
            if (slash2 != std::string_view::npos &&
                !index(after.substr(slash2 + 1), mesh.normals.size(), "normal", c.n))
                return false;
        }
        corners.push_back(c);
    }
    if (corners.size() < 3)
        return fail(lineText_,
                    fmt::format("face with {} vertices (at least 3 needed)", corners.size()));
    if (!room(lineText_, mesh.triangles.size() + corners.size() - 3, "triangles")) return false;
    for (size_t i = 1; i + 1 < corners.size(); ++i) {
        const Corner* fan[3] = {&corners[0], &corners[i], &corners[i + 1]};
        MeshData::Triangle tri;
        for (int k = 0; k < 3; ++k) {
            tri.v[k] = fan[k]->v;
            tri.n[k] = fan[k]->n;
            tri.uv[k] = fan[k]->uv;
        }
        mesh.triangles.push_back(tri);
    }
    return true;
}

bool Parser::line(std::string_view text, uint32_t lineNumber) {
    line_ = lineNumber;
    if (size_t hash = text.find('#'); hash != std::string_view::npos) text = text.substr(0, hash);
    constexpr std::string_view kBlank = " \t\r\f\v";
    text.remove_prefix(std::min(text.size(), text.find_first_not_of(kBlank)));
    text.remove_suffix(text.size() - std::min(text.size(), text.find_last_not_of(kBlank) + 1));
    lineText_ = text;
    std::string_view rest = text;
    std::string_view keyword = nextToken(rest);
    double xyz[3];
    if (keyword == "v" || keyword == "vn" || keyword == "vt") ++statements;
    if (keyword == "v") {
        if (!room(text, mesh.positions.size(), "vertices") || !numbers(rest, xyz, 3, 3))
            return false;
        mesh.positions.emplace_back(xyz[0], xyz[1], xyz[2]);
    } else if (keyword == "vn") {
        if (!room(text, mesh.normals.size(), "normals") || !numbers(rest, xyz, 3, 3))
            return false;
        mesh.normals.emplace_back(xyz[0], xyz[1], xyz[2]);
    } else if (keyword == "vt") {
        if (!room(text, mesh.uvs.size(), "texture coordinates") || !numbers(rest, xyz, 1, 2))
            return false;
        mesh.uvs.emplace_back(xyz[0], xyz[1]);
    } else if (keyword == "f") {
        ++statements;
        return face(rest);
    }
    // o, g, s, usemtl, mtllib and others: not geometry we use. A file of nothing but unknown
    // lines is another kind of file, named as a mesh by mistake.
    static constexpr std::string_view kOtherKeywords[] = {"o", "g", "s", "usemtl", "mtllib",
                                                          "l", "p", "vp"};
    if (keyword.empty()) return true;
    if (std::find(std::begin(kOtherKeywords), std::end(kOtherKeywords), keyword) !=
        std::end(kOtherKeywords))
        ++statements;
    else
        ++otherLines;
    return true;
}

} // namespace

uint64_t MeshData::byteSize() const {
    return sizeof(MeshData) + positions.capacity() * sizeof(glm::dvec3) +
           normals.capacity() * sizeof(glm::dvec3) + uvs.capacity() * sizeof(glm::dvec2) +
           triangles.capacity() * sizeof(Triangle);
}

std::string ObjError::describe(const std::string& name) const {
    if (line == 0) return fmt::format("{}: {}", name, message);
    return fmt::format("{}:{}: {}", name, line, message);
}

std::optional<MeshData> parseObj(std::string_view text, uint64_t maxSize, ObjError& error) {
    // Any file can be named as a mesh; one that is not text, or has no face, is not an OBJ
    // mesh, and saying so beats drawing nothing.
    error = ObjError{};
    if (text.find('\0') != std::string_view::npos) {
        error.message = "not a Wavefront OBJ mesh (it holds binary data)";
        return std::nullopt;
    }
    Parser parser(text, maxSize, error);
    uint32_t lineNumber = 0;
    for (std::string_view rest = text; !rest.empty();) {
        size_t end = rest.find('\n');
        std::string_view line = rest.substr(0, end);
        rest = end == std::string_view::npos ? std::string_view{} : rest.substr(end + 1);
        if (!parser.line(line, ++lineNumber)) return std::nullopt;
    }
    if (parser.statements == 0 && parser.otherLines > 0) {
        error.message = "not a Wavefront OBJ mesh (no line of it is an OBJ statement)";
        return std::nullopt;
    }
    markClosure(parser.mesh);
    return std::move(parser.mesh);
}

std::optional<MeshData> readObj(const std::string& path, uint64_t maxSize, std::string& error) {
    std::error_code ec;
    std::ifstream in;
    if (std::filesystem::is_regular_file(path, ec)) in.open(path, std::ios::binary);
    std::string text;
    if (in) text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (!in.is_open() || in.bad()) {
        error = fmt::format("cannot read '{}'", path);
        return std::nullopt;
    }
    ObjError problem;
    std::optional<MeshData> mesh = parseObj(text, maxSize, problem);
    if (!mesh) error = problem.describe(path);
    return mesh;
}

} // namespace crt::scene
