// Issue 7: a height_field image outside the allowed tree, by absolute path.
height_field { png "/etc/passwd" }
