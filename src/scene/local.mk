## src/scene: scene defaults and lifetime (no SDL).
