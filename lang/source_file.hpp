// Immutable source buffers and their line tables: byte offsets <-> line/column <-> UTF-16.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace crt::lang {

/// A half-open byte range [begin, end) in one source file.
struct SourceRange {
    uint32_t file = 0; ///< index into the SourceManager
    uint32_t begin = 0;
    uint32_t end = 0;
    bool operator==(const SourceRange&) const = default;
};

/// A 1-based line and column, the column counted in code points (a tab is one column).
struct LineColumn {
    uint32_t line = 1;
    uint32_t column = 1;
    bool operator==(const LineColumn&) const = default;
};

/// A 0-based line and UTF-16 code-unit offset, as the language server protocol counts.
struct Utf16Position {
    uint32_t line = 0;
    uint32_t character = 0;
    bool operator==(const Utf16Position&) const = default;
};

/// One file's text. The text always ends with a NUL byte past size() so the lexer can stop
/// on it without bounds checks.
class SourceFile {
public:
    SourceFile(std::string path, std::string text);

    const std::string& path() const { return path_; }
    std::string_view text() const { return {data_.data(), data_.size() - 1}; }
    const char* data() const { return data_.data(); }
    uint32_t size() const { return static_cast<uint32_t>(data_.size() - 1); }

    uint32_t lineCount() const { return static_cast<uint32_t>(lineStarts_.size()); }
    /// Byte offset where 1-based `line` starts (the end of file for lines past the last).
    uint32_t lineStart(uint32_t line) const;
    /// The text of 1-based `line`, without its line break.
    std::string_view lineText(uint32_t line) const;

    LineColumn lineColumn(uint32_t offset) const;
    uint32_t offsetOf(LineColumn position) const;
    Utf16Position utf16(uint32_t offset) const;
    uint32_t offsetOf(Utf16Position position) const;
    /// A UTF-8 position (0-based line, byte within the line), as LSP's "utf-8" encoding.
    uint32_t offsetOfUtf8(uint32_t line, uint32_t byteInLine) const;

private:
    uint32_t lineIndexOf(uint32_t offset) const;
    /// Code points and UTF-16 code units from the start of line `index` (0-based) to `offset`.
    struct Columns {
        uint32_t codePoints = 0;
        uint32_t utf16Units = 0;
        /// Counts the code point whose first byte is `lead`; returns its length in bytes.
        uint32_t count(unsigned char lead);
    };
    Columns columnsBefore(uint32_t index, uint32_t offset) const;

    /// Where counting the columns of a long line of non-ASCII text may resume: one every
    /// kCheckpointSpacing bytes of such lines, so a column costs that much at most, not the
    /// line's length (a one-line file with an error every few bytes would otherwise take
    /// time quadratic in its size to print them).
    struct Checkpoint {
        uint32_t offset;  ///< the start of a code point (as counted from its line's start)
        Columns columns;  ///< before it on its line
    };
    static constexpr uint32_t kCheckpointSpacing = 256;

    std::string path_;
    std::string data_;
    std::vector<uint32_t> lineStarts_;
    bool ascii_ = true;                 ///< columns are then byte offsets
    std::vector<Checkpoint> checkpoints_; ///< by offset; only in non-ASCII text
    mutable uint32_t lastLineIndex_ = 0; ///< lookups tend to move forward through the file
};

/// Owns every source file of one evaluation; SourceRange::file indexes it.
class SourceManager {
public:
    uint32_t add(std::string path, std::string text);
    const SourceFile& file(uint32_t index) const { return *files_[index]; }
    uint32_t fileCount() const { return static_cast<uint32_t>(files_.size()); }

private:
    std::vector<std::unique_ptr<SourceFile>> files_;
};

/// The contents of the file at `path`, or nothing if it cannot be read (or is a folder).
/// The string has room for SourceFile's terminating NUL, so it is never copied again.
std::optional<std::string> readFile(const std::string& path);

/// Number of code points in a UTF-8 string (invalid bytes count as one each).
uint32_t codePointCount(std::string_view text);

} // namespace crt::lang
