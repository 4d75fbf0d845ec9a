// Test sources with position markers, as clangd's Annotations: `@` marks a point, `«…»` a
// range, each optionally named by a preceding `$name`. Neither character occurs in CRT.
#pragma once

#include "analysis.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace crt::lsp::test {

class Annotations {
public:
    explicit Annotations(std::string_view marked) {
        std::vector<std::pair<std::string, uint32_t>> open;
        for (size_t i = 0; i < marked.size();) {
            std::string name;
            if (marked[i] == '$') {
                size_t j = i + 1;
                while (j < marked.size() && (std::isalnum(static_cast<unsigned char>(marked[j])) || marked[j] == '_')) ++j;
                name = std::string(marked.substr(i + 1, j - i - 1));
                i = j;
            }
            if (marked.substr(i, 1) == "@") {
                points_[name].push_back(static_cast<uint32_t>(code.size()));
                i += 1;
            } else if (marked.substr(i, 2) == "\xC2\xAB") { // «
                open.emplace_back(name, static_cast<uint32_t>(code.size()));
                i += 2;
            } else if (marked.substr(i, 2) == "\xC2\xBB") { // »
                REQUIRE(!open.empty());
                ranges_[open.back().first].push_back({0, open.back().second, static_cast<uint32_t>(code.size())});
                open.pop_back();
                i += 2;
            } else {
                REQUIRE(name.empty()); // a name must precede a marker
                code += marked[i++];
            }
        }
        REQUIRE(open.empty());
    }

    uint32_t point(const std::string& name = "") const {
        REQUIRE(points_.count(name));
        REQUIRE(points_.at(name).size() == 1);
        return points_.at(name)[0];
    }
    std::vector<uint32_t> points(const std::string& name = "") const {
        return points_.count(name) ? points_.at(name) : std::vector<uint32_t>{};
    }
    lang::SourceRange range(const std::string& name = "") const {
        REQUIRE(ranges_.count(name));
        REQUIRE(ranges_.at(name).size() == 1);
        return ranges_.at(name)[0];
    }
    std::vector<lang::SourceRange> ranges(const std::string& name = "") const {
        return ranges_.count(name) ? ranges_.at(name) : std::vector<lang::SourceRange>{};
    }

    std::string code;

private:
    std::map<std::string, std::vector<uint32_t>> points_;
    std::map<std::string, std::vector<lang::SourceRange>> ranges_;
};

/// A folder of its own for a test's files, removed afterwards.
struct TempDir {
    TempDir() {
        path = std::filesystem::temp_directory_path() /
               ("crt-lsp-test-" + std::to_string(reinterpret_cast<uintptr_t>(this)) + "-" +
                std::to_string(counter()++));
        std::filesystem::create_directories(path);
    }
    ~TempDir() {
        std::error_code error;
        std::filesystem::remove_all(path, error);
    }
    std::string write(const std::string& name, const std::string& text) const {
        std::ofstream(path / name) << text;
        return (path / name).string();
    }
    static int& counter() {
        static int n = 0;
        return n;
    }
    std::filesystem::path path;
};

inline AnalysisOptions testOptions() {
    AnalysisOptions options;
    options.includes.stdlibDir = CRT_SOURCE_STDLIB_DIR;
    return options;
}

/// Analyzes `code` as the file `main.crt` of `dir`.
inline std::shared_ptr<const Analysis> analyzeIn(const TempDir& dir, const std::string& code) {
    static IncludeCache cache;
    return analyze((dir.path / "main.crt").string(), code, testOptions(), cache);
}

inline std::shared_ptr<const Analysis> analyzeCode(const std::string& code) {
    TempDir dir;
    return analyzeIn(dir, code);
}

inline std::string textOf(const Analysis& a, lang::SourceRange range) { return std::string(a.text(range)); }

} // namespace crt::lsp::test
