"""Helpers the tests share: float64 and 50-digit references of the GL equation, random scenes,
headless GL peers, the render cases, the boundary's scenes and the runner of tests/scripts."""
