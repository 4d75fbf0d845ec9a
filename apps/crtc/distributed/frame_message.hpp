// The messages of an animation shared out by frames (frame_dispatcher.hpp has the protocol):
// what a rank tells rank 0 of a frame it evaluated, and of one it traced.
#pragma once

#include "tracer/renderer.hpp"

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace crt::crtc::distributed {

/// A frame evaluated on some rank: what rank 0 needs to decide whether it is traced, and to
/// write it. Sent as raw bytes between processes of the same crtc.
struct FrameFacts {
    int32_t frame = 0;
    int32_t ok = 0;
    int32_t width = 0, height = 0;
    double gamma = 1.0;
    int32_t srgb = 0;
    int32_t padding = 0;
    uint64_t hash = 0;       ///< frameHash, for the resume log
    uint64_t keyDigest[3]{}; ///< unchangedFrameKey digested: equal keys, equal digests
    bool sameScene(const FrameFacts& other) const {
        return std::memcmp(keyDigest, other.keyDigest, sizeof keyDigest) == 0;
    }
};

/// A frame traced: its ray counts and timings, for the summary and --stats.
struct FrameDone {
    int32_t frame = 0;
    uint64_t summed[tracer::RayStats::kSummed]{};     ///< RayStats::summed()
    uint64_t greatest[tracer::RayStats::kGreatest]{}; ///< RayStats::greatest()
    double buildSeconds = 0, renderSeconds = 0;
    uint64_t primitives = 0, drawnPrimitives = 0, bvhNodes = 0;
    uint64_t sceneBytes = 0, peakBytes = 0;
    int32_t bvhDepth = 0;
    int32_t ok = 0;
};

FrameDone frameDoneOf(const tracer::RenderOutcome& outcome);
/// The outcome a FrameDone describes (ok, stats, timings, BVH size).
tracer::RenderOutcome outcomeOf(const FrameDone& done);

/// A fixed-size struct, then free text (a frame's diagnostics), as one message.
template <class Fixed> std::vector<char> withText(const Fixed& fixed, const std::string& text) {
    std::vector<char> message(sizeof fixed + text.size());
    std::memcpy(message.data(), &fixed, sizeof fixed);
    if (!text.empty()) std::memcpy(message.data() + sizeof fixed, text.data(), text.size());
    return message;
}
/// The struct and text of withText's message; false for a message too short to be one.
template <class Fixed>
bool splitText(const std::vector<char>& message, Fixed& fixed, std::string* text = nullptr) {
    if (message.size() < sizeof fixed) return false;
    std::memcpy(&fixed, message.data(), sizeof fixed);
    if (text) text->assign(message.begin() + sizeof fixed, message.end());
    return true;
}

} // namespace crt::crtc::distributed
