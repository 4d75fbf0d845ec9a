// Text forms of numbers and strings shared by str(), print and the dumps.
#pragma once

#include <string>
#include <string_view>

namespace crt::lang {

/// The shortest text that reads back as exactly `x`, with ".0" added when it would
/// otherwise look like an int (`0.5`, `2.0`, `1e+20`, `inf`, `nan`).
std::string formatFloat(double x);
/// `text` in double quotes with its escapes written back.
std::string quoted(std::string_view text);

} // namespace crt::lang
