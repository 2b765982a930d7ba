## src/image: images, and the OpenImageIO module loaded on first use.
libiris_core_la_SOURCES += %reldir%/image.c %reldir%/image_io.c \
	%reldir%/image_module.h %reldir%/png.c %reldir%/png.h \
	%reldir%/heights.c %reldir%/heights.h \
	%reldir%/indices.c %reldir%/indices.h \
	%reldir%/gif_indices.c %reldir%/gif_indices.h \
	%reldir%/df3.c %reldir%/df3.h \
	%reldir%/srgb8.c %reldir%/srgb8.h
pkglib_LTLIBRARIES = iris-oiio.la
iris_oiio_la_SOURCES = %reldir%/oiio.cc %reldir%/image_module.h
iris_oiio_la_CPPFLAGS = $(AM_CPPFLAGS) $(OIIO_CFLAGS)
iris_oiio_la_LDFLAGS = -module -avoid-version -shared
iris_oiio_la_LIBADD = $(OIIO_LIBS)
