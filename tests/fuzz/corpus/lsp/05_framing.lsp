Content-Length: 2

{}

content-length:  5 
Content-Type: application/vscode-jsonrpc; charset=utf-8

[1,2]Content-Length: x

Content-Length: 99999999999

No-Colon

Content-Length: 3

{"aContent-Length: 7

not json