"""The intake: dtypes, memory layouts, shapes, `out=`, meshes and trimesh objects as they come,
and the errors that name their argument."""
