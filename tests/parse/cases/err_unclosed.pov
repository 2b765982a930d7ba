// A block left open reports where it was opened.
union {
  sphere { 0, 1 }
