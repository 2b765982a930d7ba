// A misspelt keyword inside an object.
sphere { 0, 1 pigmnet { rgb 1 } }
