## src/geometry: see the file headers. Appends to the core library.
libiris_core_la_SOURCES += %reldir%/geom.c %reldir%/geom.h \
	%reldir%/roots.c %reldir%/roots.h %reldir%/quadrics.c \
	%reldir%/sphere_span.h \
	%reldir%/torus.c %reldir%/poly.c %reldir%/superellipsoid.c \
	%reldir%/blob.c %reldir%/profile.c %reldir%/sweep.c \
	%reldir%/text.c %reldir%/isosurface.c %reldir%/julia.c \
	%reldir%/julia_hcx.c %reldir%/julia_hcx.h \
	%reldir%/ovus.c %reldir%/sphere_sweep.c %reldir%/parametric.c \
	%reldir%/lemon.c %reldir%/bicubic.c %reldir%/bound.c
