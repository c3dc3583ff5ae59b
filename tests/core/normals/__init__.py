"""Face and vertex normals."""
