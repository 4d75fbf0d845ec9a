// LSP protocol types and their JSON: the only place JSON appears (clangd's Protocol.h idea).
// Features speak in byte offsets; this layer converts to the negotiated position encoding.
#pragma once

#include "code_actions.hpp"
#include "completion.hpp"
#include "diagnostics.hpp"
#include "document_symbols.hpp"
#include "folding.hpp"
#include "hover.hpp"
#include "semantic_tokens.hpp"
#include "signature_help.hpp"
#include "xrefs.hpp"

#include <nlohmann/json.hpp>

#include <stdexcept>
#include <string>

namespace crt::lsp {

using json = nlohmann::json;

/// JSON-RPC and LSP error codes.
enum class ErrorCode : int {
    ParseError = -32700,
    InvalidRequest = -32600,
    MethodNotFound = -32601,
    InvalidParams = -32602,
    InternalError = -32603,
    ServerNotInitialized = -32002,
    RequestFailed = -32803,
    RequestCancelled = -32800,
};

/// Thrown by request handlers; becomes the response's error.
struct LspError : std::runtime_error {
    LspError(ErrorCode c, const std::string& message) : std::runtime_error(message), code(c) {}
    ErrorCode code;
};

enum class OffsetEncoding { Utf16, Utf8 };

/// Converts between byte offsets in one file and LSP positions.
class Positions {
public:
    Positions(const lang::SourceFile& file, OffsetEncoding encoding) : file_(file), encoding_(encoding) {}
    json position(uint32_t offset) const;
    json range(lang::SourceRange range) const;
    /// A position from the client; past the end of a line or the file, clamped to it.
    uint32_t offset(const json& position) const;
    /// Line and character of `offset` in the encoding.
    std::pair<uint32_t, uint32_t> lineCharacter(uint32_t offset) const;
    const lang::SourceFile& file() const { return file_; }
    OffsetEncoding encoding() const { return encoding_; }

private:
    const lang::SourceFile& file_;
    OffsetEncoding encoding_;
};

/// file:///a%20b/c.crt -> /a b/c.crt; anything else stays as it is.
std::string uriToPath(std::string_view uri);
std::string pathToUri(std::string_view path);

/// Reads a required member, throwing InvalidParams when it is missing or mistyped.
const json& member(const json& object, const char* name);

json toJson(const DocumentDiagnostic& d, const Positions& positions, const std::string& documentUri,
            const lang::SourceFile* documentFile, OffsetEncoding encoding);
json toJson(const Hover& hover, const Positions& positions);
json toJson(const CompletionList& list, const Positions& positions, bool snippets);
json toJson(const SignatureHelp& help);
json toJson(const DocumentSymbol& symbol, const Positions& positions);
json toJson(const FoldingRange& range);
/// Semantic tokens in LSP's relative encoding, as the JSON text of the result object
/// (`{"data":[…]}`): written directly, since a json array of a whole file's numbers costs
/// more than everything else in the request.
std::string encodeSemanticTokens(const std::vector<SemanticToken>& tokens, const Positions& positions);

} // namespace crt::lsp
