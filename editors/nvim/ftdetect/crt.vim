" CRT scene scripts: *.crt
autocmd BufRead,BufNewFile *.crt setfiletype crt
