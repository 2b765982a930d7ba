## src/material: see the file headers. Appends to the core library.
libiris_core_la_SOURCES += %reldir%/material.h %reldir%/mat_internal.h \
	%reldir%/noise.c %reldir%/noise.h %reldir%/pattern.c \
	%reldir%/tiling.c %reldir%/tiling.h %reldir%/penrose.c \
	%reldir%/penrose.h \
	%reldir%/fractal_pattern.c %reldir%/fractal_pattern.h \
	%reldir%/pigment.c %reldir%/normal.c %reldir%/texture.c \
	%reldir%/multitex.c \
	%reldir%/objpattern.c %reldir%/objpattern.h \
	%reldir%/listpat.c %reldir%/listpat.h
