// crtc --preview (see preview_command.hpp): wires the session, the server and the signals.
#include "preview/preview_command.hpp"

#include "preview/event_hub.hpp"
#include "preview/server.hpp"
#include "preview/session.hpp"

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <thread>

namespace crt::crtc {

namespace {

std::atomic<bool> stopRequested{false};

extern "C" void onPreviewStopSignal(int) { stopRequested.store(true); }

/// Opens `url` in the desktop's browser, without waiting for it.
void openInBrowser(const std::string& url) {
    // The URL is made of the loopback address, a port number and a hex token: safe to quote.
    const std::string command = "xdg-open '" + url + "' >/dev/null 2>&1 &";
    if (std::system(command.c_str()) != 0) std::cerr << "crtc: could not run xdg-open\n";
}

} // namespace

int previewCommand(const Options& options) {
    preview::EventHub events;
    preview::Session session(options, [&](const std::string& name, const nlohmann::json& data) {
        events.publish(name, preview::pageJson(data));
    });
    preview::Server server(session, events, preview::newToken(), [] { stopRequested.store(true); });
    std::string error;
    if (!server.bind(options.port, error)) {
        std::cerr << "crtc: " << error << "\n";
        return 2;
    }
    std::signal(SIGINT, onPreviewStopSignal);
    std::signal(SIGTERM, onPreviewStopSignal);
    std::thread serving([&] { server.serve(); });
    session.start();

    const std::string url = "http://127.0.0.1:" + std::to_string(server.port()) + "/?token=" + server.token();
    std::cout << "preview: " << url << std::endl;
    if (options.open) openInBrowser(url);

    while (!stopRequested.load()) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    events.close();
    server.stop();
    serving.join();
    return 0;
}

} // namespace crt::crtc
