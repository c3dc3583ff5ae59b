//! No file-level import cycle: if a source file names an item of another (`use crate::…`,
//! `super::…`, or a path in code), that file never names it back, directly or through others.
//! A file names the file of the longest module path it uses (`crate::lighting::model::shade`
//! names `src/lighting/model.rs`); comments and inline test modules are not counted.

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};

use super::layers::{source_dir, sources};

/// The module path of a file below `src/` (`lighting/model.rs` is `["lighting", "model"]`;
/// `lib.rs` is the root, `[]`).
fn module_of(relative: &Path) -> Vec<String> {
    let mut parts: Vec<String> = relative
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    let last = parts.pop().unwrap_or_default();
    let stem = last.trim_end_matches(".rs");
    if !(parts.is_empty() && stem == "lib") && stem != "mod" {
        parts.push(stem.to_owned());
    }
    parts
}

/// The file of the longest prefix of `path` that is a module with a file of its own.
fn file_of(path: &[String]) -> Option<PathBuf> {
    (1..=path.len()).rev().find_map(|k| {
        let base = path[..k].join("/");
        [format!("{base}.rs"), format!("{base}/mod.rs")]
            .into_iter()
            .map(PathBuf::from)
            .find(|candidate| source_dir().join(candidate).is_file())
    })
}

/// The paths a line of code names from the crate root or `super`, braces expanded one level
/// (`a::{b::C, d}` is `a::b::C` and `a::d`), each split into segments from its first
/// (`crate` or `super`).
fn paths_in(line: &str) -> Vec<Vec<String>> {
    let code = line.split("//").next().unwrap_or("");
    let mut found = Vec::new();
    for root in ["crate::", "super::"] {
        for (at, _) in code.match_indices(root) {
            let preceded = code[..at].chars().next_back();
            if preceded.is_some_and(|c| c.is_alphanumeric() || "_:".contains(c)) {
                continue; // inside a longer path (`super::super::`), counted from its start
            }
            let rest = &code[at..];
            let end = rest
                .find(|c: char| !(c.is_alphanumeric() || "_:{}, ".contains(c)))
                .unwrap_or(rest.len());
            let path = rest[..end].trim_end_matches([',', ' ']);
            let (head, braces) = match path.split_once('{') {
                Some((head, inner)) => (head, inner.split('}').next().unwrap_or("")),
                None => (path, ""),
            };
            let tails: Vec<&str> = if braces.is_empty() {
                vec![""]
            } else {
                braces.split(',').map(str::trim).collect()
            };
            for tail in tails {
                let joined = format!("{head}{tail}");
                let segments = joined
                    .split("::")
                    .filter(|s| !s.is_empty() && *s != "*")
                    .map(str::to_owned)
                    .collect();
                found.push(segments);
            }
        }
    }
    found
}

/// Every file-to-file edge of the crate: the files each file names.
fn edges() -> BTreeMap<PathBuf, Vec<PathBuf>> {
    let mut files = Vec::new();
    sources(&source_dir(), &mut files);
    let mut graph = BTreeMap::new();
    for path in files {
        let relative = path.strip_prefix(source_dir()).unwrap().to_path_buf();
        let module = module_of(&relative);
        let text = fs::read_to_string(&path).unwrap();
        let mut named = Vec::new();
        let (mut inline_depth, mut depth, mut tests) = (None, 0_usize, false);
        let mut after_cfg_test = false;
        for line in text.lines() {
            let code = line.split("//").next().unwrap_or("");
            if inline_depth.is_none()
                && code.trim_start().starts_with("mod ")
                && code.ends_with('{')
            {
                inline_depth = Some(depth);
                // Inline test modules, compiled for tests only, build cases from anywhere.
                tests = after_cfg_test;
            }
            after_cfg_test = code.trim() == "#[cfg(test)]";
            depth = (depth + code.matches('{').count()).saturating_sub(code.matches('}').count());
            if inline_depth.is_some_and(|d| depth <= d) {
                (inline_depth, tests) = (None, false);
            }
            if tests {
                continue;
            }
            for segments in paths_in(code) {
                let absolute = if segments[0] == "crate" {
                    segments[1..].to_vec()
                } else {
                    // `super::` in an inline module is the file's own module first.
                    let ups = segments.iter().take_while(|s| *s == "super").count()
                        - usize::from(inline_depth.is_some());
                    let kept = module.len().saturating_sub(ups);
                    let mut absolute = module[..kept].to_vec();
                    absolute.extend(segments.iter().skip_while(|s| *s == "super").cloned());
                    absolute
                };
                if let Some(target) = file_of(&absolute) {
                    if target != relative && !named.contains(&target) {
                        named.push(target);
                    }
                }
            }
        }
        graph.insert(relative, named);
    }
    graph
}

/// A cycle of the graph, as the files around it, if there is one.
fn cycle(graph: &BTreeMap<PathBuf, Vec<PathBuf>>) -> Option<Vec<PathBuf>> {
    // Depth-first, colouring files: absent unvisited, false on the stack, true done.
    fn visit(
        file: &PathBuf,
        graph: &BTreeMap<PathBuf, Vec<PathBuf>>,
        state: &mut BTreeMap<PathBuf, bool>,
        stack: &mut Vec<PathBuf>,
    ) -> Option<Vec<PathBuf>> {
        state.insert(file.clone(), false);
        stack.push(file.clone());
        for next in graph.get(file).into_iter().flatten() {
            match state.get(next) {
                Some(false) => {
                    let start = stack.iter().position(|f| f == next).unwrap_or(0);
                    let mut found = stack[start..].to_vec();
                    found.push(next.clone());
                    return Some(found);
                }
                Some(true) => {}
                None => {
                    if let Some(found) = visit(next, graph, state, stack) {
                        return Some(found);
                    }
                }
            }
        }
        stack.pop();
        state.insert(file.clone(), true);
        None
    }
    let mut state = BTreeMap::new();
    graph.keys().find_map(|file| {
        if state.contains_key(file) {
            return None;
        }
        visit(file, graph, &mut state, &mut Vec::new())
    })
}

#[test]
fn no_file_names_a_file_that_names_it_back() {
    let graph = edges();
    assert!(graph.len() > 100, "only {} files read", graph.len());
    let edges: usize = graph.values().map(Vec::len).sum();
    assert!(edges > 300, "only {edges} edges found");
    if let Some(files) = cycle(&graph) {
        let names: Vec<String> = files.iter().map(|f| f.display().to_string()).collect();
        panic!("an import cycle: {}", names.join(" -> "));
    }
}

#[test]
fn the_check_sees_a_cycle_and_resolves_paths_to_files() {
    let named = |code: &str| {
        paths_in(code)
            .into_iter()
            .map(|s| s.join("::"))
            .collect::<Vec<_>>()
    };
    assert_eq!(
        named("use crate::lighting::{model::shade, driver::Inputs}; // crate::render"),
        [
            "crate::lighting::model::shade",
            "crate::lighting::driver::Inputs"
        ]
    );
    assert_eq!(named("use super::super::x::Y;"), ["super::super::x::Y"]);
    let path = |p: &str| p.split("::").map(str::to_owned).collect::<Vec<_>>();
    assert_eq!(
        file_of(&path("lighting::model::shade")),
        Some(PathBuf::from("lighting/model.rs"))
    );
    assert_eq!(
        file_of(&path("lighting::fixed_function::kernel::Kernel")),
        Some(PathBuf::from("lighting/fixed_function/kernel.rs"))
    );
    assert_eq!(module_of(Path::new("lib.rs")), Vec::<String>::new());
    let (a, b) = (PathBuf::from("a.rs"), PathBuf::from("b.rs"));
    let mut graph = BTreeMap::new();
    graph.insert(a.clone(), vec![b.clone()]);
    graph.insert(b.clone(), vec![]);
    assert_eq!(cycle(&graph), None);
    graph.insert(b.clone(), vec![a.clone()]);
    assert_eq!(cycle(&graph), Some(vec![a.clone(), b, a]));
}
