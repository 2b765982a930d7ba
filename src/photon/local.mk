## src/photon: spectral caustic and global photon maps (photon.h, shoot.c,
## global.c).
libiris_core_la_SOURCES += %reldir%/photon.h %reldir%/photon.c \
	%reldir%/pmap.h %reldir%/shoot.c %reldir%/trace.c %reldir%/trace.h \
	%reldir%/global.c %reldir%/estimate.c %reldir%/pstore.c %reldir%/pstore.h \
	%reldir%/photon_file.c %reldir%/photon_file.h \
	%reldir%/membudget.c %reldir%/membudget.h \
	%reldir%/fastpath.c %reldir%/fastpath.h \
	%reldir%/pmedia.c %reldir%/pmedia.h \
	%reldir%/wavefront.c %reldir%/wavefront.h %reldir%/wf_kernel.h \
	%reldir%/targets.c %reldir%/targets.h \
	%reldir%/povbox.c %reldir%/povbox.h
