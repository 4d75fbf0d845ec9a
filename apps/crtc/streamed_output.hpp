// Writing a render's image while it is traced: finished rows go to the file on a thread of
// their own, so that encoding overlaps tracing instead of following it, and a large image is
// never held whole.
#pragma once

#include "tracer/image_io/image_io.hpp"

#include <atomic>
#include <condition_variable>
#include <deque>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <thread>
#include <vector>

namespace crt::crtc {

class StreamedOutput {
public:
    /// Starts the writer thread, which opens `path` when the first rows arrive. If opening or
    /// writing fails, `failed` is set, so that the render can stop: its image has nowhere to go.
    /// `channels`: 3 (RGB), or 4 (RGB and alpha, premultiplied as the renderer makes it).
    StreamedOutput(std::string path, int width, int height, int channels,
                   tracer::image_io::WriteOptions options, std::atomic<bool>& failed);
    /// Destroying an unfinished output (an interrupted or failed render) leaves no file.
    ~StreamedOutput();
    StreamedOutput(const StreamedOutput&) = delete;
    StreamedOutput& operator=(const StreamedOutput&) = delete;

    /// Hands over rows [yBegin, yEnd) (`channels` floats a pixel), the next ones from the top;
    /// a copy is queued, so this returns at once (it runs on a render worker).
    void addRows(int yBegin, int yEnd, std::span<const float> pixels);
    /// After the last rows: waits for the writer, then completes and renames the file.
    bool finish(std::string& error);

private:
    struct Band {
        int yBegin, yEnd;
        std::vector<float> pixels;
    };

    void write();
    void stopWriter();

    std::string path_;
    int width_, height_, channels_;
    tracer::image_io::WriteOptions options_;
    std::atomic<bool>& failed_;
    std::unique_ptr<tracer::image_io::ImageStream> stream_;
    std::string error_; ///< the first failure, written by the writer thread
    std::mutex mutex_;
    std::condition_variable ready_;
    std::deque<Band> bands_;
    /// Buffers of bands written, for the next ones: fresh memory costs a page fault every 4 KB.
    std::vector<std::vector<float>> spare_;
    bool noMoreRows_ = false;
    std::thread writer_;
};

} // namespace crt::crtc
