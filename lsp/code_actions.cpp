// One quick fix per fix-it; the title says what the edit does.
#include "code_actions.hpp"

#include <fmt/format.h>

namespace crt::lsp {

std::vector<CodeAction> codeActions(const std::vector<DocumentDiagnostic>& diagnostics, std::string_view text,
                                    uint32_t begin, uint32_t end) {
    std::vector<CodeAction> result;
    for (size_t i = 0; i < diagnostics.size(); ++i) {
        const DocumentDiagnostic& d = diagnostics[i];
        if (d.range.end < begin || d.range.begin > end) continue;
        for (const lang::FixIt& fix : d.fixits) {
            if (fix.range.end > text.size() || fix.range.begin > fix.range.end) continue;
            std::string title;
            std::string trimmed = fix.replacement;
            while (!trimmed.empty() && trimmed.back() == ' ') trimmed.pop_back();
            if (fix.range.begin == fix.range.end) {
                title = fmt::format("Insert '{}'", trimmed);
                if (d.message.find("missing its required attribute") != std::string::npos) {
                    title = fmt::format("Add the missing attribute '{}'", trimmed);
                }
            } else {
                title = fmt::format("Change '{}' to '{}'", text.substr(fix.range.begin, fix.range.end - fix.range.begin),
                                    trimmed);
            }
            result.push_back({title, {{fix.range, fix.replacement}}, i, d.fixits.size() == 1});
        }
    }
    return result;
}

} // namespace crt::lsp
