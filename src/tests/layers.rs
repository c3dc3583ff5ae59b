//! The layers of `lib.rs`, checked against the sources: a file may name (`crate::layer`) only
//! its own layer and the layers declared below it in `lib.rs`, which lists them top to bottom.
//! Below the binding, files name a layer, never a crate-root re-export, so the rule sees every
//! path. Comments are not code and may point anywhere.

use std::fs;
use std::path::{Path, PathBuf};

/// The layers as `lib.rs` declares them (`mod name;`), top first; `tests` is not a layer.
fn layers() -> Vec<String> {
    let lib = fs::read_to_string(source_dir().join("lib.rs")).unwrap();
    lib.lines()
        .filter_map(|line| line.trim().strip_prefix("mod ")?.strip_suffix(';'))
        .filter(|name| *name != "tests")
        .map(str::to_owned)
        .collect()
}

pub(super) fn source_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// Every `.rs` file under `dir`, with its path relative to `src/`.
pub(super) fn sources(dir: &Path, found: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            sources(&path, found);
        } else if path.extension().is_some_and(|e| e == "rs") {
            found.push(path);
        }
    }
}

/// A path from the crate root in a file's code: its line, its first segment, and whether it
/// was written `crate::` (else `super::` as many times as the file lies deep below `src/`,
/// which from the file's own scope is the root too; inside an inline module it is not, so only
/// layer names count there).
struct RootPath {
    line: usize,
    segment: String,
    via_crate: bool,
}

/// Every path from the crate root in the code of `text` (comments dropped), for a file `depth`
/// modules below the root.
fn crate_paths(text: &str, depth: usize) -> Vec<RootPath> {
    let supers = "super::".repeat(depth);
    let mut paths = Vec::new();
    for (number, line) in text.lines().enumerate() {
        let code = line.split("//").next().unwrap_or("");
        for root in ["crate::", supers.as_str()] {
            for (at, _) in code.match_indices(root) {
                let rest = &code[at + root.len()..];
                let preceded = code[..at].chars().next_back();
                let inside_a_path =
                    preceded.is_some_and(|c| c.is_alphanumeric() || "_$:".contains(c));
                if inside_a_path || rest.starts_with("super::") {
                    continue;
                }
                paths.push(RootPath {
                    line: number + 1,
                    segment: rest
                        .chars()
                        .take_while(|c| c.is_alphanumeric() || *c == '_' || *c == '{')
                        .collect(),
                    via_crate: root == "crate::",
                });
            }
        }
    }
    paths
}

#[test]
fn no_layer_uses_a_layer_above_it() {
    let layers = layers();
    assert!(
        layers.len() >= 8,
        "lib.rs declares too few layers: {layers:?}"
    );
    let rank = |name: &str| layers.iter().position(|l| l == name);
    let mut files = Vec::new();
    sources(&source_dir(), &mut files);
    let mut violations = Vec::new();
    let mut checked = 0;
    for path in &files {
        let relative = path.strip_prefix(source_dir()).unwrap();
        let top = relative.components().next().unwrap().as_os_str();
        let top = top.to_str().unwrap().trim_end_matches(".rs");
        let Some(own) = rank(top) else {
            continue; // lib.rs and the tests
        };
        checked += 1;
        let text = fs::read_to_string(path).unwrap();
        let depth = relative.components().count();
        for RootPath {
            line,
            segment,
            via_crate,
        } in crate_paths(&text, depth)
        {
            match rank(&segment) {
                Some(used) if used >= own => {}
                Some(_) => violations.push(format!(
                    "{}:{line}: layer `{top}` uses the higher layer `{segment}`",
                    relative.display()
                )),
                // The binding may use the crate's API; `super::` may name a sibling module.
                None if top == "python" || !via_crate => {}
                None => violations.push(format!(
                    "{}:{line}: `crate::{segment}` is not a layer (name the layer)",
                    relative.display()
                )),
            }
        }
    }
    assert!(checked > 30, "only {checked} files checked");
    assert!(violations.is_empty(), "{}", violations.join("\n"));
}

#[test]
fn the_check_sees_a_violation() {
    let text = "use crate::render::camera::Camera; // crate::python is a comment\n\
                use super::lab::stream;\n";
    let found = |depth| {
        crate_paths(text, depth)
            .into_iter()
            .map(|p| (p.line, p.segment, p.via_crate))
            .collect::<Vec<_>>()
    };
    assert_eq!(
        found(1),
        [(1, "render".to_owned(), true), (2, "lab".to_owned(), false)]
    );
    assert_eq!(found(2), [(1, "render".to_owned(), true)]); // super:: is a sibling there
    let layers = layers();
    let render = layers.iter().position(|l| l == "render").unwrap();
    let simd = layers.iter().position(|l| l == "simd").unwrap();
    assert!(render < simd, "render is declared above simd: {layers:?}");
}
