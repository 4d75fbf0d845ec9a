// A scratch folder for tests that write files: fresh for each process, removed when it ends.
#pragma once

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <unistd.h>
#include <vector>

namespace crt::tracer::test {

inline const std::filesystem::path& scratch() {
    struct Folder {
        std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("crt_test." + std::to_string(getpid()));
        Folder() {
            std::filesystem::remove_all(path);
            std::filesystem::create_directories(path);
        }
        ~Folder() {
            std::error_code ignored;
            std::filesystem::remove_all(path, ignored);
        }
    };
    static Folder folder;
    return folder.path;
}

inline std::string scratchFile(const std::string& name) { return (scratch() / name).string(); }

/// The names in the scratch folder, sorted: what a write left behind.
inline std::vector<std::string> scratchListing() {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(scratch()))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

/// Whether OpenImageIO's library is loaded into this process.
inline bool openImageIoMapped() {
    std::ifstream maps("/proc/self/maps");
    const std::string text{std::istreambuf_iterator<char>(maps), std::istreambuf_iterator<char>()};
    return text.find("libOpenImageIO") != std::string::npos;
}

} // namespace crt::tracer::test
