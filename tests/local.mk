## tests: cmocka unit tests (TAP) and data-driven shell tests (TAP).
## Each area keeps its own fragment so that parts grow independently.
EXTRA_DIST += tests/testutil.h tests/scene_builder.h tests/tap.sh
include $(srcdir)/tests/unit/util.mk
include $(srcdir)/tests/unit/parse.mk
include $(srcdir)/tests/unit/geometry.mk
include $(srcdir)/tests/unit/render.mk
include $(srcdir)/tests/unit/spectrum.mk
include $(srcdir)/tests/unit/photon.mk
include $(srcdir)/tests/cli.mk
include $(srcdir)/tests/robust.mk
include $(srcdir)/tests/progressive.mk
include $(srcdir)/tests/mpi.mk
include $(srcdir)/tests/largerun.mk
include $(srcdir)/tests/optics.mk
