// An unterminated string.
#declare S = "no end
