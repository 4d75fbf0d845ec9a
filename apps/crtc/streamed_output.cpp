// The streamed output's writer thread.
#include "streamed_output.hpp"

namespace crt::crtc {

namespace image_io = tracer::image_io;

StreamedOutput::StreamedOutput(std::string path, int width, int height, int channels,
                               image_io::WriteOptions options, std::atomic<bool>& failed)
    : path_(std::move(path)), width_(width), height_(height), channels_(channels),
      options_(options), failed_(failed), writer_([this] { write(); }) {}

StreamedOutput::~StreamedOutput() {
    stopWriter();
    // stream_, if unfinished, removes its temporary file as it goes.
}

void StreamedOutput::addRows(int yBegin, int yEnd, std::span<const float> pixels) {
    Band band{yBegin, yEnd, {}};
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!spare_.empty()) {
            band.pixels = std::move(spare_.back());
            spare_.pop_back();
        }
    }
    band.pixels.assign(pixels.begin(), pixels.end());
    if (channels_ == 4) image_io::straightenAlpha(band.pixels); // files take straight alpha
    {
        std::lock_guard<std::mutex> lock(mutex_);
        bands_.push_back(std::move(band));
    }
    ready_.notify_one();
}

void StreamedOutput::write() {
    std::unique_ptr<image_io::ImageStream> stream;
    std::string error = "no rows were rendered";
    bool opened = false;
    while (true) {
        Band band;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            ready_.wait(lock, [&] { return !bands_.empty() || noMoreRows_; });
            if (bands_.empty()) break;
            band = std::move(bands_.front());
            bands_.pop_front();
        }
        if (!opened) {
            // Opened with the first rows: a render that fails before it has any leaves no
            // file behind.
            opened = true;
            error.clear();
            stream = image_io::ImageStream::open(path_, width_, height_, channels_, options_, error);
            if (!stream) failed_ = true;
        }
        // After a failure the remaining rows are only drained: the error is reported once.
        if (stream && !stream->writeRows(band.yBegin, band.yEnd, band.pixels, error)) {
            stream.reset();
            failed_ = true;
        }
        std::lock_guard<std::mutex> lock(mutex_);
        spare_.push_back(std::move(band.pixels));
    }
    std::lock_guard<std::mutex> lock(mutex_);
    stream_ = std::move(stream);
    error_ = error;
}

void StreamedOutput::stopWriter() {
    if (!writer_.joinable()) return;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        noMoreRows_ = true;
    }
    ready_.notify_one();
    writer_.join();
}

bool StreamedOutput::finish(std::string& error) {
    stopWriter();
    if (!stream_) {
        error = error_;
        return false;
    }
    bool ok = stream_->finish(error);
    stream_.reset();
    return ok;
}

} // namespace crt::crtc
