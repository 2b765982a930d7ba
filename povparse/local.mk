## povparse: the SDL front end.
libiris_core_la_SOURCES += %reldir%/parse_placeholder.c
