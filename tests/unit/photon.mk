## tests/unit/photon.mk: unit tests of the photon map.
