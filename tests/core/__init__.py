"""The core's own tests, one folder per area: what glshade computes and how it takes its input."""
