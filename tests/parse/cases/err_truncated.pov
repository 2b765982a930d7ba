// Truncated in the middle of a vector.
sphere { <1, 2