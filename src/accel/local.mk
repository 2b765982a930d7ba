## src/accel: see the file headers. Appends to the core library.
libiris_core_la_SOURCES += %reldir%/accel.c %reldir%/accel.h \
	%reldir%/node.c %reldir%/node.h %reldir%/mesh.c \
	%reldir%/csgbox.c %reldir%/csgbox.h
