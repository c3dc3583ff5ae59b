"""The command-line tools (``python -m glshade demo|report|bench ...``) and the report behind
`gs.report`, apart from the library: they use glshade only through its public API.

``cli``: the command line; ``demo``; ``report`` with ``report_worker`` (one instruction set per
process), ``report_files`` (Markdown, JSON, CSV) and ``figures`` (matplotlib); ``studies``;
``bench`` (normals, render) and ``bench_shade``; ``baselines``: the equation in numpy and numba,
also the report's reference; ``scenes``: what is timed and measured; ``bounds``: each accuracy
mode's bound; ``timing``: the one timer; ``progress``: the progress bar; ``machine``: the
machine description saved with every result; ``meshes``: built-in meshes.
"""
