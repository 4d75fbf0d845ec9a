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

void DiagnosticBag::sortByPosition(size_t first) {
    std::stable_sort(items_.begin() + static_cast<std::ptrdiff_t>(first), items_.end(),
                     [](const Diagnostic& a, const Diagnostic& b) {
                         return std::pair(a.range.file, a.range.begin) <
                                std::pair(b.range.file, b.range.begin);
                     });
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
    // Optimal string alignment: insertions, deletions, substitutions and swaps of two
    // neighbouring letters ("widht"), each one edit; letter case is ignored.
    auto same = [](char x, char y) {
        return std::tolower(static_cast<unsigned char>(x)) ==
               std::tolower(static_cast<unsigned char>(y));
    };
    std::vector<size_t> before(b.size() + 1), previous(b.size() + 1), row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        before.swap(previous);
        previous.swap(row);
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            row[j] = std::min({previous[j] + 1, row[j - 1] + 1,
                               previous[j - 1] + (same(a[i - 1], b[j - 1]) ? 0 : 1)});
            if (i > 1 && j > 1 && same(a[i - 1], b[j - 2]) && same(a[i - 2], b[j - 1]))
                row[j] = std::min(row[j], before[j - 2] + 1);
        }
    }
    return row[b.size()];
}

} // namespace

std::string closestMatch(std::string_view word, const std::vector<std::string_view>& candidates) {
    // Allow one typo per three characters, at least one: more would suggest far-fetched
    // names for short words (Cube for Cone).
    size_t best = std::max<size_t>(1, word.size() / 3) + 1;
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
