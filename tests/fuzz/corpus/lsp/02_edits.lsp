Content-Length: 349

{"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {"general": {"positionEncodings": ["utf-8", "utf-16"]}, "textDocument": {"completion": {"completionItem": {"snippetSupport": true}}}}, "rootUri": "file:///fuzz", "workspaceFolders": [{"uri": "file:///fuzz", "name": "fuzz"}], "initializationOptions": {"maxSteps": 1000}}}Content-Length: 57

{"jsonrpc": "2.0", "method": "initialized", "params": {}}Content-Length: 320

{"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt", "languageId": "crt", "version": 1, "text": "size = 1\nball = Sphere { center -> vec3(0, 0, 0) radius -> size }\nM = Macro(r) { Sphere { radius -> r } }\nfor i in range(3) { ball }\nScene { ball M(2) }\n"}}}Content-Length: 253

{"jsonrpc": "2.0", "method": "textDocument/didChange", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt", "version": 2}, "contentChanges": [{"range": {"start": {"line": 0, "character": 7}, "end": {"line": 0, "character": 8}}, "text": "2.5"}]}}Content-Length: 219

{"jsonrpc": "2.0", "method": "textDocument/didChange", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt", "version": 3}, "contentChanges": [{"text": "x = \"unterminated\nScene { Sphere { radius -> x } }\n"}]}}Content-Length: 164

{"jsonrpc": "2.0", "id": 2, "method": "textDocument/hover", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}, "position": {"line": 1, "character": 30}}}Content-Length: 115

{"jsonrpc": "2.0", "method": "textDocument/didSave", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}}}Content-Length: 116

{"jsonrpc": "2.0", "method": "textDocument/didClose", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}}}Content-Length: 163

{"jsonrpc": "2.0", "id": 3, "method": "textDocument/hover", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}, "position": {"line": 0, "character": 0}}}Content-Length: 66

{"jsonrpc": "2.0", "id": 99, "method": "shutdown", "params": null}Content-Length: 52

{"jsonrpc": "2.0", "method": "exit", "params": null}