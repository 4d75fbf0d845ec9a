// The preview's HTTP routes (see server.hpp and docs/preview.md).
#include "preview/server.hpp"

#include "preview/camera_controls.hpp"
#include "preview/camera_json.hpp"
#include "preview/camera_writer.hpp"
#include "preview_page.hpp"

#include <fmt/format.h>
#include <httplib.h>
#include <sys/socket.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <random>
#include <stdexcept>

namespace crt::crtc::preview {

namespace {

using nlohmann::json;

/// How long an event stream waits before it checks that its page is still there.
constexpr auto kEventPoll = std::chrono::milliseconds(1000);

void replyJson(httplib::Response& res, const json& body, int status = 200) {
    res.status = status;
    res.set_header("Cache-Control", "no-store");
    res.set_content(pageJson(body), "application/json");
}

void replyError(httplib::Response& res, const std::string& message, int status = 400) {
    replyJson(res, {{"error", message}}, status);
}

/// Why cpp-httplib refused a request with `status`, in the API's words.
std::string errorReason(const httplib::Request& req, int status) {
    switch (status) {
    case 404: return fmt::format("no such request: {} {}", req.method, req.path);
    case 405: return fmt::format("{} is not a method of {}", req.method, req.path);
    case 411: return "a POST needs a body (send {} when there is nothing to say)";
    case 413: return "the body is too large";
    case 400: return "bad request (a POST needs a body: send {} when there is nothing to say)";
    default: return fmt::format("refused with status {}", status);
    }
}

/// The request's JSON body; throws std::invalid_argument when it is not a JSON object.
json bodyOf(const httplib::Request& req) {
    json body = json::parse(req.body, nullptr, false);
    if (body.is_discarded() || !body.is_object()) throw std::invalid_argument("the body must be a JSON object");
    return body;
}

double numberIn(const json& body, const char* name, double fallback) {
    if (!body.contains(name)) return fallback;
    const json& value = body[name];
    if (!value.is_number() || !std::isfinite(value.get<double>()))
        throw std::invalid_argument(std::string(name) + " must be a finite number");
    return value.get<double>();
}

/// A number of the request's query (`fallback` when absent).
double queryNumber(const httplib::Request& req, const char* name, double fallback) {
    if (!req.has_param(name)) return fallback;
    const std::string text = req.get_param_value(name);
    double value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        throw std::invalid_argument(std::string(name) + " must be a finite number");
    return value;
}

/// Runs a handler that reads a JSON body; bad input becomes a 400 with its reason.
template <typename Handler> httplib::Server::Handler withJson(Handler handler) {
    return [handler](const httplib::Request& req, httplib::Response& res) {
        try {
            handler(bodyOf(req), res);
        } catch (const std::exception& e) {
            replyError(res, e.what());
        }
    };
}

/// Compares without stopping at the first difference, so timing does not leak the token.
bool sameSecret(const std::string& a, const std::string& b) {
    if (a.size() != b.size()) return false;
    unsigned char difference = 0;
    for (size_t i = 0; i < a.size(); ++i) difference |= static_cast<unsigned char>(a[i] ^ b[i]);
    return difference == 0;
}

} // namespace

std::string pageJson(const json& value) {
    return value.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string newToken() {
    std::random_device device;
    std::string token;
    for (int i = 0; i < 4; ++i) token += fmt::format("{:08x}", device());
    return token;
}

Server::Server(Session& session, EventHub& events, std::string token, std::function<void()> onQuit)
    : session_(session), events_(events), token_(std::move(token)), onQuit_(std::move(onQuit)),
      http_(std::make_unique<httplib::Server>()) {
    // Event streams hold a thread each: room for a few pages beside their requests.
    http_->new_task_queue = [] { return new httplib::ThreadPool(16); };
    http_->set_payload_max_length(1 << 16);
    // cpp-httplib's own options add SO_REUSEPORT, with which a second preview could listen on
    // the same port and take half of the first one's requests. SO_REUSEADDR alone lets a
    // preview start again on a port whose last connections are closing, but not a taken one.
    http_->set_socket_options([](socket_t sock) {
        int yes = 1;
        setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    });
    http_->set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
        if (allowed(req.get_header_value("Host"), req.get_header_value("Origin"), req.get_param_value("token")))
            return httplib::Server::HandlerResponse::Unhandled;
        replyError(res, "forbidden: open the URL crtc --preview printed", 403);
        return httplib::Server::HandlerResponse::Handled;
    });
    // What cpp-httplib answers by itself (no such path, no body) is an API error like ours.
    http_->set_error_handler(httplib::Server::HandlerWithResponse(
        [](const httplib::Request& req, httplib::Response& res) {
            if (!res.body.empty()) return httplib::Server::HandlerResponse::Unhandled;
            replyError(res, errorReason(req, res.status), res.status);
            return httplib::Server::HandlerResponse::Handled;
        }));
    addRoutes();
    addCameraRoutes();
}

Server::~Server() = default;

bool Server::allowed(const std::string& host, const std::string& origin, const std::string& token) const {
    const std::string ip = fmt::format("127.0.0.1:{}", port_), name = fmt::format("localhost:{}", port_);
    if (host != ip && host != name) return false;
    if (!origin.empty() && origin != "http://" + ip && origin != "http://" + name) return false;
    return sameSecret(token, token_);
}

bool Server::bind(int port, std::string& error) {
    errno = 0;
    port_ = port == 0 ? http_->bind_to_any_port("127.0.0.1") : (http_->bind_to_port("127.0.0.1", port) ? port : -1);
    if (port_ > 0) return true;
    if (port == 0)
        error = "cannot listen on 127.0.0.1";
    else if (errno == EADDRINUSE)
        error = fmt::format("cannot listen on 127.0.0.1:{}: the port is taken (another preview or "
                            "program listens on it); choose another with --port, or --port 0 "
                            "for a free one",
                            port);
    else
        error = fmt::format("cannot listen on 127.0.0.1:{}{}", port,
                            errno != 0 ? fmt::format(": {}", std::strerror(errno)) : "");
    return false;
}

void Server::serve() { http_->listen_after_bind(); }

void Server::stop() { http_->stop(); }

void Server::addRoutes() {
    http_->Get("/", [](const httplib::Request&, httplib::Response& res) {
        res.set_header("Cache-Control", "no-store");
        res.set_header("Referrer-Policy", "no-referrer"); // the URL holds the token
        res.set_header("X-Frame-Options", "DENY");
        res.set_header("Content-Security-Policy",
                       "default-src 'none'; img-src 'self' blob:; style-src 'unsafe-inline'; "
                       "script-src 'unsafe-inline'; connect-src 'self'; frame-ancestors 'none'");
        res.set_content(std::string(kPreviewPage), "text/html; charset=utf-8");
    });
    http_->Get("/api/frame.png", [this](const httplib::Request&, httplib::Response& res) {
        std::shared_ptr<const FrameImage> image = session_.latestImage();
        if (!image) return replyError(res, "no image yet", 404);
        res.set_header("Cache-Control", "no-store");
        res.set_header("X-Frame-Number", std::to_string(image->number));
        res.set_header("X-Frame-Pass", fmt::format("{}/{}", image->pass, image->passes));
        res.set_header("X-Frame-Final", image->final ? "true" : "false");
        if (image->paths > 0) res.set_header("X-Frame-Paths", fmt::format("{:.2f}", image->paths));
        res.set_content(reinterpret_cast<const char*>(image->png.data()), image->png.size(), "image/png");
    });
    http_->Get("/api/viewport.png", [this](const httplib::Request& req, httplib::Response& res) {
        Viewport view;
        try {
            const std::optional<ViewportAxis> axis = viewportAxis(req.get_param_value("view"));
            if (!axis) throw std::invalid_argument("view must be top, front or side");
            view.axis = *axis;
            view.across = queryNumber(req, "across", 0);
            view.up = queryNumber(req, "up", 0);
            view.width = queryNumber(req, "width", 10);
            if (!(view.width > 0)) throw std::invalid_argument("width must be above 0");
            const double pixels = queryNumber(req, "pixels", 240), lines = queryNumber(req, "lines", 180);
            for (double size : {pixels, lines})
                if (size != std::floor(size) || size < 1 || size > kMostViewportPixels)
                    throw std::invalid_argument(fmt::format("pixels and lines must be whole numbers from 1 to {}",
                                                            kMostViewportPixels));
            view.pixels = static_cast<int>(pixels);
            view.lines = static_cast<int>(lines);
        } catch (const std::invalid_argument& e) {
            return replyError(res, e.what(), 400);
        }
        std::string error;
        const std::vector<std::uint8_t> png = session_.viewport(view, error);
        if (png.empty()) return replyError(res, error, 404);
        res.set_header("Cache-Control", "no-store");
        res.set_content(reinterpret_cast<const char*>(png.data()), png.size(), "image/png");
    });
    http_->Get("/api/state", [this](const httplib::Request&, httplib::Response& res) { replyJson(res, session_.state()); });
    http_->Get("/api/events", [this](const httplib::Request&, httplib::Response& res) {
        std::shared_ptr<EventHub::Subscription> subscription = events_.subscribe();
        res.set_header("Cache-Control", "no-store");
        res.set_chunked_content_provider(
            "text/event-stream",
            [subscription](size_t, httplib::DataSink& sink) {
                std::optional<std::string> event = subscription->next(kEventPoll);
                if (!event || !sink.is_writable()) return false;
                return sink.write(event->data(), event->size());
            },
            [this, subscription](bool) { events_.unsubscribe(subscription); });
    });
    http_->Post("/api/quality", withJson([this](const json& body, httplib::Response& res) {
        ViewQuality quality;
        if (body.contains("draft")) {
            if (!body["draft"].is_boolean()) throw std::invalid_argument("draft must be true or false");
            quality.draft = body["draft"].get<bool>();
        }
        quality.scale = numberIn(body, "scale", 1);
        if (quality.scale < 1.0 / 16 || quality.scale > 1) throw std::invalid_argument("scale must be in [1/16, 1]");
        session_.setQuality(quality);
        replyJson(res, session_.state());
    }));
    http_->Post("/api/frame", withJson([this](const json& body, httplib::Response& res) {
        const double frame = numberIn(body, "frame", 0);
        if (frame != std::floor(frame)) throw std::invalid_argument("frame must be an integer");
        session_.setFrame(static_cast<int>(std::clamp(frame, -1e9, 1e9)));
        replyJson(res, session_.state());
    }));
    http_->Post("/api/pick", withJson([this](const json& body, httplib::Response& res) {
        const double x = numberIn(body, "x", -1), y = numberIn(body, "y", -1);
        if (x < 0 || x > 1 || y < 0 || y > 1) throw std::invalid_argument("x and y must be in [0, 1]");
        replyJson(res, session_.pick(x, y));
    }));
    http_->Post("/api/quit", [this](const httplib::Request&, httplib::Response& res) {
        replyJson(res, {{"quitting", true}});
        onQuit_();
    });
}

void Server::addCameraRoutes() {
    http_->Get("/api/camera", [this](const httplib::Request&, httplib::Response& res) {
        replyJson(res, cameraJson(session_.camera()));
    });
    http_->Get("/api/camera.crt", [this](const httplib::Request&, httplib::Response& res) {
        res.set_header("Cache-Control", "no-store");
        res.set_content(cameraLiteral(session_.camera()) + "\n", "text/plain; charset=utf-8");
    });
    http_->Post("/api/camera", withJson([this](const json& body, httplib::Response& res) {
        cameraFromJson(session_.camera(), body); // refuses bad values before anything changes
        const bool interactive = body.value("interactive", false);
        replyJson(res, cameraJson(session_.changeCamera(
                           [&](scene::CameraDesc c) { return cameraFromJson(c, body); }, interactive)));
    }));
    http_->Post("/api/camera/move", withJson([this](const json& body, httplib::Response& res) {
        const double yaw = numberIn(body, "orbitX", 0), pitch = numberIn(body, "orbitY", 0);
        const double right = numberIn(body, "panX", 0), up = numberIn(body, "panY", 0);
        const double factor = numberIn(body, "dolly", 1), fov = numberIn(body, "fov", 0);
        if (!(factor > 0)) throw std::invalid_argument("dolly must be positive");
        const bool interactive = body.value("interactive", false);
        replyJson(res, cameraJson(session_.changeCamera(
                           [&](scene::CameraDesc c) {
                               c = dolly(pan(orbit(c, yaw, pitch), right, up), factor);
                               return fov > 0 ? withFov(c, fov) : c;
                           },
                           interactive)));
    }));
    http_->Post("/api/camera/reset", [this](const httplib::Request&, httplib::Response& res) {
        session_.resetCamera();
        replyJson(res, cameraJson(session_.camera()));
    });
    http_->Post("/api/camera/write", [this](const httplib::Request&, httplib::Response& res) {
        const CameraEdit edit = session_.writeCamera();
        replyJson(res, {{"written", edit.ok}, {"message", edit.message}});
    });
}

} // namespace crt::crtc::preview
