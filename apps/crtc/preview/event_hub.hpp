// Server-Sent Events for the preview's pages: every event published goes to every page
// listening, and a page that connects late is first told the latest event of each kind, in the
// order they were published.
#pragma once

#include <chrono>
#include <cstdint>
#include <condition_variable>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace crt::crtc::preview {

class EventHub {
public:
    /// One page's stream of events, already in the text/event-stream format.
    class Subscription {
    public:
        /// The next event's text; a comment (": ...") if none came within `wait`, nothing
        /// once the hub is closed.
        std::optional<std::string> next(std::chrono::milliseconds wait);

    private:
        friend class EventHub;
        std::mutex mutex_;
        std::condition_variable ready_;
        std::deque<std::string> queue_;
        bool closed_ = false;
    };

    /// Sends `data` (JSON text, one line) as event `name` to every subscriber.
    void publish(const std::string& name, const std::string& data);
    std::shared_ptr<Subscription> subscribe();
    void unsubscribe(const std::shared_ptr<Subscription>& subscription);
    /// Ends every stream, now and for later subscribers.
    void close();

private:
    std::mutex mutex_;
    std::vector<std::shared_ptr<Subscription>> subscribers_;
    /// The latest event of each name, with its place in the order of publication.
    std::map<std::string, std::pair<uint64_t, std::string>> latest_;
    uint64_t published_ = 0;
    bool closed_ = false;
};

} // namespace crt::crtc::preview
