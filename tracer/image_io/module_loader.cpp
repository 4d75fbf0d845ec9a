// Finds and loads the OpenImageIO module once per process, optionally on a background thread.
#include "tracer/image_io/module_loader.hpp"

#include <dlfcn.h>

#include <condition_variable>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <system_error>
#include <thread>
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

// Where an installed or build-tree crtc keeps its module: beside the executable (the build
// tree puts it there), or in ../lib/crt/ (an installed layout).
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

// Runs on the loading thread, where an escaping exception would terminate the process.
LoadResult loadModuleSafely() noexcept {
    try {
        return loadModule();
    } catch (const std::exception& e) {
        return {nullptr, std::string("cannot load the image module: ") + e.what()};
    }
}

class Loader {
  public:
    ~Loader() {
        // A process that exits while the load is under way waits for it: leaving the thread
        // inside dlopen while static destructors run would be undefined behaviour.
        if (thread_.joinable()) thread_.join();
    }

    void startInBackground() {
        std::lock_guard lock(mutex_);
        if (started_) return;
        started_ = true;
        try {
            thread_ = std::thread([this] { finish(loadModuleSafely()); });
        } catch (const std::system_error&) {
            // No thread to be had: the first call will load on its own thread instead.
            started_ = false;
        }
    }

    const CrtImageIoModule* get(std::string& error) {
        std::unique_lock lock(mutex_);
        if (!started_) {
            started_ = true;
            lock.unlock();
            finish(loadModuleSafely());
            lock.lock();
        }
        done_.wait(lock, [this] { return finished_; });
        if (!result_.module) error = result_.error;
        return result_.module;
    }

    bool waitIfStarted() {
        std::unique_lock lock(mutex_);
        if (started_) done_.wait(lock, [this] { return finished_; });
        return started_;
    }

  private:
    void finish(LoadResult result) {
        {
            std::lock_guard lock(mutex_);
            result_ = std::move(result);
            finished_ = true;
        }
        done_.notify_all();
    }

    std::mutex mutex_;
    std::condition_variable done_;
    bool started_ = false;
    bool finished_ = false;
    LoadResult result_;
    std::thread thread_;
};

Loader& loader() {
    static Loader instance;
    return instance;
}

} // namespace

void startModuleLoad() {
    loader().startInBackground();
}

bool waitForStartedLoad() {
    return loader().waitIfStarted();
}

const CrtImageIoModule* loadedModule(std::string& error) {
    return loader().get(error);
}

} // namespace crt::tracer::image_io::detail
