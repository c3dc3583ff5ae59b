"""The description of the machine a measurement ran on, saved beside every result so that two
runs can be compared."""

from __future__ import annotations

import datetime
import os
import platform
import sys
from pathlib import Path
from typing import Any

import numpy as np

import glshade as gs

__all__ = ["describe", "identity", "instruction_set", "machine", "usable_cpus"]

# The x86 feature flags that decide glshade's instruction set (and numpy's and numba's).
FLAGS = ("sse2", "avx", "avx2", "fma", "avx512f", "avx512bw", "avx512dq", "avx512vl")


def usable_cpus() -> int:
    """The CPUs this process may run on (its affinity mask where the system has one)."""
    if hasattr(os, "sched_getaffinity"):
        return len(os.sched_getaffinity(0))
    return os.cpu_count() or 1


def instruction_set() -> str:
    """The instruction set glshade's kernels run with in this process (``"avx512"``, ``"avx2"``
    or ``"baseline"``), as `Scene.plan` names it; ``GLSHADE_ISA`` caps it."""
    return gs.Scene().plan().split(", ")[1]


# Microarchitectures by vendor, family and model number, for the CPUs whose model name does not
# say (under a hypervisor AMD's is often just "AMD EPYC"): AMD's Zen 3 to 5, Intel's Xeons with
# AVX-512. Others print their numbers only.
_MICROARCHITECTURES = (
    ("AuthenticAMD", 25, (*range(0x00, 0x10), *range(0x20, 0x30), *range(0x40, 0x60)), "Zen 3"),
    ("AuthenticAMD", 25, (*range(0x10, 0x20), *range(0x60, 0x80), *range(0xA0, 0xB0)), "Zen 4"),
    ("AuthenticAMD", 26, range(0x00, 0x100), "Zen 5"),
    ("GenuineIntel", 6, (0x55,), "Skylake or Cascade Lake"),
    ("GenuineIntel", 6, (0x6A, 0x6C), "Ice Lake"),
    ("GenuineIntel", 6, (0x8F,), "Sapphire Rapids"),
    ("GenuineIntel", 6, (0xCF,), "Emerald Rapids"),
    ("GenuineIntel", 6, (0xAD, 0xAE), "Granite Rapids"),
)


def identity(fields: dict[str, str]) -> str:
    """`vendor family F model M`, with the microarchitecture where `_MICROARCHITECTURES` knows
    it; empty where /proc/cpuinfo gives no numbers.

    Parameters
    ----------
    fields : dict of str to str
        The fields of one processor in /proc/cpuinfo, by name (``vendor_id``, ``cpu family``,
        ``model``; others are ignored).

    Returns
    -------
    str
        For example ``"AuthenticAMD family 25 model 17: Zen 4"``, or ``""``.
    """
    vendor, family, model = (fields.get(k, "") for k in ("vendor_id", "cpu family", "model"))
    if not (family.isdigit() and model.isdigit()):
        return ""
    name = next(
        (
            arch
            for v, f, models, arch in _MICROARCHITECTURES
            if (v, f) == (vendor, int(family)) and int(model) in models
        ),
        None,
    )
    return f"{vendor} family {family} model {model}" + (f": {name}" if name else "")


def _cpu() -> tuple[str, list[str]]:
    """The CPU's model name (with its family and model number, and the microarchitecture where
    known) and which of `FLAGS` it has, from /proc/cpuinfo where there is one."""
    try:
        text = Path("/proc/cpuinfo").read_text()
    except OSError:
        return platform.processor() or platform.machine(), []
    fields = {
        key.strip(): value.strip()
        for key, _, value in (line.partition(":") for line in text.splitlines()[:40])
    }
    flags = set(fields.get("flags", "").split())
    name, model = fields.get("model name", platform.machine()), identity(fields)
    return (f"{name} ({model})" if model else name), [f for f in FLAGS if f in flags]


def machine() -> dict[str, Any]:
    """The machine and the software of this process.

    Returns
    -------
    dict
        ``cpu`` (model name), ``cpu_flags`` (the SIMD flags it has), ``logical_cpus``,
        ``usable_cpus`` (this process's affinity), ``threads`` (glshade's thread pool:
        ``RAYON_NUM_THREADS`` or the usable CPUs), ``instruction_set`` (glshade's, in this
        process), ``glshade``, ``numpy``, ``python`` (versions), ``platform`` and ``date``
        (UTC, ISO 8601).
    """
    model, flags = _cpu()
    usable = usable_cpus()
    threads = os.environ.get("RAYON_NUM_THREADS")
    return {
        "cpu": model,
        "cpu_flags": flags,
        "logical_cpus": os.cpu_count(),
        "usable_cpus": usable,
        "threads": int(threads) if threads and threads.isdigit() else usable,
        "instruction_set": instruction_set(),
        "glshade": gs.__version__,
        "numpy": np.__version__,
        "python": platform.python_version(),
        "platform": f"{sys.platform}, {platform.machine()}, {platform.platform(terse=True)}",
        "date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
    }


def describe(m: dict[str, Any]) -> str:
    """One line of `machine`'s fields, for a printout.

    Parameters
    ----------
    m : dict
        A dict as `machine` returns it.

    Returns
    -------
    str
        The CPU and its flags, the usable CPUs, glshade's version, instruction set and threads,
        numpy's and Python's versions, and the date.
    """
    return (
        f"{m['cpu']} ({', '.join(m['cpu_flags']) or 'flags unknown'}), {m['usable_cpus']} of "
        f"{m['logical_cpus']} CPUs usable, glshade {m['glshade']} ({m['instruction_set']}, "
        f"{m['threads']} threads), numpy {m['numpy']}, Python {m['python']}, {m['date']}"
    )
