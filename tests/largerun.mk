## tests/largerun.mk: large runs (issue 8): photon files (save_file,
## load_file) and the memory budget of the photon pass. photon_file.sh
## uses tests/progressive/imgdiff (progressive.mk).
TESTS += tests/largerun/photon_file.sh tests/largerun/memory_limit.sh
EXTRA_DIST += tests/largerun/photon_file.sh tests/largerun/photon_file.pov \
	tests/largerun/memory_limit.sh tests/largerun/plates.pov
