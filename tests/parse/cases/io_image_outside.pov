// Issue 7: image files are reads too (image_map, bump_map, height_field).
plane { y, 0 pigment { image_map { png "../run.sh" } } }
