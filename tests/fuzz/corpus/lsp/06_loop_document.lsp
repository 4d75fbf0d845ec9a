Content-Length: 349

{"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {"general": {"positionEncodings": ["utf-8", "utf-16"]}, "textDocument": {"completion": {"completionItem": {"snippetSupport": true}}}}, "rootUri": "file:///fuzz", "workspaceFolders": [{"uri": "file:///fuzz", "name": "fuzz"}], "initializationOptions": {"maxSteps": 1000}}}Content-Length: 57

{"jsonrpc": "2.0", "method": "initialized", "params": {}}Content-Length: 295

{"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt", "languageId": "crt", "version": 1, "text": "while true {}\nx = [1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,1,]\nScene {}\n"}}}Content-Length: 168

{"jsonrpc": "2.0", "id": 2, "method": "textDocument/completion", "params": {"textDocument": {"uri": "file:///fuzz/scene.crt"}, "position": {"line": 1, "character": 3}}}