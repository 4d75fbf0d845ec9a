// Server-Sent Events (see event_hub.hpp).
#include "preview/event_hub.hpp"

#include <algorithm>

namespace crt::crtc::preview {

namespace {

/// A queue that a page stopped reading is not allowed to grow without bound: past this many
/// waiting events the oldest are dropped (the page catches up from the newest).
constexpr size_t kMaxQueued = 256;

} // namespace

std::optional<std::string> EventHub::Subscription::next(std::chrono::milliseconds wait) {
    std::unique_lock lock(mutex_);
    if (!ready_.wait_for(lock, wait, [this] { return closed_ || !queue_.empty(); })) return ": idle\n\n";
    if (queue_.empty()) return std::nullopt; // closed
    std::string event = std::move(queue_.front());
    queue_.pop_front();
    return event;
}

void EventHub::publish(const std::string& name, const std::string& data) {
    std::string event = "event: " + name + "\ndata: " + data + "\n\n";
    std::lock_guard lock(mutex_);
    latest_[name] = {++published_, event};
    for (const std::shared_ptr<Subscription>& s : subscribers_) {
        std::lock_guard queueLock(s->mutex_);
        if (s->queue_.size() >= kMaxQueued) s->queue_.pop_front();
        s->queue_.push_back(event);
        s->ready_.notify_one();
    }
}

std::shared_ptr<EventHub::Subscription> EventHub::subscribe() {
    auto subscription = std::make_shared<Subscription>();
    std::lock_guard lock(mutex_);
    subscription->closed_ = closed_;
    std::vector<std::pair<uint64_t, std::string>> replay;
    for (const auto& [name, event] : latest_) replay.push_back(event);
    std::sort(replay.begin(), replay.end());
    for (auto& [order, event] : replay) subscription->queue_.push_back(std::move(event));
    subscribers_.push_back(subscription);
    return subscription;
}

void EventHub::unsubscribe(const std::shared_ptr<Subscription>& subscription) {
    std::lock_guard lock(mutex_);
    std::erase(subscribers_, subscription);
}

void EventHub::close() {
    std::lock_guard lock(mutex_);
    closed_ = true;
    for (const std::shared_ptr<Subscription>& s : subscribers_) {
        std::lock_guard queueLock(s->mutex_);
        s->closed_ = true;
        s->ready_.notify_all();
    }
}

} // namespace crt::crtc::preview
