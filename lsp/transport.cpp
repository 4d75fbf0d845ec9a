// Content-Length framing: headers up to an empty line, then exactly that many bytes.
#include "transport.hpp"

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

Transport::Incoming Transport::read() {
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
    if (length > kMaxMessageBytes) {
        for (size_t i = 0; i < length; ++i) {
            if (std::fgetc(in_) == EOF) return {Status::End, {}};
        }
        return {Status::Malformed, "message too large"};
    }
    std::string body(length, '\0');
    size_t got = length ? std::fread(body.data(), 1, length, in_) : 0;
    if (got != length) return {Status::End, {}};
    return {Status::Message, std::move(body)};
}

void Transport::write(const std::string& body) {
    std::lock_guard lock(writeMutex_);
    std::fprintf(out_, "Content-Length: %zu\r\n\r\n", body.size());
    std::fwrite(body.data(), 1, body.size(), out_);
    std::fflush(out_);
}

} // namespace crt::lsp
