// Static name resolution (spec §4 "Scopes"): binds every name to a slot before evaluation,
// checks object types and attribute names, and finds unused macro locals.
#pragma once

#include "ast.hpp"
#include "diagnostic.hpp"

#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace crt::lang {

/// The global scope shared by a script and the files it includes.
class GlobalTable {
public:
    struct Entry {
        std::string name;
        bool assigned = false;      ///< some resolved file assigns it at top level
        bool read = false;          ///< some resolved expression reads it
        bool reportUnused = false;  ///< first assigned in the main file
        SourceRange firstAssignment{};
    };

    uint32_t slotFor(std::string_view name);
    const Entry* find(std::string_view name) const;
    Entry& entry(uint32_t slot) { return entries_[slot]; }
    const Entry& entry(uint32_t slot) const { return entries_[slot]; }
    uint32_t size() const { return static_cast<uint32_t>(entries_.size()); }

private:
    std::unordered_map<std::string, uint32_t> slots_;
    std::vector<Entry> entries_;
};

struct ResolveResult {
    bool readsTime = false; ///< the file reads t or clock (it is animated)
};

/// Resolves `script` against `globals`. `isMainFile` decides whether unused globals of
/// this file are reported later. Errors and warnings go to `diagnostics`.
ResolveResult resolve(Script& script, GlobalTable& globals, DiagnosticBag& diagnostics,
                      bool isMainFile);

} // namespace crt::lang
