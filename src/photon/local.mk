## src/photon: spectral caustic photon map (see photon.h and shoot.c).
libiris_core_la_SOURCES += %reldir%/photon.h %reldir%/photon.c \
	%reldir%/pmap.h %reldir%/shoot.c %reldir%/trace.c %reldir%/trace.h \
	%reldir%/estimate.c %reldir%/pstore.c %reldir%/pstore.h
