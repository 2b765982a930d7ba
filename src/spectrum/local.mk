## src/spectrum: see the file headers. Appends to the core library.
