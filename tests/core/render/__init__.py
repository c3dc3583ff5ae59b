"""The rasteriser: coverage, depth, colours, images, cameras, world lights, `gs.compare`."""
