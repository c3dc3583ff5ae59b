"""Scene objects and records: pickling, copying, equality and indexing."""
