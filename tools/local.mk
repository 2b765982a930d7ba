## tools: generators run by make targets, not at render time.
