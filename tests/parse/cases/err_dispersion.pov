// dispersion_samples below 2 is an error, as in POV-Ray.
sphere { 0, 1 interior { ior 1.5 dispersion_samples 1 } }
