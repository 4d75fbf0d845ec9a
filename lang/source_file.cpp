// Line tables and position conversions for source buffers.
#include "source_file.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <sys/stat.h>

namespace crt::lang {
namespace {

/// Length of the UTF-8 sequence starting with `lead` (1 for invalid lead bytes).
uint32_t sequenceLength(unsigned char lead) {
    if (lead < 0x80) return 1;
    if ((lead >> 5) == 0x6) return 2;
    if ((lead >> 4) == 0xE) return 3;
    if ((lead >> 3) == 0x1E) return 4;
    return 1;
}

} // namespace

uint32_t codePointCount(std::string_view text) {
    uint32_t count = 0;
    for (size_t i = 0; i < text.size(); ++count) {
        i += std::min<size_t>(sequenceLength(static_cast<unsigned char>(text[i])), text.size() - i);
    }
    return count;
}

SourceFile::SourceFile(std::string path, std::string text)
    : path_(std::move(path)), data_(std::move(text)) {
    data_.push_back('\0');
    lineStarts_.push_back(0);
    const char* begin = data_.data();
    const char* end = begin + data_.size() - 1;
    for (const char* p = begin; (p = static_cast<const char*>(std::memchr(p, '\n', static_cast<size_t>(end - p))));) {
        lineStarts_.push_back(static_cast<uint32_t>(++p - begin));
    }
    ascii_ = std::all_of(begin, end, [](char c) { return static_cast<unsigned char>(c) < 0x80; });
    // A byte-order mark is not text: columns of the first line count from after it.
    if (std::string_view(begin, static_cast<size_t>(end - begin)).starts_with("\xEF\xBB\xBF")) lineStarts_[0] = 3;
    if (ascii_) return;
    for (uint32_t index = 0; index < lineStarts_.size(); ++index) {
        const uint32_t lineEnd = index + 1 < lineStarts_.size() ? lineStarts_[index + 1] : size();
        if (lineEnd - std::min(lineStarts_[index], lineEnd) <= kCheckpointSpacing) continue;
        Columns columns;
        uint32_t mark = lineStarts_[index] + kCheckpointSpacing;
        for (uint32_t at = lineStarts_[index]; at < lineEnd;) {
            if (at >= mark) {
                checkpoints_.push_back({at, columns});
                mark = at + kCheckpointSpacing;
            }
            at += columns.count(static_cast<unsigned char>(data_[at]));
        }
    }
}

SourceFile::Columns SourceFile::columnsBefore(uint32_t index, uint32_t offset) const {
    uint32_t at = lineStarts_[index];
    Columns columns;
    auto after = std::upper_bound(checkpoints_.begin(), checkpoints_.end(), offset,
                                  [](uint32_t value, const Checkpoint& c) { return value < c.offset; });
    if (after != checkpoints_.begin() && std::prev(after)->offset >= at) {
        at = std::prev(after)->offset;
        columns = std::prev(after)->columns;
    }
    // Every code point that starts before `offset` counts, one that straddles it included.
    while (at < offset) at += columns.count(static_cast<unsigned char>(data_[at]));
    return columns;
}

uint32_t SourceFile::Columns::count(unsigned char lead) {
    const uint32_t length = sequenceLength(lead);
    ++codePoints;
    utf16Units += length == 4 ? 2 : 1; // past U+FFFF: a surrogate pair
    return length;
}

uint32_t SourceFile::lineStart(uint32_t line) const {
    if (line == 0) return 0;
    if (line > lineStarts_.size()) return size();
    return lineStarts_[line - 1];
}

std::string_view SourceFile::lineText(uint32_t line) const {
    uint32_t begin = lineStart(line);
    uint32_t end = line < lineStarts_.size() ? lineStarts_[line] : size();
    std::string_view text = this->text().substr(begin, end - begin);
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.remove_suffix(1);
    return text;
}

uint32_t SourceFile::lineIndexOf(uint32_t offset) const {
    offset = std::clamp(offset, lineStarts_[0], size());
    uint32_t last = lastLineIndex_;
    auto contains = [&](uint32_t index) {
        return lineStarts_[index] <= offset &&
               (index + 1 == lineStarts_.size() || offset < lineStarts_[index + 1]);
    };
    if (contains(last)) return last;
    if (last + 1 < lineStarts_.size() && contains(last + 1)) return lastLineIndex_ = last + 1;
    auto it = std::upper_bound(lineStarts_.begin(), lineStarts_.end(), offset);
    return lastLineIndex_ = static_cast<uint32_t>(it - lineStarts_.begin()) - 1;
}

LineColumn SourceFile::lineColumn(uint32_t offset) const {
    offset = std::clamp(offset, lineStarts_[0], size());
    uint32_t index = lineIndexOf(offset);
    uint32_t bytes = offset - lineStarts_[index];
    if (ascii_) return {index + 1, bytes + 1};
    return {index + 1, columnsBefore(index, offset).codePoints + 1};
}

uint32_t SourceFile::offsetOf(LineColumn position) const {
    if (position.line == 0 || position.line > lineStarts_.size()) return size();
    uint32_t offset = lineStarts_[position.line - 1];
    std::string_view line = lineText(position.line);
    uint32_t end = offset + static_cast<uint32_t>(line.size());
    for (uint32_t column = 1; column < position.column && offset < end; ++column) {
        offset += sequenceLength(static_cast<unsigned char>(data_[offset]));
    }
    return std::min(offset, end);
}

Utf16Position SourceFile::utf16(uint32_t offset) const {
    offset = std::clamp(offset, lineStarts_[0], size());
    uint32_t index = lineIndexOf(offset);
    if (ascii_) return {index, offset - lineStarts_[index]};
    return {index, columnsBefore(index, offset).utf16Units};
}

uint32_t SourceFile::offsetOf(Utf16Position position) const {
    if (position.line >= lineStarts_.size()) return size();
    uint32_t offset = lineStarts_[position.line];
    std::string_view line = lineText(position.line + 1);
    uint32_t end = offset + static_cast<uint32_t>(line.size());
    uint32_t units = 0;
    while (offset < end && units < position.character) {
        uint32_t length = sequenceLength(static_cast<unsigned char>(data_[offset]));
        units += length == 4 ? 2 : 1;
        offset += length;
    }
    return std::min(offset, end);
}

uint32_t SourceFile::offsetOfUtf8(uint32_t line, uint32_t byteInLine) const {
    if (line >= lineStarts_.size()) return size();
    std::string_view text = lineText(line + 1);
    return lineStarts_[line] + std::min<uint32_t>(byteInLine, static_cast<uint32_t>(text.size()));
}

std::optional<std::string> readFile(const std::string& path) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (!file) return std::nullopt;
    std::string text;
    struct stat info;
    if (fstat(fileno(file), &info) == 0 && S_ISREG(info.st_mode)) {
        text.reserve(static_cast<size_t>(info.st_size) + 1);
    } else if (fstat(fileno(file), &info) == 0 && S_ISDIR(info.st_mode)) {
        std::fclose(file);
        return std::nullopt;
    }
    char buffer[1 << 16];
    size_t count = 0;
    while ((count = std::fread(buffer, 1, sizeof buffer, file)) > 0) text.append(buffer, count);
    bool failed = std::ferror(file) != 0;
    std::fclose(file);
    if (failed) return std::nullopt;
    return text;
}

uint32_t SourceManager::add(std::string path, std::string text) {
    files_.push_back(std::make_unique<SourceFile>(std::move(path), std::move(text)));
    return static_cast<uint32_t>(files_.size() - 1);
}

} // namespace crt::lang
