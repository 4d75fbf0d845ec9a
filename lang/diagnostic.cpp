// Diagnostic collection and "did you mean" suggestions.
#include "diagnostic.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

namespace crt::lang {

Diagnostic& DiagnosticBag::error(SourceRange range, std::string message) {
    ++errorCount_;
    items_.push_back({Severity::Error, range, std::move(message), {}, {}, WarningKind::None});
    return items_.back();
}

Diagnostic& DiagnosticBag::warning(WarningKind kind, SourceRange range, std::string message) {
    items_.push_back({Severity::Warning, range, std::move(message), {}, {}, kind});
    return items_.back();
}

void DiagnosticBag::promoteWarnings() {
    for (Diagnostic& d : items_) {
        if (d.severity == Severity::Warning) {
            d.severity = Severity::Error;
            ++errorCount_;
        }
    }
}

namespace {

size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            size_t above = row[j];
            bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

} // namespace

std::string closestMatch(std::string_view word, const std::vector<std::string_view>& candidates) {
    // Allow about one typo per three characters, as clang's typo correction does.
    size_t best = std::max<size_t>(1, (word.size() + 2) / 3) + 1;
    std::string_view found;
    for (std::string_view candidate : candidates) {
        size_t distance = editDistance(word, candidate);
        if (distance < best) {
            best = distance;
            found = candidate;
        }
    }
    return std::string(found);
}

void addCallNote(Diagnostic& d, DiagnosticNote note) {
    std::vector<DiagnosticNote>& notes = d.notes;
    if (notes.size() < 2 * kCallNotesShown) {
        notes.push_back(std::move(note));
        return;
    }
    // notes: the first kCallNotesShown, the count left out (once there is one), the last
    // kCallNotesShown. The oldest of the last ones joins those left out.
    if (d.hiddenNotes == 0) notes.insert(notes.begin() + kCallNotesShown, DiagnosticNote{});
    const auto oldestLast = notes.begin() + kCallNotesShown + 1;
    const SourceRange left = oldestLast->range;
    notes.erase(oldestLast);
    ++d.hiddenNotes;
    notes[kCallNotesShown] = {left, fmt::format("{} more call{} not shown", d.hiddenNotes, d.hiddenNotes == 1 ? "" : "s")};
    notes.push_back(std::move(note));
}

} // namespace crt::lang
