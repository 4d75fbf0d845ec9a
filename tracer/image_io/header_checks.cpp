// Header checks before OpenImageIO opens a file (see header_checks.hpp).
#include "tracer/image_io/header_checks.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <utility>

namespace crt::tracer::image_io {

namespace {

// The little-endian 32-bit integer at `bytes`, signed or not.
long long littleEndian32(const unsigned char* bytes, bool isSigned = true) {
    const std::uint32_t bits = std::uint32_t(bytes[0]) | std::uint32_t(bytes[1]) << 8 |
                               std::uint32_t(bytes[2]) << 16 | std::uint32_t(bytes[3]) << 24;
    return isSigned ? (long long)std::int32_t(bits) : (long long)bits;
}

// The big-endian unsigned 32-bit integer at `bytes`.
long long bigEndian32(const unsigned char* bytes) {
    const unsigned char swapped[4] = {bytes[3], bytes[2], bytes[1], bytes[0]};
    return littleEndian32(swapped, false);
}

// Whether a PNG's chunks (a 4-byte big-endian length, a 4-byte type, the data and a 4-byte
// CRC each) all end within the file's `size` bytes.
bool pngChunksFit(std::FILE* file, long size) {
    for (long at = 8; at + 8 <= size;) {
        unsigned char header[8];
        if (std::fseek(file, at, SEEK_SET) != 0 || std::fread(header, 1, sizeof header, file) != sizeof header)
            return true; // OpenImageIO reports a read error itself
        const long long length = bigEndian32(header);
        if (length > size - at - 12) return false;
        at += 12 + length;
    }
    return true;
}

enum class NameRead { Read, End, TooLong };

// Reads bytes up to a NUL into `text`, as OpenEXR reads an attribute's name or type name: at
// most `maxLength` bytes and the NUL. End: the file ends first; TooLong: no NUL within them.
NameRead readName(std::FILE* file, std::size_t maxLength, std::string& text) {
    text.clear();
    for (int c; (c = std::fgetc(file)) != EOF;) {
        if (c == 0) return NameRead::Read;
        if (text.size() == maxLength) return NameRead::TooLong;
        text += char(c);
    }
    return NameRead::End;
}

// Reads a little-endian 32-bit integer, signed or not; false at the end of the file.
bool readInt32(std::FILE* file, long long& value, bool isSigned = true) {
    unsigned char bytes[4];
    if (std::fread(bytes, 1, sizeof bytes, file) != sizeof bytes) return false;
    value = littleEndian32(bytes, isSigned);
    return true;
}

// The width and height a BMP's header gives: 16-bit in the oldest header (12 bytes), 32-bit
// in the others, where a negative height means rows from the top.
std::pair<long long, long long> bmpSize(const unsigned char* head) {
    if (littleEndian32(head + 14) == 12) return {head[18] | head[19] << 8, head[20] | head[21] << 8};
    return {littleEndian32(head + 18), std::llabs(littleEndian32(head + 22))};
}

// The number of bytes OpenEXR reads for a value of `type` whatever size the file declares for
// it, or 0 for a type whose values it reads by their declared size (string, opaque …) or by
// their own layout (chlist, preview: checked apart).
long exrFixedSize(const std::string& type) {
    static const std::pair<const char*, long> sizes[] = {
        {"box2i", 16},   {"box2f", 16},          {"chromaticities", 32}, {"compression", 1},
        {"double", 8},   {"envmap", 1},          {"float", 4},           {"int", 4},
        {"keycode", 28}, {"lineOrder", 1},       {"m33f", 36},           {"m33d", 72},
        {"m44f", 64},    {"m44d", 128},          {"rational", 8},        {"tiledesc", 9},
        {"timecode", 8}, {"v2i", 8},             {"v2f", 8},             {"v2d", 16},
        {"v3i", 12},     {"v3f", 12},            {"v3d", 24},            {"deepImageState", 1}};
    for (const auto& [name, size] : sizes)
        if (type == name) return size;
    return 0;
}

// The sizes one OpenEXR header gives, as far as the checks need them.
struct ExrSizes {
    long long width = 0, height = 0;         // of the data window
    long long tileWidth = 0, tileHeight = 0; // of a tiled part's tiles
    int compression = 0;
};

// How many bytes of a channel list OpenEXR reads: entries of a name, its NUL and 16 bytes,
// up to an empty name. -1 when a name is longer than OpenEXR reads or the file ends first.
long exrChannelListLength(std::FILE* file, std::size_t maxLength) {
    long length = 0;
    std::string name;
    while (true) {
        if (readName(file, maxLength, name) != NameRead::Read) return -1;
        length += long(name.size()) + 1;
        if (name.empty()) return length;
        if (std::fseek(file, 16, SEEK_CUR) != 0) return -1;
        length += 16;
    }
}

// Why the value of one attribute (at the file's position, `length` bytes declared) cannot be
// trusted, or empty; learns the header's sizes on the way. OpenEXR reads a value of a known
// type by the type's own layout: were that not the declared size, it would go on reading the
// next attribute from somewhere else than the check does.
std::string exrValueRefusal(std::FILE* file, const std::string& name, const std::string& type, long length,
                            std::size_t maxLength, ExrSizes& sizes) {
    const std::string damaged = "damaged OpenEXR file: attribute '" + name + "' of type " + type;
    if (const long fixed = exrFixedSize(type); fixed != 0 && fixed != length)
        return damaged + " declares " + std::to_string(length) + " bytes, not " + std::to_string(fixed);
    long long a = 0, b = 0, c = 0, d = 0;
    if (type == "chlist") {
        if (exrChannelListLength(file, maxLength) != length) return damaged + " does not end where it says";
    } else if (type == "preview") {
        // Its width and height, then 4 bytes a pixel: OpenEXR reserves them before it reads.
        if (!readInt32(file, a, false) || !readInt32(file, b, false)) return {};
        const unsigned long long pixels = (unsigned long long)a * (unsigned long long)b; // < 2^64
        if (length < 8 || (length - 8) % 4 != 0 || pixels != (unsigned long long)(length - 8) / 4)
            return damaged + " does not end where it says";
    } else if (type == "box2i" && name == "dataWindow") {
        if (!readInt32(file, a) || !readInt32(file, b) || !readInt32(file, c) || !readInt32(file, d)) return {};
        sizes.width = c - a + 1;
        sizes.height = d - b + 1;
    } else if (type == "tiledesc" && name == "tiles") {
        if (!readInt32(file, a, false) || !readInt32(file, b, false)) return {};
        sizes.tileWidth = a;
        sizes.tileHeight = b;
    } else if (type == "compression" && name == "compression") {
        sizes.compression = std::fgetc(file);
    }
    return {};
}

// The lines of pixels OpenEXR decompresses at once with `compression` (NONE, RLE, ZIPS: 1;
// ZIP, PXR24: 16; PIZ, B44, B44A, DWAA: 32; DWAB: 256), whatever the image's height.
long long exrLinesAtOnce(int compression) {
    static constexpr long long lines[] = {1, 1, 1, 16, 32, 16, 32, 32, 32, 256};
    return compression >= 0 && compression < 10 ? lines[compression] : 1;
}

// Why an OpenEXR file's headers cannot be trusted, or empty. Each attribute is a name and a
// type name, each ending with a NUL byte, a 4-byte little-endian size, then the value; an
// empty name ends a header, and an empty header ends a multi-part file's. OpenEXR reserves
// the size before reading the value, and it reads a name longer than its limit (31 bytes, or
// 255 with the long-names flag) only up to that limit, going on from there as if the rest
// were the type name and the size. When it opens a file it reserves a line buffer as wide as
// the data window (and tiles as large as they say): those sizes go to the host's limit.
// Where the header is cut short, OpenEXR reports that itself.
std::string exrHeaderRefusal(std::FILE* file, long size, const unsigned char* head, const SizeCheck& accepts) {
    const bool longNames = (head[5] & 0x04) != 0, multipart = (head[5] & 0x10) != 0;
    const std::size_t maxLength = longNames ? 255 : 31;
    if (std::fseek(file, 8, SEEK_SET) != 0) return {};
    std::string name, type;
    while (true) {
        bool emptyHeader = true;
        ExrSizes sizes;
        while (true) {
            NameRead read = readName(file, maxLength, name);
            if (read == NameRead::Read && name.empty()) break;
            if (read == NameRead::Read) read = readName(file, maxLength, type);
            if (read == NameRead::TooLong) return "damaged OpenEXR file: an attribute's name is too long";
            emptyHeader = false;
            long long length = 0;
            if (read == NameRead::End || !readInt32(file, length)) return {};
            const long at = std::ftell(file);
            if (length < 0 || at < 0 || length > size - at)
                return "damaged OpenEXR file: a header attribute is longer than the file";
            if (std::string refusal = exrValueRefusal(file, name, type, long(length), maxLength, sizes);
                !refusal.empty())
                return refusal;
            if (std::fseek(file, at + long(length), SEEK_SET) != 0) return {};
        }
        if (!accepts(sizes.width, std::max(sizes.height, exrLinesAtOnce(sizes.compression))) ||
            !accepts(sizes.tileWidth, sizes.tileHeight))
            return kSizeRefused;
        if (!multipart || emptyHeader) return {};
    }
}

} // namespace

// Files OpenImageIO 2.4 cannot be trusted with, told by their bytes before it opens them
// (found by tests/fuzz/fuzz_image); the reason to refuse `path`, or empty.
// - PNG, DPX and OpenEXR: libpng reserves the length a chunk announces (up to 2 GiB), the DPX
//   reader the user data length the header announces, OpenEXR the size a header attribute
//   announces, before reading them; nothing limits any of them, so such a length beyond the
//   end of the file is refused first.
// - GIF, OpenEXR and BMP: their readers reserve memory for the size the header claims while
//   they open the file (GIF's the logical screen, OpenEXR's its line buffers, BMP's a
//   run-length image, decoded whole), so the host's limit on that size is asked first.
std::string refusedBeforeOpen(const char* path, const SizeCheck& accepts) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path, "rb"), std::fclose);
    if (!file) return {}; // OpenImageIO says why
    unsigned char head[36] = {};
    const std::size_t got = std::fread(head, 1, sizeof head, file.get());
    if (got < 10) return {};
    std::fseek(file.get(), 0, SEEK_END);
    const long size = std::ftell(file.get());
    if (std::memcmp(head, "\x89PNG\r\n\x1a\n", 8) == 0 && !pngChunksFit(file.get(), size))
        return "damaged PNG file: a chunk is longer than the file";
    // giflib takes a file for a GIF by its first 3 bytes, whatever version the next 3 say.
    if (std::memcmp(head, "GIF", 3) == 0 && !accepts(head[6] | head[7] << 8, head[8] | head[9] << 8))
        return kSizeRefused;
    if (std::memcmp(head, "BM", 2) == 0 && got >= 34) {
        const auto [width, height] = bmpSize(head);
        if (!accepts(width, height)) return kSizeRefused;
        // Run-length coding is of 8 or of 4 bits a pixel: OpenImageIO's reader decodes the
        // codes of either into rows of the bit count the header states, and read past their
        // end (a SIGSEGV) for RLE8 codes in a 24-bit image.
        const int bits = head[28] | head[29] << 8;
        const long long compression = littleEndian32(head + 30);
        if (littleEndian32(head + 14) >= 40 && ((compression == 1 && bits != 8) || (compression == 2 && bits != 4)))
            return "damaged BMP file: run-length coding of " + std::to_string(compression == 1 ? 8 : 4) +
                   "-bit pixels in an image of " + std::to_string(bits) + "-bit pixels";
    }
    // OpenEXR: the magic number, then a version byte and flags, 0x1000 for a multi-part file.
    if (std::memcmp(head, "\x76\x2f\x31\x01", 4) == 0) {
        if (std::string refusal = exrHeaderRefusal(file.get(), size, head, accepts); !refusal.empty())
            return refusal;
    }
    const bool dpxBigEndian = std::memcmp(head, "SDPX", 4) == 0;
    if ((dpxBigEndian || std::memcmp(head, "XPDS", 4) == 0) && got == sizeof head) {
        const unsigned char* field = head + 32; // the user data length
        const long long length = dpxBigEndian ? bigEndian32(field) : littleEndian32(field, false);
        if (length != 0xffffffffLL && length > size)
            return "damaged DPX file: its user data is longer than the file";
    }
    return {};
}

} // namespace crt::tracer::image_io
