"""The built extension's SIMD kernels, read from its machine code: the functions compiled for AVX2
and AVX-512 (``glshade::simd::dispatch::avx2`` and ``avx512``, into which every kernel is
inlined) call no function but the cold ones (panics, the rescaled normalisation of tiny and huge
vectors, ``memset``/``memcpy``).

A vector operation that is not inlined becomes a call, and a call in a kernel costs more than
the call: every vector register is caller-saved, so the block's values go to the stack around
it. It happens silently when a kernel passes a closure to the standard library
(``array::map``, ``array::from_fn``), which runs it in a function compiled without the kernel's
target features: 16 and 32 lights ran 1.2 times as fast once the one such call (the light sums'
``map``) was gone (``docs/pages/performance/notes.md``, "Calls inside the kernels").
"""

from __future__ import annotations

import platform
import re
import shutil
import subprocess
from pathlib import Path

from conftest import unavailable

import glshade._glshade as native

KERNEL = re.compile(r"glshade4simd8dispatch(4avx2|6avx512)17h")
"""The legacy-mangled names of the AVX2 and AVX-512 entry points (one per kernel)."""

COLD = ("panicking", "panic_", "slice_index", "rescaled", "memset", "memcpy")
"""Substrings of the names a kernel may call: the cold paths."""


def _disassembly(what: str) -> str:
    objdump = shutil.which("objdump")
    if objdump is None:
        unavailable("objdump (Debian's binutils) is needed to read the extension's machine code")
    return subprocess.run(
        [objdump, what, "--no-show-raw-insn", native.__file__],
        capture_output=True,
        text=True,
        check=True,
    ).stdout


def _kernel_calls() -> dict[str, set[str]]:
    """Each kernel's call targets, by name (every kernel a key); calls through the GOT resolved
    to the function the relocation names."""
    functions: dict[int, str] = {}
    calls: dict[str, set[str]] = {}
    indirect: dict[str, set[int]] = {}
    current = None
    for line in _disassembly("-d").splitlines():
        header = re.match(r"([0-9a-f]+) <(.+)>:$", line)
        if header:
            address, current = int(header[1], 16), header[2]
            functions[address] = current
            if KERNEL.search(current):
                calls.setdefault(current, set())
            continue
        if current is None or not KERNEL.search(current) or "call" not in line:
            continue
        direct = re.search(r"\scall\s+[0-9a-f]+ <(.+)>", line)
        if direct:
            calls.setdefault(current, set()).add(direct[1])
        got = re.search(r"\scall\s+\*.*# ([0-9a-f]+) <", line)
        if got:
            indirect.setdefault(current, set()).add(int(got[1], 16))
    slots: dict[int, str] = {}
    for line in _disassembly("-R").splitlines():
        relative = re.match(r"([0-9a-f]+) R_X86_64_RELATIVE\s+\*ABS\*\+0x([0-9a-f]+)", line)
        if relative:
            slots[int(relative[1], 16)] = functions.get(int(relative[2], 16), relative[2])
        named = re.match(r"([0-9a-f]+) R_X86_64_\w+\s+(\S+)", line)
        if named and not relative:
            slots[int(named[1], 16)] = named[2]
    for kernel, targets in indirect.items():
        calls.setdefault(kernel, set()).update(slots.get(a, f"GOT slot {a:#x}") for a in targets)
    return calls


def test_the_simd_kernels_call_only_cold_functions() -> None:
    if platform.machine() not in ("x86_64", "AMD64"):
        unavailable(f"the AVX2 and AVX-512 kernels exist on x86-64 only, not {platform.machine()}")
    assert Path(native.__file__).is_file()
    calls = _kernel_calls()
    # 2 instruction sets times the kernels of GL's shapes and models in two types: a few dozen.
    assert len(calls) >= 8, f"found {len(calls)} SIMD kernels: were the symbols stripped?"
    hot = {
        kernel: sorted(t for t in targets if not any(c in t for c in COLD))
        for kernel, targets in calls.items()
    }
    hot = {kernel: targets for kernel, targets in hot.items() if targets}
    assert not hot, f"kernels call functions that are not cold paths: {hot}"
