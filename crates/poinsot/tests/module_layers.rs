//! The core's modules depend one way (ARCHITECTURE.md): each module of [`LAYERS`] refers only to
//! modules after it (`crate::name` in its files, comments aside), so there is no cycle; a new
//! module must be placed in the list.

use std::fs;
use std::path::{Path, PathBuf};

/// The core's modules from the top down, as ARCHITECTURE.md lists them.
const LAYERS: &[&str] = &[
    "sweep",
    "defaults",
    "dynamics",
    "analytic",
    "earth",
    "rows",
    "frames",
    "inertia",
    "special",
    "rotation",
    "integrate",
    "control",
    "limits",
    "simd",
    "error",
];

fn rust_files(path: &Path, out: &mut Vec<PathBuf>) {
    if path.is_dir() {
        for entry in fs::read_dir(path).unwrap() {
            rust_files(&entry.unwrap().path(), out);
        }
    } else if path.is_file() && path.extension().is_some_and(|e| e == "rs") {
        out.push(path.to_path_buf());
    }
}

/// The modules of [`LAYERS`] that `source` names as `crate::name` or inside `crate::{…}`,
/// comments removed.
fn referenced(source: &str) -> Vec<String> {
    let code: String = source
        .lines()
        .map(|l| l.split("//").next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n");
    let mut names = Vec::new();
    let mut rest = code.as_str();
    while let Some(at) = rest.find("crate::") {
        rest = &rest[at + "crate::".len()..];
        let group = if let Some(inner) = rest.strip_prefix('{') {
            &inner[..inner.find('}').unwrap_or(inner.len())]
        } else {
            rest
        };
        for part in group.split(',') {
            let name: String = part
                .trim()
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            if LAYERS.contains(&name.as_str()) {
                names.push(name);
            }
            if !rest.starts_with('{') {
                break;
            }
        }
    }
    names
}

/// For each module, the lower-or-equal-layer violations: (module, file, referenced module).
fn upward_references(src: &Path) -> Vec<(String, String, String)> {
    let mut bad = Vec::new();
    for (rank, module) in LAYERS.iter().enumerate() {
        let mut files = Vec::new();
        rust_files(&src.join(format!("{module}.rs")), &mut files);
        rust_files(&src.join(module), &mut files);
        assert!(!files.is_empty(), "{module}: no source");
        for file in files {
            let text = fs::read_to_string(&file).unwrap();
            for name in referenced(&text) {
                let to = LAYERS.iter().position(|m| *m == name).unwrap();
                if name != *module && to <= rank {
                    bad.push((module.to_string(), file.display().to_string(), name));
                }
            }
        }
    }
    bad
}

#[test]
fn modules_depend_one_way() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    // Every module of the crate is placed in the list.
    for entry in fs::read_dir(&src).unwrap() {
        let path = entry.unwrap().path();
        let stem = path.file_stem().unwrap().to_string_lossy().to_string();
        if stem != "lib" {
            assert!(
                LAYERS.contains(&stem.as_str()),
                "module {stem} is not in LAYERS"
            );
        }
    }
    let bad = upward_references(&src);
    assert!(bad.is_empty(), "references up the layers: {bad:#?}");
}

#[test]
fn an_upward_reference_is_seen_negative_control() {
    // `analytic` naming `dynamics` (as free_states.rs did for the batch's row checks) and a
    // grouped import are both found; comments are not code.
    assert_eq!(
        referenced("use crate::dynamics::{check_row, in_row}; // crate::sweep"),
        ["dynamics"]
    );
    assert_eq!(
        referenced("use crate::{dynamics::Torque, Vec3, rows::check_row};"),
        ["dynamics", "rows"]
    );
    // A tree of empty modules in which `analytic` imports from `dynamics`: one violation.
    let src = std::env::temp_dir().join(format!("poinsot_layers_{}", std::process::id()));
    fs::create_dir_all(&src).unwrap();
    for module in LAYERS {
        fs::write(src.join(format!("{module}.rs")), "").unwrap();
    }
    fs::write(
        src.join("analytic.rs"),
        "use crate::dynamics::{check_every_row, check_row};\n",
    )
    .unwrap();
    let bad = upward_references(&src);
    fs::remove_dir_all(&src).unwrap();
    assert_eq!(bad.len(), 1, "{bad:?}");
    assert_eq!(
        (bad[0].0.as_str(), bad[0].2.as_str()),
        ("analytic", "dynamics")
    );
}
