// A frame worker's line to rank 0's dispatcher: MPI messages from another process, or a pair of
// queues for the worker that runs on rank 0 itself, beside the dispatcher.
#pragma once

#include "mpi_session.hpp"

#include <deque>
#include <mutex>
#include <utility>
#include <vector>

namespace crt::crtc::distributed {

class FrameLink {
  public:
    virtual ~FrameLink() = default;
    /// Sends a message to rank 0's dispatcher.
    virtual void send(Tag tag, const void* data, size_t bytes) = 0;
    /// Takes the dispatcher's next message to this worker, if one waits.
    virtual bool take(int& tag, std::vector<char>& message) = 0;
};

/// The link of a rank other than 0: MPI, called from its main thread only.
class MpiFrameLink final : public FrameLink {
  public:
    explicit MpiFrameLink(MpiSession& session) : session_(session) {}
    void send(Tag tag, const void* data, size_t bytes) override {
        session_.send(0, tag, data, bytes);
    }
    bool take(int& tag, std::vector<char>& message) override {
        int source = 0, bytes = 0;
        if (!session_.poll(source, tag, bytes)) return false;
        message = session_.receive(source, tag);
        return true;
    }

  private:
    MpiSession& session_;
};

/// The link of rank 0's own worker: messages both ways through queues, so that the worker's
/// thread never calls MPI (the dispatcher, on the main thread, reads them with its MPI messages).
class LocalFrameLink final : public FrameLink {
  public:
    void send(Tag tag, const void* data, size_t bytes) override {
        push(toDispatcher_, tag, data, bytes);
    }
    bool take(int& tag, std::vector<char>& message) override {
        return pop(toWorker_, tag, message);
    }
    /// The dispatcher's side.
    void sendToWorker(Tag tag, const void* data, size_t bytes) {
        push(toWorker_, tag, data, bytes);
    }
    bool takeFromWorker(int& tag, std::vector<char>& message) {
        return pop(toDispatcher_, tag, message);
    }

  private:
    using Queue = std::deque<std::pair<int, std::vector<char>>>;
    void push(Queue& queue, Tag tag, const void* data, size_t bytes) {
        const char* begin = static_cast<const char*>(data);
        std::lock_guard lock(mutex_);
        queue.emplace_back(tag,
                           bytes ? std::vector<char>(begin, begin + bytes) : std::vector<char>());
    }
    bool pop(Queue& queue, int& tag, std::vector<char>& message) {
        std::lock_guard lock(mutex_);
        if (queue.empty()) return false;
        tag = queue.front().first;
        message = std::move(queue.front().second);
        queue.pop_front();
        return true;
    }

    std::mutex mutex_;
    Queue toDispatcher_, toWorker_;
};

} // namespace crt::crtc::distributed
