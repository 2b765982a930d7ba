## tests/cli.mk: end-to-end tests of the iris command.
