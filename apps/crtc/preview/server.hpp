// The preview's HTTP server: the page, its events and its actions (docs/preview.md), on
// 127.0.0.1 only, for requests that carry the token and come from the preview's own origin.
#pragma once

#include "preview/event_hub.hpp"
#include "preview/session.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <functional>
#include <memory>
#include <string>

namespace httplib {
class Server;
}

namespace crt::crtc::preview {

class Server {
public:
    /// `onQuit` is called (from a server thread) when the page asks the preview to stop.
    Server(Session& session, EventHub& events, std::string token, std::function<void()> onQuit);
    ~Server();
    Server(const Server&) = delete;
    Server& operator=(const Server&) = delete;

    /// Binds 127.0.0.1:`port` (0: a free port); false, with `error` set, if it cannot.
    bool bind(int port, std::string& error);
    int port() const { return port_; }
    const std::string& token() const { return token_; }
    /// Serves until stop(); call from its own thread.
    void serve();
    void stop();

private:
    void addRoutes();
    void addCameraRoutes();
    /// Whether the request comes from the preview's page: the right Host (no DNS rebinding),
    /// no foreign Origin, and the token.
    bool allowed(const std::string& host, const std::string& origin, const std::string& token) const;

    Session& session_;
    EventHub& events_;
    std::string token_;
    std::function<void()> onQuit_;
    std::unique_ptr<httplib::Server> http_;
    int port_ = 0;
};

/// `value` as JSON text for the page. A script's strings and paths may hold bytes that are not
/// UTF-8, which JSON cannot carry: each becomes U+FFFD.
std::string pageJson(const nlohmann::json& value);

/// A new random token: 128 bits from the system's random source, in hex.
std::string newToken();

} // namespace crt::crtc::preview
