// The checks a mesh file must pass before Assimp reads it (see assimp_guard.hpp).
#include "scene/assimp_guard.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <sstream>
#include <utility>
#include <vector>

namespace crt::scene {

namespace {

/// The bytes of one value of a PLY scalar type; 0 for a name PLY does not have.
int plyTypeSize(std::string_view type) {
    static constexpr std::pair<std::string_view, int> kSizes[] = {
        {"char", 1},  {"uchar", 1},   {"int8", 1},   {"uint8", 1},  {"short", 2}, {"ushort", 2},
        {"int16", 2}, {"uint16", 2},  {"int", 4},    {"uint", 4},   {"int32", 4}, {"uint32", 4},
        {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
    for (auto [name, size] : kSizes)
        if (name == type) return size;
    return 0;
}

} // namespace

std::string plyHeaderProblem(std::string_view head, uint64_t fileSize) {
    std::istringstream lines{std::string(head)};
    std::string line;
    if (!std::getline(lines, line) || (line != "ply" && line != "ply\r")) return "not a PLY file";
    bool text = true, ended = false;
    struct Element {
        std::string name;
        uint64_t count = 0, least = 0;
    };
    std::vector<Element> elements;
    size_t bodyStart = line.size() + 1;
    for (int number = 2; !ended && std::getline(lines, line); ++number) {
        bodyStart += line.size() + 1;
        std::istringstream words(line);
        std::string keyword, type, extra;
        words >> keyword;
        bool plain = true;
        if (keyword == "end_header") {
            ended = !(words >> extra);
            plain = ended;
        } else if (keyword == "format") {
            plain =
                static_cast<bool>(words >> type >> extra) &&
                (type == "ascii" || type == "binary_little_endian" || type == "binary_big_endian");
            text = type == "ascii";
        } else if (keyword == "element") {
            Element e;
            plain = static_cast<bool>(words >> e.name >> e.count) && !(words >> extra);
            elements.push_back(e);
        } else if (keyword == "property") {
            // "property TYPE NAME" or "property list COUNT_TYPE TYPE NAME", nothing after.
            std::string countType, name;
            words >> type;
            if (type == "list") words >> countType >> type;
            plain = static_cast<bool>(words >> name) && !(words >> extra) && !elements.empty() &&
                    plyTypeSize(type) > 0 && (countType.empty() || plyTypeSize(countType) > 0);
            // A list holds at least its count.
            const int bytes = plyTypeSize(countType.empty() ? type : countType);
            if (plain) elements.back().least += text ? 2 : static_cast<uint64_t>(bytes);
        } else {
            plain = keyword == "comment" || keyword == "obj_info";
        }
        if (!plain) return fmt::format("line {} of its PLY header is not one Assimp reads", number);
    }
    if (!ended) return "no end_header line in the first 64 KiB of the PLY file";
    const uint64_t body = fileSize > bodyStart ? fileSize - bodyStart : 0;
    uint64_t needed = 0;
    for (const Element& e : elements) {
        needed += std::min(e.count, body + 1) * std::max<uint64_t>(e.least, 1);
        if (e.count > body || needed > body) {
            return fmt::format("its header declares {} {} elements, more than its {} bytes of "
                               "data can hold",
                               e.count, e.name, body);
        }
    }
    return {};
}

std::string glbProblem(const ByteReader& read, uint64_t fileSize) {
    // Little-endian words: the magic "glTF", the version, the length; then chunks, each its
    // length and type before its data.
    auto word = [&](uint64_t offset, uint32_t& value) {
        uint8_t bytes[4];
        if (!read(offset, bytes, 4)) return false;
        value = uint32_t(bytes[0]) | uint32_t(bytes[1]) << 8 | uint32_t(bytes[2]) << 16 |
                uint32_t(bytes[3]) << 24;
        return true;
    };
    uint32_t magic = 0, version = 0, length = 0;
    if (!word(0, magic) || !word(4, version) || !word(8, length) || magic != 0x46546C67)
        return "not a GLB file";
    if (version != 2) return fmt::format("a GLB file of version {}, not 2", version);
    if (length != fileSize)
        return fmt::format("its header gives a length of {} bytes, but the file has {}", length,
                           fileSize);
    for (uint64_t at = 12; at < length;) {
        uint32_t chunk = 0;
        if (at + 8 > length || !word(at, chunk) || chunk > length - at - 8)
            return fmt::format("its chunk at byte {} runs past the end of the file", at);
        at += 8 + uint64_t(chunk);
    }
    return {};
}

std::string assimpGuardProblem(std::string_view extension, const ByteReader& read,
                               uint64_t fileSize) {
    if (extension == "glb") return glbProblem(read, fileSize);
    if (extension != "ply") return {};
    constexpr uint64_t kHeadBytes = 64 * 1024;
    std::string head(std::min(fileSize, kHeadBytes), '\0');
    if (!read(0, head.data(), head.size())) return "cannot read its header";
    return plyHeaderProblem(head, fileSize);
}

} // namespace crt::scene
