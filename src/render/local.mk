## src/render: see the file headers. Appends to the core library.
libiris_core_la_SOURCES += %reldir%/render_placeholder.c
