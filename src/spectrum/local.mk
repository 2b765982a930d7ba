## src/spectrum: colour matching, RGB <-> spectrum, light spectra, IOR(lambda).
## tables.c and burns_table.c are generated (tools/local.mk) and checked in.
libiris_core_la_SOURCES += %reldir%/spectrum.c %reldir%/spectrum.h \
	%reldir%/illuminant.c %reldir%/internal.h \
	%reldir%/tables.c %reldir%/tables.h %reldir%/burns_table.c \
	%reldir%/ior.c %reldir%/ior.h
