## src/fn: the evaluator of compiled SDL functions.
