## tests/unit/render.mk: unit tests of this area.
