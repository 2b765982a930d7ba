## tests/unit/geometry.mk: unit tests of this area.
