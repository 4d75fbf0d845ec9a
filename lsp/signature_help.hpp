// Signature help for calls of built-ins and macros.
#pragma once

#include "analysis.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace crt::lsp {

struct SignatureHelp {
    std::string label;                                   ///< "rgb(r, g, b)"
    std::vector<std::pair<uint32_t, uint32_t>> parameters; ///< byte ranges in `label`
    std::string documentation;
    uint32_t activeParameter = 0;
};

/// The signature of the call whose argument list holds `offset`, if the callee is known.
std::optional<SignatureHelp> signatureHelp(const Analysis& analysis, uint32_t offset);

} // namespace crt::lsp
