"""Beyond one call and one process: `glshade.dask` and process pools over memory-mapped files."""
