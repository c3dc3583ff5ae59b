"""glshade against other renderers and references: Mesa's fixed function, moderngl, pyrender,
trimesh, the spec's float64 transcription, `glshade.glsl`'s shaders."""
