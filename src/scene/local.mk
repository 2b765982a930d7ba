## src/scene: scene defaults and lifetime (no SDL).
libiris_core_la_SOURCES += %reldir%/scene.c
