## tools: generators run by make targets, not at render time. Their output
## is checked in, so an ordinary build needs neither the tools nor data/.
##   make regen-tables   data/*.csv -> src/spectrum/tables.c
##   make regen-burns    Burns' curves -> src/spectrum/burns_table.c
##                       (needs LAPACKE: Debian liblapacke-dev)
EXTRA_PROGRAMS = tools/gen_tables tools/photon_bench
tools_gen_tables_SOURCES = tools/gen_tables.c
CLEANFILES += tools/gen_tables$(EXEEXT) tools/photon_bench$(EXEEXT)

## photon_bench: the photon pass alone, for bench/photons.sh
tools_photon_bench_SOURCES = tools/photon_bench.c
tools_photon_bench_LDADD = libiris_core.la $(IRIS_LIBS)

regen-tables: tools/gen_tables$(EXEEXT)
	tools/gen_tables$(EXEEXT) $(top_srcdir)/data > $(top_srcdir)/src/spectrum/tables.c.tmp
	mv $(top_srcdir)/src/spectrum/tables.c.tmp $(top_srcdir)/src/spectrum/tables.c

if HAVE_LAPACKE
EXTRA_PROGRAMS += tools/burns
tools_burns_SOURCES = tools/burns.c
tools_burns_CFLAGS = $(AM_CFLAGS) $(LAPACKE_CFLAGS)
tools_burns_LDADD = libiris_core.la $(LAPACKE_LIBS) $(IRIS_LIBS)
CLEANFILES += tools/burns$(EXEEXT)

regen-burns: tools/burns$(EXEEXT)
	tools/burns$(EXEEXT) > $(top_srcdir)/src/spectrum/burns_table.c.tmp
	mv $(top_srcdir)/src/spectrum/burns_table.c.tmp $(top_srcdir)/src/spectrum/burns_table.c
else
regen-burns:
	@echo "regen-burns needs LAPACKE (Debian: liblapacke-dev); rerun configure" >&2; exit 1
endif
.PHONY: regen-tables regen-burns
EXTRA_DIST += tools/gen_tables.c tools/burns.c tools/photon_bench.c

## Progressive photon mapping (issue 6), for bench/error-vs-time.sh:
##   ball_reference W H out.exr   semi-analytic image of bench/caustic_ball.pov
##   error_plot out.png NAME=log.csv ...   log-log rel. RMSE against time
##   make error-plot PLOT=out.png LOGS="iris=a.csv povray=b.csv"
EXTRA_PROGRAMS += tools/ball_reference tools/error_plot
tools_ball_reference_SOURCES = tools/ball_reference.c
tools_ball_reference_LDADD = libiris_core.la $(IRIS_LIBS)
tools_error_plot_SOURCES = tools/error_plot.c
tools_error_plot_LDADD = libiris_core.la $(IRIS_LIBS)
CLEANFILES += tools/ball_reference$(EXEEXT) tools/error_plot$(EXEEXT)
EXTRA_DIST += tools/ball_reference.c tools/error_plot.c
error-plot: tools/error_plot$(EXEEXT)
	tools/error_plot$(EXEEXT) $(PLOT) $(LOGS)
.PHONY: error-plot
