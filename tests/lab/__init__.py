"""The lab's tools (`glshade.lab`): the report, the benchmarks, the demo, the render study."""
