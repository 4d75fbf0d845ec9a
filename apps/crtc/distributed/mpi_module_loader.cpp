// Finds and loads the MPI module crt_mpi.so.
#include "mpi_module_loader.hpp"

#include "companion_files.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <system_error>
#include <vector>

namespace crt::crtc::distributed {
namespace {

namespace fs = std::filesystem;

constexpr const char* kModuleFileName = "crt_mpi.so";
constexpr const char* kModuleVariable = "CRT_MPI_MODULE";

const CrtMpiModule* openModule(const fs::path& path, std::string& error) {
    // The handle is never closed: MPI keeps threads and state alive until the process exits.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* reason = dlerror();
        error = "cannot load the MPI module " + path.string() + ": " +
                (reason ? reason : "unknown dlopen error");
        return nullptr;
    }
    auto entry = reinterpret_cast<CrtMpiEntryFn>(dlsym(handle, kCrtMpiEntryName));
    if (!entry) {
        error = "the MPI module " + path.string() + " has no entry point " + kCrtMpiEntryName;
        return nullptr;
    }
    const CrtMpiModule* module = entry();
    if (!module || module->abiVersion != kCrtMpiAbiVersion) {
        error = "the MPI module " + path.string() +
                " was built for another version of crt (interface version " +
                std::to_string(module ? module->abiVersion : 0) + ", expected " +
                std::to_string(kCrtMpiAbiVersion) + ")";
        return nullptr;
    }
    return module;
}

} // namespace

const CrtMpiModule* loadMpiModule(std::string& error) {
    std::error_code ec;
    if (const char* named = std::getenv(kModuleVariable); named && *named) {
        if (fs::exists(named, ec)) return openModule(named, error);
        error = std::string("the MPI module ") + named + " named by " + kModuleVariable +
                " does not exist";
        return nullptr;
    }
    const std::vector<fs::path> candidates = companionCandidates(kModuleFileName);
    for (const fs::path& path : candidates)
        if (fs::exists(path, ec)) return openModule(path, error);
    error = std::string("the MPI module ") + kModuleFileName + " was not found; looked for " +
            describeCandidates(candidates) + "; " + kModuleVariable + " can name it";
    return nullptr;
}

} // namespace crt::crtc::distributed
