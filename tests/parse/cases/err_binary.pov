ELF binary ÿþ
