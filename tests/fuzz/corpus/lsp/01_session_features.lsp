Content-Length: 349

{"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {"general": {"positionEncodings": ["utf-8", "utf-16"]}, "textDocument": {"completion": {"completionItem": {"snippetSupport": true}}}}, "rootUri": "file:///fuzz", "workspaceFolders": [{"uri": "file:///fuzz", "name": "fuzz"}], "initializationOptions": {"maxSteps": 1000}}}Content-Length: 57

{"jsonrpc": "2.0", "method": "initialized", "params": {}}Content-Length: 320

{"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt", "languageId": "crt", "version": 1, "text": "size = 1\nball = Sphere { center -> vec3(0, 0, 0) radius -> size }\nM = Macro(r) { Sphere { radius -> r } }\nfor i in range(3) { ball }\nScene { ball M(2) }\n"}}}Content-Length: 164

{"jsonrpc": "2.0", "id": 2, "method": "textDocument/hover", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}, "position": {"line": 1, "character": 20}}}Content-Length: 168

{"jsonrpc": "2.0", "id": 3, "method": "textDocument/completion", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}, "position": {"line": 1, "character": 3}}}Content-Length: 136

{"jsonrpc": "2.0", "id": 4, "method": "textDocument/semanticTokens/full", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}}}Content-Length: 222

{"jsonrpc": "2.0", "id": 5, "method": "textDocument/semanticTokens/range", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}, "range": {"start": {"line": 0, "character": 0}, "end": {"line": 2, "character": 5}}}}Content-Length: 169

{"jsonrpc": "2.0", "id": 6, "method": "textDocument/definition", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}, "position": {"line": 3, "character": 21}}}Content-Length: 209

{"jsonrpc": "2.0", "id": 7, "method": "textDocument/references", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}, "position": {"line": 0, "character": 1}, "context": {"includeDeclaration": true}}}Content-Length: 175

{"jsonrpc": "2.0", "id": 8, "method": "textDocument/documentHighlight", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}, "position": {"line": 0, "character": 1}}}Content-Length: 171

{"jsonrpc": "2.0", "id": 9, "method": "textDocument/prepareRename", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}, "position": {"line": 0, "character": 1}}}Content-Length: 187

{"jsonrpc": "2.0", "id": 10, "method": "textDocument/rename", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}, "position": {"line": 0, "character": 1}, "newName": "radius2"}}Content-Length: 132

{"jsonrpc": "2.0", "id": 11, "method": "textDocument/documentSymbol", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}}}Content-Length: 130

{"jsonrpc": "2.0", "id": 12, "method": "textDocument/foldingRange", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}}}Content-Length: 177

{"jsonrpc": "2.0", "id": 13, "method": "textDocument/formatting", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}, "options": {"tabSize": 4, "insertSpaces": true}}}Content-Length: 267

{"jsonrpc": "2.0", "id": 14, "method": "textDocument/rangeFormatting", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}, "range": {"start": {"line": 0, "character": 0}, "end": {"line": 1, "character": 0}}, "options": {"tabSize": 2, "insertSpaces": true}}}Content-Length: 173

{"jsonrpc": "2.0", "id": 15, "method": "textDocument/signatureHelp", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}, "position": {"line": 2, "character": 30}}}Content-Length: 245

{"jsonrpc": "2.0", "id": 16, "method": "textDocument/codeAction", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}, "range": {"start": {"line": 0, "character": 0}, "end": {"line": 0, "character": 4}}, "context": {"diagnostics": []}}}Content-Length: 170

{"jsonrpc": "2.0", "id": 17, "method": "textDocument/declaration", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}, "position": {"line": 1, "character": 2}}}Content-Length: 66

{"jsonrpc": "2.0", "id": 99, "method": "shutdown", "params": null}Content-Length: 52

{"jsonrpc": "2.0", "method": "exit", "params": null}