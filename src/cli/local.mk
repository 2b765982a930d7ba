## src/cli: see the file headers. Appends to the core library.
