// JSON-RPC framing over byte streams: Content-Length headers, as LSP's base protocol says.
#pragma once

#include <cstdio>
#include <mutex>
#include <string>

namespace crt::lsp {

/// Reads and writes framed messages. Reading is for one thread; writing may come from any.
class Transport {
public:
    Transport(std::FILE* in, std::FILE* out) : in_(in), out_(out) {}

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

    /// Frames larger than this are read and dropped (Malformed): no document is that big.
    static constexpr size_t kMaxMessageBytes = size_t{256} << 20;

private:
    std::FILE* in_;
    std::FILE* out_;
    std::mutex writeMutex_;
};

} // namespace crt::lsp
