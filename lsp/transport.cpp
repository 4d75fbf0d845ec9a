// Content-Length framing: headers up to an empty line, then exactly that many bytes.
#include "transport.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <string_view>

namespace crt::lsp {

namespace {

/// One header line without its CR LF; false at end of input.
bool readLine(std::FILE* in, std::string& line) {
    line.clear();
    for (int c; (c = std::fgetc(in)) != EOF;) {
        if (c == '\n') {
            if (!line.empty() && line.back() == '\r') line.pop_back();
            return true;
        }
        if (line.size() < 4096) line.push_back(static_cast<char>(c)); // a header is short
    }
    return !line.empty();
}

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
    }
    return true;
}

} // namespace

bool Transport::readBody(size_t length, std::string& body) {
    constexpr size_t kChunk = size_t{1} << 20;
    body.clear();
    while (body.size() < length) {
        const size_t before = body.size();
        const size_t want = std::min(kChunk, length - before);
        body.resize(before + want);
        const size_t got = std::fread(body.data() + before, 1, want, in_);
        if (got != want) return false;
    }
    return true;
}

Transport::Incoming Transport::read() {
    char discard[1 << 16];
    while (skipBeforeNext_ > 0) {
        const size_t want = std::min(sizeof discard, skipBeforeNext_);
        if (std::fread(discard, 1, want, in_) != want) return {Status::End, {}};
        skipBeforeNext_ -= want;
    }
    std::string line;
    bool sawHeader = false;
    bool haveLength = false;
    bool badLength = false;
    size_t length = 0;
    while (true) {
        if (!readLine(in_, line)) return {Status::End, {}};
        if (line.empty()) {
            if (!sawHeader) continue; // stray blank lines between messages
            break;
        }
        sawHeader = true;
        size_t colon = line.find(':');
        if (colon == std::string::npos) continue;
        std::string_view name = std::string_view(line).substr(0, colon);
        std::string_view value = std::string_view(line).substr(colon + 1);
        while (!value.empty() && value.front() == ' ') value.remove_prefix(1);
        while (!value.empty() && value.back() == ' ') value.remove_suffix(1);
        if (equalsIgnoringCase(name, "Content-Length")) {
            auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), length);
            haveLength = error == std::errc() && end == value.data() + value.size();
            badLength = !haveLength;
        }
    }
    if (!haveLength || badLength) return {Status::Malformed, "missing or invalid Content-Length header"};
    if (length > maxMessageBytes_) {
        skipBeforeNext_ = length;
        return {Status::Malformed, fmt::format("message of {} bytes is larger than the limit of {} MiB "
                                               "(crt-lsp --max-message-mib); its body is skipped",
                                               length, maxMessageBytes_ >> 20)};
    }
    std::string body;
    if (!readBody(length, body)) return {Status::End, {}};
    return {Status::Message, std::move(body)};
}

void Transport::write(const std::string& body) {
    std::lock_guard lock(writeMutex_);
    std::fprintf(out_, "Content-Length: %zu\r\n\r\n", body.size());
    std::fwrite(body.data(), 1, body.size(), out_);
    std::fflush(out_);
}

} // namespace crt::lsp
