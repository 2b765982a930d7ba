## src/render: see the file headers. Appends to the core library.
libiris_core_la_SOURCES += %reldir%/render.c \
	%reldir%/camera.c %reldir%/camera.h \
	%reldir%/meshcam.c %reldir%/meshcam.h %reldir%/light.c %reldir%/light.h \
	%reldir%/query.h %reldir%/trace.c %reldir%/trace.h \
	%reldir%/plan.c %reldir%/plan.h %reldir%/eyepass.c %reldir%/eyepass.h \
	%reldir%/jitter.c %reldir%/jitter.h %reldir%/camray.h \
	%reldir%/eyespectrum.c %reldir%/eyespectrum.h \
	%reldir%/focalblur.c %reldir%/focalblur.h \
	%reldir%/check_ior.c %reldir%/check_ior.h \
	%reldir%/gather.c %reldir%/gather.h \
	%reldir%/gather_sources.c %reldir%/gather_sources.h \
	%reldir%/media.c %reldir%/media.h \
	%reldir%/rainbow.c %reldir%/rainbow.h
libiris_core_la_SOURCES += %reldir%/progressive.c %reldir%/progressive.h
libiris_core_la_SOURCES += %reldir%/mpi_passes.c %reldir%/mpi_passes.h
libiris_core_la_SOURCES += %reldir%/subsurface.c %reldir%/subsurface.h
