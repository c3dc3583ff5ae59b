"""The lighting equation: corner cases, light sums, the presets' models, the range of results."""
