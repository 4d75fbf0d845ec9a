Content-Length: 349

{"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {"general": {"positionEncodings": ["utf-8", "utf-16"]}, "textDocument": {"completion": {"completionItem": {"snippetSupport": true}}}}, "rootUri": "file:///fuzz", "workspaceFolders": [{"uri": "file:///fuzz", "name": "fuzz"}], "initializationOptions": {"maxSteps": 1000}}}Content-Length: 57

{"jsonrpc": "2.0", "method": "initialized", "params": {}}Content-Length: 320

{"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt", "languageId": "crt", "version": 1, "text": "size = 1\nball = Sphere { center -> vec3(0, 0, 0) radius -> size }\nM = Macro(r) { Sphere { radius -> r } }\nfor i in range(3) { ball }\nScene { ball M(2) }\n"}}}Content-Length: 68

{"jsonrpc": "2.0", "method": "$/cancelRequest", "params": {"id": 2}}Content-Length: 163

{"jsonrpc": "2.0", "id": 2, "method": "textDocument/hover", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}, "position": {"line": 0, "character": 0}}}Content-Length: 69

{"jsonrpc": "2.0", "id": 3, "method": "no/such/method", "params": {}}Content-Length: 158

{"jsonrpc": "2.0", "id": 4, "method": "textDocument/hover", "params": {"textDocument": {"uri": "file:///other.crt"}, "position": {"line": 0, "character": 0}}}Content-Length: 168

{"jsonrpc": "2.0", "id": 5, "method": "textDocument/hover", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}, "position": {"line": -1, "character": 99999}}}Content-Length: 51

{"jsonrpc": "2.0", "id": [1], "method": "shutdown"}Content-Length: 43

{"jsonrpc": "2.0", "id": 6, "result": null}Content-Length: 74

{"jsonrpc": "2.0", "method": "$/setTrace", "params": {"value": "verbose"}}Content-Length: 66

{"jsonrpc": "2.0", "id": 99, "method": "shutdown", "params": null}Content-Length: 52

{"jsonrpc": "2.0", "method": "exit", "params": null}