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

fn source_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// Every `.rs` file under `dir`, with its path relative to `src/`.
fn sources(dir: &Path, found: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            sources(&path, found);
        } else if path.extension().is_some_and(|e| e == "rs") {
            found.push(path);
        }
    }
}

/// The first segment of every `crate::` path in the code of `text` (comments dropped).
fn crate_paths(text: &str) -> Vec<(usize, String)> {
    let mut paths = Vec::new();
    for (number, line) in text.lines().enumerate() {
        let code = line.split("//").next().unwrap_or("");
        let mut rest = code;
        while let Some(at) = rest.find("crate::") {
            let preceded = rest[..at].chars().next_back();
            rest = &rest[at + "crate::".len()..];
            if preceded.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == '$') {
                continue;
            }
            let segment: String = rest
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_' || *c == '{')
                .collect();
            paths.push((number + 1, segment));
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
        for (line, segment) in crate_paths(&text) {
            match rank(&segment) {
                Some(used) if used >= own => {}
                Some(_) => violations.push(format!(
                    "{}:{line}: layer `{top}` uses the higher layer `{segment}`",
                    relative.display()
                )),
                None if top == "python" => {} // the binding may use the crate's API
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
    let text = "use crate::render::camera::Camera; // crate::python is a comment\n";
    assert_eq!(crate_paths(text), [(1, "render".to_owned())]);
    let layers = layers();
    let render = layers.iter().position(|l| l == "render").unwrap();
    let simd = layers.iter().position(|l| l == "simd").unwrap();
    assert!(render < simd, "render is declared above simd: {layers:?}");
}
