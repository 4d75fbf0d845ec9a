// JSON-RPC framing over byte streams: Content-Length headers, as LSP's base protocol says.
#pragma once

#include <cstdio>
#include <mutex>
#include <string>

namespace crt::lsp {

/// Reads and writes framed messages. Reading is for one thread; writing may come from any.
class Transport {
public:
    Transport(std::FILE* in, std::FILE* out, size_t maxMessageBytes = kDefaultMaxMessageBytes)
        : in_(in), out_(out), maxMessageBytes_(maxMessageBytes) {}

    enum class Status { Message, Malformed, End };
    struct Incoming {
        Status status;
        std::string body; ///< the message, or what was wrong with the frame
    };
    /// The next message body. A frame with no usable Content-Length is Malformed, and
    /// reading goes on after its header.
    Incoming read();
    /// Writes one message with its header, atomically with respect to other writers.
    void write(const std::string& body);

    /// Frames larger than this are Malformed at once (so the client hears why without
    /// waiting), and their bodies are skipped by the next read: no document is that big.
    static constexpr size_t kDefaultMaxMessageBytes = size_t{64} << 20;

private:
    /// Reads `length` bytes of body, growing the buffer as they arrive rather than trusting
    /// the header; false at the end of input.
    bool readBody(size_t length, std::string& body);

    std::FILE* in_;
    std::FILE* out_;
    size_t maxMessageBytes_;
    size_t skipBeforeNext_ = 0; ///< the body of a frame too large, still to drop
    std::mutex writeMutex_;
};

} // namespace crt::lsp
