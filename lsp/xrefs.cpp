// Symbols come from the index; globals also match by name in included files.
#include "xrefs.hpp"

#include "builtins.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

namespace crt::lsp {

using namespace lang;

namespace {

const Occurrence* occurrenceFor(const Analysis& a, uint32_t offset) {
    const Occurrence* o = a.occurrenceAt(offset);
    if (!o) return nullptr;
    return o;
}

bool isGlobal(const Symbol& s) { return !s.scope && !s.builtin(); }

} // namespace

std::vector<Location> definition(const Analysis& a, uint32_t offset) {
    const Occurrence* o = occurrenceFor(a, offset);
    if (!o) {
        // An include's string: go to the file.
        int index = a.tokenAt(offset);
        if (index > 0 && a.tokens[static_cast<size_t>(index)].kind == TokenKind::String &&
            a.tokens[static_cast<size_t>(index - 1)].kind == TokenKind::KwInclude) {
            const Token& t = a.tokens[static_cast<size_t>(index)];
            std::string name(a.text(t).substr(1, t.end - t.begin >= 2 ? t.end - t.begin - 2 : 0));
            std::error_code error;
            for (const auto& included : a.includes) {
                if (std::filesystem::path(included->path).filename() == std::filesystem::path(name).filename()) {
                    return {{included->file.get(), {0, 0, 0}}};
                }
            }
        }
        return {};
    }
    const Symbol& s = a.symbols[o->symbol];
    if (s.definition) return {{&a.file(), *s.definition}};
    if (s.external >= 0) {
        const ExternalSymbol& e = a.externals[static_cast<size_t>(s.external)];
        return {{e.file->file.get(), e.range}};
    }
    return {};
}

std::vector<Location> references(const Analysis& a, uint32_t offset, bool includeDeclaration) {
    const Occurrence* o = occurrenceFor(a, offset);
    if (!o) return {};
    const Symbol& s = a.symbols[o->symbol];
    std::vector<Location> result;
    for (const auto& included : a.includes) {
        if (!isGlobal(s)) break;
        for (const IncludedFile::Mention& m : included->mentions) {
            if (m.name == s.name && (includeDeclaration || !m.definition)) result.push_back({included->file.get(), m.range});
        }
    }
    for (const Occurrence& other : a.occurrences) {
        if (other.symbol == o->symbol && (includeDeclaration || !other.definition)) result.push_back({&a.file(), other.range});
    }
    return result;
}

std::vector<Highlight> documentHighlights(const Analysis& a, uint32_t offset) {
    const Occurrence* o = occurrenceFor(a, offset);
    if (!o) return {};
    std::vector<Highlight> result;
    for (const Occurrence& other : a.occurrences) {
        if (other.symbol == o->symbol) result.push_back({other.range, other.write});
    }
    return result;
}

RenameCheck prepareRename(const Analysis& a, uint32_t offset, const AnalysisOptions& options) {
    const Occurrence* o = occurrenceFor(a, offset);
    if (!o) return {std::nullopt, "", "there is no variable, parameter or macro here"};
    const Symbol& s = a.symbols[o->symbol];
    if (s.builtin()) return {std::nullopt, "", "built-ins cannot be renamed"};
    if (isGlobal(s) && !options.includes.stdlibDir.empty()) {
        std::error_code error;
        auto stdlib = std::filesystem::weakly_canonical(options.includes.stdlibDir, error).string();
        for (const auto& included : a.includes) {
            auto path = std::filesystem::weakly_canonical(included->path, error).string();
            if (!path.starts_with(stdlib)) continue;
            for (const IncludedFile::Mention& m : included->mentions) {
                if (m.name == s.name) return {std::nullopt, "", fmt::format("'{}' is used by the standard library", s.name)};
            }
        }
    }
    return {o->range, s.name, ""};
}

RenameResult rename(const Analysis& a, uint32_t offset, std::string_view newName,
                    const AnalysisOptions& options) {
    RenameCheck check = prepareRename(a, offset, options);
    if (!check.range) return {{}, check.error};
    bool valid = !newName.empty() && newName[0] >= 'a' && newName[0] <= 'z' &&
                 std::all_of(newName.begin(), newName.end(), [](char c) {
                     return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
                 });
    static constexpr std::string_view keywords[] = {"scale", "translate", "rotate", "true", "false", "while",
                                                   "for", "in", "if", "else", "include"};
    if (!valid || std::find(std::begin(keywords), std::end(keywords), newName) != std::end(keywords)) {
        return {{}, fmt::format("'{}' is not a valid variable name", newName)};
    }
    const Occurrence* o = a.occurrenceAt(offset);
    const Symbol& s = a.symbols[o->symbol];
    // A new name already visible at a mention would capture it.
    for (const Occurrence& other : a.occurrences) {
        if (other.symbol != o->symbol) continue;
        const Symbol* clash = a.lookup(newName, other.range.begin);
        if (clash && clash != &s && !clash->builtin()) {
            return {{}, fmt::format("'{}' is already defined here", newName)};
        }
    }
    return {references(a, offset, true), ""};
}

} // namespace crt::lsp
