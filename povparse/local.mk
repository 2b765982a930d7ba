## povparse: the SDL front end (see povparse/pp.h).
libiris_core_la_SOURCES += %reldir%/pp.h %reldir%/pp_test.h %reldir%/tokens.def \
	%reldir%/lex.c %reldir%/diag.c %reldir%/input.c %reldir%/directive.c \
	%reldir%/symtab.c %reldir%/expr.c %reldir%/bounds.c %reldir%/rvalue.c \
	%reldir%/fnc.c %reldir%/mat.c %reldir%/obj.c %reldir%/scene.c \
	%reldir%/parse.c %reldir%/dump.c %reldir%/gamma.c %reldir%/access.c \
	%reldir%/media.c %reldir%/memfile.c %reldir%/maptree.c
