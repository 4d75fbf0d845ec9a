// A rank's standard error kept for rank 0, which prints it with the frame it is about.
#pragma once

#include <iostream>
#include <mutex>
#include <streambuf>
#include <string>
#include <thread>
#include <utility>

namespace crt::crtc::distributed {

/// Keeps what is written to std::cerr (diagnostics, warnings) while it lives: by every thread,
/// or by every thread but one, whose text goes on to standard error (rank 0's main thread,
/// which reports the run while its worker evaluates frames beside it).
class CapturedErrors {
  public:
    explicit CapturedErrors(std::thread::id except = {})
        : buffer_(except, std::cerr.rdbuf()), previous_(std::cerr.rdbuf(&buffer_)) {}
    ~CapturedErrors() { std::cerr.rdbuf(previous_); }
    CapturedErrors(const CapturedErrors&) = delete;
    CapturedErrors& operator=(const CapturedErrors&) = delete;

    /// The text kept since the last take().
    std::string take() { return buffer_.take(); }

  private:
    class Buffer final : public std::streambuf {
      public:
        Buffer(std::thread::id except, std::streambuf* out) : except_(except), out_(out) {}
        std::string take() {
            std::lock_guard lock(mutex_);
            return std::exchange(text_, {});
        }

      protected:
        int_type overflow(int_type c) override {
            if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
            const char ch = traits_type::to_char_type(c);
            return xsputn(&ch, 1) == 1 ? c : traits_type::eof();
        }
        std::streamsize xsputn(const char* s, std::streamsize n) override {
            if (except_ != std::thread::id() && std::this_thread::get_id() == except_)
                return out_->sputn(s, n);
            std::lock_guard lock(mutex_);
            text_.append(s, static_cast<size_t>(n));
            return n;
        }
        int sync() override { return out_->pubsync(); }

      private:
        const std::thread::id except_;
        std::streambuf* const out_;
        std::mutex mutex_;
        std::string text_;
    };

    Buffer buffer_;
    std::streambuf* previous_;
};

} // namespace crt::crtc::distributed
