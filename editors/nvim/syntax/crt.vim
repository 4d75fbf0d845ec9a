" Syntax highlighting for CRT scene scripts (Neovim 0.7 has no semantic tokens).
if exists('b:current_syntax') | finish | endif
syn keyword crtKeyword Settings Scene Macro while for in if else include
syn keyword crtModifier scale translate rotate
syn keyword crtBoolean true false
syn match crtType "\<[A-Z][A-Za-z0-9_]*\>"
syn match crtAttribute "\<[a-z][A-Za-z0-9_]*\>\ze\s*->"
syn match crtNumber "\<\d\+\(\.\d*\)\=\([eE][+-]\=\d\+\)\=\>"
syn match crtNumber "\.\d\+\([eE][+-]\=\d\+\)\=\>"
syn region crtString start=+"+ skip=+\\\\\|\\"+ end=+"+ oneline
syn match crtComment "--.*$"
syn match crtOperator "->\|[-+*/%^!<>=?:]\|&&\|||"
hi def link crtKeyword Keyword
hi def link crtModifier Keyword
hi def link crtBoolean Boolean
hi def link crtType Type
hi def link crtAttribute Identifier
hi def link crtNumber Number
hi def link crtString String
hi def link crtComment Comment
hi def link crtOperator Operator
let b:current_syntax = 'crt'
