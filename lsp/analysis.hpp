// One document's analysis: the front end's AST, tokens and resolution, indexed for the features.
// No LSP types here: positions are byte offsets into the document's SourceFile.
#pragma once

#include "interpreter.hpp"
#include "lexer.hpp"

#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace crt::lsp {

/// How the server runs the front end; set from the command line and initializationOptions.
/// Tighter than crtc's defaults: an editor wants an answer, not a finished render. The
/// primitive count costs no expansion, so that limit stays crtc's, as do the others.
inline lang::Limits editorLimits() {
    lang::Limits limits;
    limits.maxSteps = 5'000'000;
    limits.maxEntities = 1'000'000;
    limits.maxMemory = uint64_t{512} << 20;
    return limits;
}

struct AnalysisOptions {
    lang::IncludeSearch includes; ///< as crtc's -I and standard library
    std::vector<std::string> assetRoots; ///< as crtc's --assets
    /// What a script may read beyond its roots (crtc's --allow-read); the workspace folders
    /// are added to allowRead.
    lang::ReadPermissions access{{}, false, "the setting allowRead (or allowReadAll)"};
    lang::Limits limits = editorLimits();
    std::chrono::milliseconds timeBudget{1500}; ///< wall-clock limit of one evaluation
};

enum class SymbolKind : uint8_t { Variable, Parameter, LoopVariable, Macro, Builtin };

/// A name the resolver bound: a global, a macro local or parameter, or a built-in.
struct Symbol {
    std::string name;
    SymbolKind kind = SymbolKind::Variable;
    /// The macro owning a local, or the Function a parameter; null for globals.
    const lang::Expr* scope = nullptr;
    std::optional<lang::SourceRange> definition; ///< first binding in this document
    const lang::Expr* value = nullptr;        ///< what the definition assigns, if an assignment
    int external = -1; ///< index into Analysis::externals when first bound in an included file
    bool builtin() const { return kind == SymbolKind::Builtin; }
};

/// One mention of a symbol in the document.
struct Occurrence {
    lang::SourceRange range;
    uint32_t symbol;
    bool write = false;      ///< assigned here (or a parameter, or a loop variable)
    bool definition = false; ///< the first binding
};

/// An attribute name in an object literal or the Settings block.
struct AttributeUse {
    lang::SourceRange nameRange;
    lang::ObjectType type;
    int slot; ///< -1: unknown attribute
};

/// A file reached through `include`, parsed once and kept while it does not change.
struct IncludedFile {
    std::string path;
    std::unique_ptr<lang::SourceFile> file;
    std::unique_ptr<lang::Arena> arena;
    lang::Script script;
    std::vector<std::string> includes; ///< the include names it holds, in order
    /// Top-level names: every mention, the first binding of each marked.
    struct Mention {
        std::string name;
        lang::SourceRange range;
        bool definition;
        const lang::Expr* value; ///< for a definition, what it assigns
    };
    std::vector<Mention> mentions;
};

/// A global first bound in an included file.
struct ExternalSymbol {
    std::string name;
    std::shared_ptr<const IncludedFile> file;
    lang::SourceRange range;
    const lang::Expr* value = nullptr;
};

/// Parses included files and keeps them while their modification time does not change.
/// Used from one thread only.
class IncludeCache {
public:
    std::shared_ptr<const IncludedFile> get(const std::string& path);

private:
    struct Entry {
        std::filesystem::file_time_type mtime;
        std::shared_ptr<const IncludedFile> file;
    };
    std::map<std::string, Entry> entries_;
};

struct Analysis {
    lang::Compilation compilation; ///< parsed and resolved, not evaluated
    std::vector<lang::Token> tokens;   ///< every token of the document, EndOfFile excluded
    std::vector<lang::Token> comments;
    std::vector<Symbol> symbols;
    std::vector<Occurrence> occurrences; ///< sorted by position
    std::vector<AttributeUse> attributes; ///< sorted by position
    std::vector<std::shared_ptr<const IncludedFile>> includes; ///< reachable, in first-seen order
    std::vector<ExternalSymbol> externals;
    /// Every macro and Function literal (the scopes of names), outer before inner.
    std::vector<const lang::Expr*> scopes;
    bool syntaxErrors = false;

    const lang::SourceFile& file() const { return compilation.sources.file(0); }
    const lang::Script& script() const { return compilation.main; }
    /// The occurrence whose range holds `offset` (its end included, as editors place the
    /// cursor just after a word).
    const Occurrence* occurrenceAt(uint32_t offset) const;
    const AttributeUse* attributeAt(uint32_t offset) const;
    /// Index of the token holding `offset` (end included), or -1.
    int tokenAt(uint32_t offset) const;
    /// Index of the last token ending at or before `offset`, or -1.
    int tokenBefore(uint32_t offset) const;
    std::string_view text(const lang::Token& token) const {
        return file().text().substr(token.begin, token.end - token.begin);
    }
    std::string_view text(lang::SourceRange range) const {
        return file().text().substr(range.begin, range.end - range.begin);
    }
    /// The symbol called `name` visible at `offset`: locals of enclosing macros first.
    const Symbol* lookup(std::string_view name, uint32_t offset) const;
    /// Macros and Functions whose body holds `offset`, innermost last.
    std::vector<const lang::Expr*> scopesAt(uint32_t offset) const;
    /// The object type (or Settings) whose braces enclose token `index`, from the tokens
    /// alone (so it works where the parse failed); ObjectType::Count when none.
    lang::ObjectType enclosingObject(int index) const;
};

/// Runs the front end on `text` (parse and resolve; evaluation is the diagnostics worker's)
/// and indexes the result.
std::shared_ptr<const Analysis> analyze(const std::string& path, std::string text,
                                        const AnalysisOptions& options, IncludeCache& cache);
/// Indexes a compilation made already (by the diagnostics worker, before it evaluates it).
std::shared_ptr<Analysis> analyze(lang::Compilation compilation, const AnalysisOptions& options,
                                  IncludeCache& cache);
/// Indexes `analysis`, whose compilation is set (parsed, maybe resolved). Reads of the
/// compilation only `file` (its file 0), the main script's AST and `resolved`, so the
/// compilation may be evaluated meanwhile on another thread (evaluation adds files and
/// diagnostics, and never writes the main script's AST).
void index(Analysis& analysis, const lang::SourceFile& file, const AnalysisOptions& options, IncludeCache& cache);

/// Only the tokens and comments of `text`, no parse: with the names of an older analysis,
/// enough to complete (stale_names.hpp), in a millisecond where analyze() takes tens.
std::shared_ptr<const Analysis> lexOnly(const std::string& path, std::string text);

/// Where `include "name"` in a file of folder `folder` finds its file, as the interpreter
/// looks (lang::IncludeSearch), among the files `access` allows. Empty if nowhere.
std::string findInclude(const std::string& name, const std::string& folder,
                        const AnalysisOptions& options, const lang::FileAccess& access);

/// The evaluation options of a document: limits, include search, asset roots and access.
lang::EvalOptions evalOptions(const AnalysisOptions& options);

/// A short static description of what an expression yields ("vec3", "Sphere", "macro (a, b)").
/// Looks at most `depth` levels into the expression.
std::string staticType(const lang::Expr* value, int depth = 32);

} // namespace crt::lsp
