// How `crtc --help` lays out its options: descriptions wrapped to 80 columns, an option's value
// named without CLI11's notes on exclusions and validators.
#pragma once

#include <CLI/CLI.hpp>

namespace crt::crtc {

class HelpFormatter : public CLI::Formatter {
public:
    HelpFormatter();

    std::string make_option_opts(const CLI::Option* option) const override;
    std::string make_option_desc(const CLI::Option* option) const override;
};

} // namespace crt::crtc
