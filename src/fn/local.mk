## src/fn: the evaluator of compiled SDL functions.
libiris_core_la_SOURCES += %reldir%/fn.c %reldir%/fnintern.c %reldir%/spline.c \
	%reldir%/fnimages.c %reldir%/fnimages.h
