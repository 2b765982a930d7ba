// ior_decay needs spread > 0.
sphere { 0, 1 interior { ior_decay 1.6, 1.5, -3 } }
