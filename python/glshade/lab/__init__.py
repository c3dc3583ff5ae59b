"""glshade's lab: the command-line tools (``python -m glshade demo|report|bench ...``) and the
report behind `gs.report`, apart from the library. The lab uses glshade only through its public
API, and ``import glshade`` does not import the lab (``gs.report`` and ``gs.Report`` load it on
first use).

``cli``: the command line; ``demo``; ``report`` with ``report_worker`` (one instruction set per
process), ``records`` (its rows and data, as JSON and CSV), ``report_files`` (Markdown, JSON,
CSV) and ``figures`` (matplotlib); ``studies``;
``bench`` (normals, render) and ``bench_shade``; ``baselines``: the equation in numpy and numba,
also the report's reference; ``scenes``: what is timed and measured; ``bounds``: each accuracy
mode's bound; ``timing``: the one timer; ``progress``: the progress bar; ``machine``: the
machine description saved with every result. The built-in meshes are public: `glshade.meshes`.
"""
