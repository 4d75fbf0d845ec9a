// Layout of crtc's --help.
#include "help_formatter.hpp"

namespace crt::crtc {

namespace {

constexpr size_t kNameColumn = 26;
constexpr size_t kLineWidth = 80;

/// `text` broken into lines of at most `width` characters, at spaces.
std::string wrap(const std::string& text, size_t width) {
    std::string out, line;
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find(' ', start);
        if (end == std::string::npos) end = text.size();
        const std::string word = text.substr(start, end - start);
        if (!line.empty() && line.size() + 1 + word.size() > width) {
            out += line + "\n";
            line.clear();
        }
        line += (line.empty() ? "" : " ") + word;
        start = end + 1;
    }
    return out + line;
}

} // namespace

HelpFormatter::HelpFormatter() {
    column_width(kNameColumn);
}

std::string HelpFormatter::make_option_opts(const CLI::Option* option) const {
    if (option->get_type_size() == 0) return ""; // a flag
    return " " + option->get_type_name();
}

std::string HelpFormatter::make_option_desc(const CLI::Option* option) const {
    return wrap(option->get_description(), kLineWidth - kNameColumn);
}

} // namespace crt::crtc
