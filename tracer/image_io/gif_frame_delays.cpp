// Reading and setting the frame delays of a GIF file (GIF89a: header, logical screen and
// colour table, then extension and image blocks made of length-prefixed sub-blocks).
#include "tracer/image_io/gif_frame_delays.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

namespace crt::tracer::image_io {

namespace {

constexpr unsigned char kExtension = 0x21, kImage = 0x2C, kTrailer = 0x3B;
constexpr unsigned char kGraphicControl = 0xF9;

/// Where the delay of each frame is in `bytes` (its low byte; the high one follows), or
/// nothing when the bytes are not a GIF whose blocks end where they should.
std::optional<std::vector<size_t>> delayOffsets(const std::vector<unsigned char>& bytes) {
    size_t at = 13; // header and logical screen descriptor
    auto colourTable = [&](unsigned char flags) {
        if (flags & 0x80) at += 3 * (size_t{2} << (flags & 7));
    };
    // Sub-blocks: a size byte, that many bytes, until a size of 0.
    auto skipSubBlocks = [&] {
        while (at < bytes.size() && bytes[at] != 0) at += 1 + bytes[at];
        ++at;
    };
    if (bytes.size() < at || std::memcmp(bytes.data(), "GIF89a", 6) != 0) return std::nullopt;
    colourTable(bytes[10]);
    std::vector<size_t> offsets;
    while (at < bytes.size()) {
        const unsigned char block = bytes[at++];
        if (block == kTrailer) return offsets;
        if (block == kExtension && at < bytes.size()) {
            const unsigned char label = bytes[at++];
            if (label == kGraphicControl && at + 5 < bytes.size() && bytes[at] == 4)
                offsets.push_back(at + 2); // size, flags, then the delay
            skipSubBlocks();
        } else if (block == kImage && at + 9 < bytes.size()) {
            const unsigned char flags = bytes[at + 8];
            at += 9;
            colourTable(flags);
            ++at; // the LZW code size
            skipSubBlocks();
        } else {
            return std::nullopt;
        }
    }
    return std::nullopt; // no trailer
}

std::optional<std::vector<unsigned char>> readAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::vector<unsigned char> bytes{std::istreambuf_iterator<char>(in), {}};
    if (in.bad()) return std::nullopt;
    return bytes;
}

} // namespace

std::vector<std::uint16_t> gifFrameDelays(int frames, double fps) {
    std::vector<std::uint16_t> delays;
    long previous = 0;
    for (int i = 0; i < frames; ++i) {
        const long end = std::max(previous + 1, std::lround((i + 1) * 100.0 / fps));
        delays.push_back(static_cast<std::uint16_t>(std::min(end - previous, 65535L)));
        previous = end;
    }
    return delays;
}

std::optional<std::vector<std::uint16_t>> readGifDelays(const std::string& path,
                                                        std::string& error) {
    const std::optional<std::vector<unsigned char>> bytes = readAll(path);
    if (!bytes) {
        error = std::strerror(errno);
        return std::nullopt;
    }
    const std::optional<std::vector<size_t>> offsets = delayOffsets(*bytes);
    if (!offsets) {
        error = "not a GIF file whose blocks can be read";
        return std::nullopt;
    }
    std::vector<std::uint16_t> delays;
    for (size_t at : *offsets)
        delays.push_back(static_cast<std::uint16_t>((*bytes)[at] | ((*bytes)[at + 1] << 8)));
    return delays;
}

bool writeGifDelays(const std::string& path, const std::vector<std::uint16_t>& delays,
                    std::string& error) {
    const std::optional<std::vector<unsigned char>> bytes = readAll(path);
    const std::optional<std::vector<size_t>> offsets = bytes ? delayOffsets(*bytes) : std::nullopt;
    if (!offsets || offsets->size() != delays.size()) {
        error = "the GIF writer did not write one frame delay for each frame";
        return false;
    }
    const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    bool ok = fd >= 0;
    for (size_t i = 0; ok && i < delays.size(); ++i) {
        const unsigned char delay[2] = {static_cast<unsigned char>(delays[i] & 0xFF),
                                        static_cast<unsigned char>(delays[i] >> 8)};
        ok = ::pwrite(fd, delay, 2, static_cast<off_t>((*offsets)[i])) == 2;
    }
    if (!ok) error = std::strerror(errno);
    if (fd >= 0 && ::close(fd) != 0 && ok) {
        error = std::strerror(errno);
        ok = false;
    }
    return ok;
}

} // namespace crt::tracer::image_io
