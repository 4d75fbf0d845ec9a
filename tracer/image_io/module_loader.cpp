// Finds and loads the OpenImageIO module once per process, on first use.
#include "tracer/image_io/module_loader.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <exception>
#include <filesystem>
#include <system_error>
#include <vector>

namespace crt::tracer::image_io::detail {
namespace {

namespace fs = std::filesystem;

constexpr const char* kModuleFileName = "crt_image_io_oiio.so";
constexpr const char* kModuleVariable = "CRT_IMAGE_IO_MODULE";

struct LoadResult {
    const CrtImageIoModule* module = nullptr;
    std::string error;
};

// Where a program keeps the module: beside its executable (the build tree puts it there), or
// in ../lib/crt/ (an installed layout).
std::vector<fs::path> candidatePaths() {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    const fs::path dir = exe.parent_path();
    return {dir / kModuleFileName,
            (dir / ".." / "lib" / "crt" / kModuleFileName).lexically_normal()};
}

LoadResult openModule(const fs::path& path) {
    // RTLD_LOCAL keeps OpenImageIO's symbols (and its bundled fmt) out of the global namespace;
    // the handle is never closed, since OIIO keeps threads and static state alive until exit.
    void* handle = dlopen(path.c_str(), RTLD_LAZY | RTLD_LOCAL);
    if (!handle) {
        const char* reason = dlerror();
        return {nullptr, "cannot load the image module " + path.string() + ": " +
                             (reason ? reason : "unknown dlopen error")};
    }
    auto entry = reinterpret_cast<CrtImageIoEntryFn>(dlsym(handle, kCrtImageIoEntryName));
    if (!entry) {
        return {nullptr, "the image module " + path.string() + " has no entry point " +
                             kCrtImageIoEntryName};
    }
    const CrtImageIoModule* module = entry();
    if (!module || module->abiVersion != kCrtImageIoAbiVersion) {
        return {nullptr, "the image module " + path.string() +
                             " was built for another version of crt (interface version " +
                             std::to_string(module ? module->abiVersion : 0) + ", expected " +
                             std::to_string(kCrtImageIoAbiVersion) + ")"};
    }
    return {module, {}};
}

LoadResult loadModule() {
    if (const char* named = std::getenv(kModuleVariable); named && *named) {
        std::error_code ec;
        if (!fs::exists(named, ec)) {
            return {nullptr, std::string("the image module ") + named + " named by " +
                                 kModuleVariable + " does not exist"};
        }
        return openModule(named);
    }
    const std::vector<fs::path> candidates = candidatePaths();
    for (const fs::path& path : candidates) {
        std::error_code ec;
        if (fs::exists(path, ec)) return openModule(path);
    }
    std::string message = std::string("the image module ") + kModuleFileName +
                          " was not found (images cannot be read or written); looked for ";
    for (std::size_t i = 0; i < candidates.size(); ++i)
        message += (i ? " and " : "") + candidates[i].string();
    if (candidates.empty()) message += "the executable's directory, which is unknown";
    return {nullptr, message + "; " + kModuleVariable + " can name it"};
}

// A failure to load is an error message, never an exception: the outcome is kept for good.
LoadResult loadModuleSafely() noexcept {
    try {
        return loadModule();
    } catch (const std::exception& e) {
        return {nullptr, std::string("cannot load the image module: ") + e.what()};
    }
}

} // namespace

const CrtImageIoModule* loadedModule(std::string& error) {
    // A function-local static is initialised once, and callers arriving meanwhile wait for it.
    static const LoadResult result = loadModuleSafely();
    if (!result.module) error = result.error;
    return result.module;
}

} // namespace crt::tracer::image_io::detail
