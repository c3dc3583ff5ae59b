"""Accuracy: stiff cases against 50-digit references, the deprecated "display" alias, hypothesis
properties."""
