//! The kernels' machine code: the functions compiled for AVX2 and AVX-512
//! (`glshade::simd::dispatch::avx2` and `avx512`, into which every kernel is inlined) call no
//! function but the cold ones (panics, the rescaled normalisation of tiny and huge vectors,
//! `memset`, `memcpy`, the stack probe of a large frame).
//!
//! A vector operation that is not inlined becomes a call, and a call in a kernel costs more
//! than the call: no vector register survives a call, so the block's values go to the stack
//! around it. It happens silently when a kernel hands a closure to the standard library
//! (`array::map`, `array::from_fn`, `Option::map`), which runs it in a function compiled
//! without the kernel's target features: 16 mixed and 32 point lights ran 1.21 and 1.14 times
//! as fast once the light sums' `map` was gone (the performance lab notes, "Calls inside the
//! kernels").
//!
//! The test reads this test binary with `objdump -d -C` (the released wheel has no symbols to
//! read). The `test` profile optimises at level 2, which inlines less than the release build,
//! so a call the release build would make shows here too. Without objdump the test fails under
//! `CI=true` and passes with a message elsewhere.

use std::collections::BTreeMap;
use std::process::Command;

/// Substrings of the names a kernel may call: its cold paths, and the growth of a `Vec` (the
/// tests' sweep of `exp` and `ln` collects its lanes in one; no kernel of the library pushes to
/// a `Vec`).
const COLD: [&str; 8] = [
    "panicking",
    "panic_",
    "slice_index",
    "rescaled",
    "memset",
    "memcpy",
    "probestack",
    "do_reserve_and_handle",
];

/// `objdump <what> -C` of this binary, or `None` without objdump (under `CI=true`, a failure).
fn objdump(what: &str) -> Option<String> {
    let exe = std::env::current_exe().expect("the test binary's path");
    match Command::new("objdump")
        .args([what, "-C", "--no-show-raw-insn"])
        .arg(&exe)
        .output()
    {
        Ok(out) if out.status.success() => Some(String::from_utf8_lossy(&out.stdout).into()),
        result => {
            let why = format!("objdump {what} of {} failed: {result:?}", exe.display());
            assert!(
                std::env::var_os("CI").is_none(),
                "{why} (CI=true: binutils is needed)"
            );
            eprintln!("skipped: {why}");
            None
        }
    }
}

/// Whether a demangled function name is a kernel's entry point.
fn is_kernel(name: &str) -> bool {
    name.starts_with("glshade::simd::dispatch::avx2")
        || name.starts_with("glshade::simd::dispatch::avx512")
}

/// The hexadecimal number `text`.
fn hex(text: &str) -> Option<u64> {
    u64::from_str_radix(text.trim(), 16).ok()
}

/// The GOT slot's address an instruction's comment names (`# abc123 <memcpy@GLIBC>`), 0 if
/// none.
fn got_slot(comment: &str) -> u64 {
    comment.trim().split(' ').next().and_then(hex).unwrap_or(0)
}

/// Each kernel's call targets by name (every kernel a key: its name and address), from the
/// disassembly `code`; a call through the GOT, directly or through a register loaded from it,
/// is named by the relocation of its slot in `relocations` (`objdump -R`): the symbol it binds,
/// or the function at the address it holds.
fn kernel_calls(code: &str, relocations: &str) -> BTreeMap<String, Vec<String>> {
    let mut functions: BTreeMap<u64, String> = BTreeMap::new();
    let mut calls: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut slots: Vec<(String, u64)> = Vec::new();
    let mut current: Option<String> = None;
    // The GOT slot last loaded into each register (`mov 0x10(%rip),%r12  # abc <memcpy@..>`):
    // a function called more than once may be called through a register (`call *%r12`).
    let mut loaded: BTreeMap<String, u64> = BTreeMap::new();
    for line in code.lines() {
        // A function's header: `0000000000abc123 <name>:`.
        if let Some((address, name)) = line.strip_suffix(">:").and_then(|l| l.split_once(" <")) {
            if let Some(a) = hex(address) {
                functions.insert(a, name.to_owned());
            }
            // Each instantiation of a generic kernel has the same demangled name.
            current = is_kernel(name).then(|| format!("{name} at {address}"));
            loaded.clear();
            if let Some(kernel) = &current {
                calls.entry(kernel.clone()).or_default();
            }
            continue;
        }
        // A register holds the slot a `mov` loaded from the GOT until anything else moves
        // into it.
        if let Some((_, mov)) = line.split_once("\tmov") {
            let (operands, comment) = mov.split_once('#').unwrap_or((mov, ""));
            if let Some((source, register)) = operands.trim().rsplit_once(',') {
                let register = register.trim().to_owned();
                if source.ends_with("(%rip)") && !comment.is_empty() {
                    loaded.insert(register, got_slot(comment));
                } else {
                    loaded.remove(&register);
                }
            }
            continue;
        }
        let (Some(kernel), Some((_, call))) = (&current, line.split_once("\tcall")) else {
            continue;
        };
        if let Some(slot) = call.trim().strip_prefix('*').and_then(|r| loaded.get(r)) {
            slots.push((kernel.clone(), *slot));
            continue;
        }
        // `call   abc123 <target>`, or through the GOT `call *0x10(%rip)  # abc <_DYNAMIC+0x8>`.
        if let Some((_, slot)) = call.split_once('#') {
            slots.push((kernel.clone(), got_slot(slot)));
        } else {
            let target = call.rsplit_once(" <").map_or(call.trim(), |(_, t)| t);
            let target = target.trim_end_matches('>').to_owned();
            calls.entry(kernel.clone()).or_default().push(target);
        }
    }
    // `000000000002ff2d0 R_X86_64_RELATIVE  *ABS*+0x123`, `... R_X86_64_GLOB_DAT  fma@GLIBC`.
    let mut bound: BTreeMap<u64, String> = BTreeMap::new();
    for line in relocations.lines() {
        let fields: Vec<&str> = line.split_whitespace().collect();
        if let [slot, kind, value, ..] = fields[..] {
            let Some(slot) = hex(slot) else { continue };
            let name = match value.strip_prefix("*ABS*+0x").and_then(hex) {
                Some(address) => functions.get(&address).cloned(),
                None if kind.starts_with("R_X86_64") => Some(value.to_owned()),
                None => None,
            };
            if let Some(name) = name {
                bound.insert(slot, name);
            }
        }
    }
    for (kernel, slot) in slots {
        let target = bound
            .get(&slot)
            .cloned()
            .unwrap_or_else(|| format!("GOT slot {slot:#x}"));
        calls.entry(kernel).or_default().push(target);
    }
    calls
}

#[test]
fn the_simd_kernels_call_only_cold_functions() {
    if !cfg!(target_arch = "x86_64") {
        return; // the AVX2 and AVX-512 kernels exist on x86-64 only
    }
    let (Some(code), Some(relocations)) = (objdump("-d"), objdump("-R")) else {
        return;
    };
    let calls = kernel_calls(&code, &relocations);
    // Two instruction sets times the kernels the tests instantiate: a few dozen.
    assert!(
        calls.len() >= 8,
        "found {} SIMD kernels in the test binary",
        calls.len()
    );
    let hot: BTreeMap<&String, Vec<&String>> = calls
        .iter()
        .map(|(kernel, targets)| {
            let hot = targets
                .iter()
                .filter(|t| !COLD.iter().any(|c| t.contains(c)));
            (kernel, hot.collect::<Vec<_>>())
        })
        .filter(|(_, hot)| !hot.is_empty())
        .collect();
    assert!(
        hot.is_empty(),
        "kernels call functions that are not cold paths: {hot:#?}"
    );
}
