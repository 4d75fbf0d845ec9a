" Syntax highlighting for CRT scene scripts (Neovim 0.7 has no semantic tokens).
if exists('b:current_syntax') | finish | endif
syn keyword crtKeyword Settings Scene Macro Function while for in if else include
syn keyword crtModifier scale translate rotate
syn keyword crtBoolean true false
syn match crtType "\<[A-Z][A-Za-z0-9_]*\>"
syn match crtAttribute "\<[a-z][A-Za-z0-9_]*\>\ze\s*->"
" 1, 2., 2.5, .25, 1e3: a number ends where no word character follows ("2." too).
syn match crtNumber "\<\d\+\(\.\d*\)\=\([eE][+-]\=\d\+\)\=\w\@!"
syn match crtNumber "\(\w\|\.\)\@<!\.\d\+\([eE][+-]\=\d\+\)\=\w\@!"
syn match crtEscape contained +\\\([tbnrf'"\\]\|u\x\{4}\)+
syn match crtEscapeError contained +\\\([^tbnrf'"\\u]\|u\x\{,3}\X\@=\)+
syn region crtString start=+"+ skip=+\\\\\|\\"+ end=+"+ end=+$+ oneline contains=crtEscape,crtEscapeError
syn match crtOperator "->\|[-+*/%^!<>=?:]\|&&\|||"
" Defined after the operators: of two matches starting at the same column the last defined
" wins, and a comment's "--" must not be taken for two minus signs.
syn match crtComment "--.*$" contains=@Spell
hi def link crtKeyword Keyword
hi def link crtModifier Keyword
hi def link crtBoolean Boolean
hi def link crtType Type
hi def link crtAttribute Identifier
hi def link crtNumber Number
hi def link crtString String
hi def link crtEscape SpecialChar
hi def link crtEscapeError Error
hi def link crtComment Comment
hi def link crtOperator Operator
let b:current_syntax = 'crt'
