" g2d graph grammars: *.g2d files
autocmd BufRead,BufNewFile *.g2d setfiletype g2d
