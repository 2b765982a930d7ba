## src/material: see the file headers. Appends to the core library.
