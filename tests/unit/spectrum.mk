## tests/unit/spectrum.mk: unit tests of this area.
