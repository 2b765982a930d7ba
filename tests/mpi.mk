## tests/mpi.mk: progressive passes across MPI ranks (issue 8). The test
## skips itself when iris was built without MPI (MPIRUN empty).
TESTS += tests/mpi/mpi.sh
EXTRA_DIST += tests/mpi/mpi.sh
AM_TESTS_ENVIRONMENT += export MPIRUN='$(MPIRUN)';
