"""Accuracy: stiff cases against 50-digit references, the display tier, hypothesis properties."""
