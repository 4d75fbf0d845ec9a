Content-Length: 163

{"jsonrpc": "2.0", "id": 1, "method": "textDocument/hover", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}, "position": {"line": 0, "character": 0}}}Content-Length: 320

{"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt", "languageId": "crt", "version": 1, "text": "size = 1\nball = Sphere { center -> vec3(0, 0, 0) radius -> size }\nM = Macro(r) { Sphere { radius -> r } }\nfor i in range(3) { ball }\nScene { ball M(2) }\n"}}}Content-Length: 349

{"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {"general": {"positionEncodings": ["utf-8", "utf-16"]}, "textDocument": {"completion": {"completionItem": {"snippetSupport": true}}}}, "rootUri": "file:///fuzz", "workspaceFolders": [{"uri": "file:///fuzz", "name": "fuzz"}], "initializationOptions": {"maxSteps": 1000}}}Content-Length: 57

{"jsonrpc": "2.0", "method": "initialized", "params": {}}Content-Length: 65

{"jsonrpc": "2.0", "id": 2, "method": "initialize", "params": {}}