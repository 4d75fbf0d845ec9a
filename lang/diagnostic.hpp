// Diagnostics: errors, warnings and notes with source ranges and fix-its.
#pragma once

#include "source_file.hpp"

#include <string>
#include <vector>

namespace crt::lang {

enum class Severity { Error, Warning, Note };

/// A suggested edit: replace `range` with `replacement`.
struct FixIt {
    SourceRange range;
    std::string replacement;
};

struct DiagnosticNote {
    SourceRange range;
    std::string message;
};

/// Stable identifiers for warnings, so tools can tell them apart.
enum class WarningKind {
    None,
    UnusedVariable,
    EntityNeverDrawn,
    UnusedLight,
    DuplicateAttribute,
    ValueNotDrawn,
    ShadowedBuiltin,
    ZeroSizeEntity,
    EmptyScene,
    DivisionByZero,
    OutsideScene,
    NoLights,
    MissingGlyph,
};

struct Diagnostic {
    Severity severity = Severity::Error;
    SourceRange range;
    std::string message;
    std::vector<DiagnosticNote> notes;
    std::vector<FixIt> fixits;
    WarningKind warning = WarningKind::None;
    uint32_t hiddenNotes = 0; ///< notes of a long chain left out (addCallNote)
};

/// The notes shown at each end of a long chain of call notes (innermost first).
inline constexpr size_t kCallNotesShown = 5;
/// Adds the note of the next call out of a chain that can be long (a recursion 200,000 calls
/// deep): the first and the last kCallNotesShown notes are kept, and one note between them
/// says how many calls were left out, as compilers cap their backtraces.
void addCallNote(Diagnostic& d, DiagnosticNote note);

/// Collects diagnostics in the order they are reported.
class DiagnosticBag {
public:
    Diagnostic& error(SourceRange range, std::string message);
    Diagnostic& warning(WarningKind kind, SourceRange range, std::string message);
    void add(Diagnostic diagnostic) {
        if (diagnostic.severity == Severity::Error) ++errorCount_;
        items_.push_back(std::move(diagnostic));
    }

    const std::vector<Diagnostic>& items() const { return items_; }
    std::vector<Diagnostic>& items() { return items_; }
    bool hasErrors() const { return errorCount_ > 0; }
    size_t errorCount() const { return errorCount_; }
    /// Turns every warning into an error (-Werror).
    void promoteWarnings();
    /// Puts the diagnostics from index `first` on in source order (file, then offset).
    void sortByPosition(size_t first = 0);

private:
    std::vector<Diagnostic> items_;
    size_t errorCount_ = 0;
};

/// The candidate closest to `word` by edit distance, or "" when none is close enough to be
/// a plausible typo.
std::string closestMatch(std::string_view word, const std::vector<std::string_view>& candidates);

} // namespace crt::lang
