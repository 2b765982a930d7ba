## src/image: see the file headers. Appends to the core library.
libiris_core_la_SOURCES += %reldir%/image.c %reldir%/oiio.cc
