## src/util: see the file headers. Appends to the core library.
libiris_core_la_SOURCES += %reldir%/arena.c %reldir%/arena.h \
	%reldir%/mem.c %reldir%/mem.h %reldir%/rng.h \
	%reldir%/thread.c %reldir%/thread.h
