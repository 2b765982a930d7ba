## tests/unit/parse.mk: unit tests of this area.
