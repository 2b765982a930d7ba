## src/math: see the file headers. Appends to the core library.
libiris_core_la_SOURCES += %reldir%/vec3.h %reldir%/transform.c %reldir%/transform.h
