## src/image: see the file headers. Appends to the core library.
