// An undeclared identifier is named, with a caret under it.
sphere { 0, Radius }
