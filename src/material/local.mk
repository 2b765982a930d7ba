## src/material: see the file headers. Appends to the core library.
libiris_core_la_SOURCES += %reldir%/material.h %reldir%/mat_internal.h \
	%reldir%/noise.c %reldir%/noise.h %reldir%/pattern.c \
	%reldir%/pigment.c %reldir%/normal.c %reldir%/texture.c
