//! Sets `WEAROPT_BUILD_ID`: a hash of the sources this build compiles (every file
//! under `src/`, `Cargo.toml` and `Cargo.lock`), so that outputs which must come
//! from one build (the parts of a sweep: `report::sweep::fingerprint`) can tell two
//! builds of one version apart — a changed line of the model changes the id, the
//! same sources give the same id on every machine and for the command line and the
//! Python package alike.

use std::path::{Path, PathBuf};

fn files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            files(&path, out);
        } else {
            out.push(path);
        }
    }
}

fn main() {
    let root = PathBuf::from(std::env::var_os("CARGO_MANIFEST_DIR").unwrap_or_default());
    let mut list = vec![root.join("Cargo.toml"), root.join("Cargo.lock")];
    files(&root.join("src"), &mut list);
    list.sort();
    // FNV-1a (64 bit) of each file's path (relative to the crate) and content.
    let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
    let mut eat = |bytes: &[u8]| {
        for &b in bytes {
            hash ^= u64::from(b);
            hash = hash.wrapping_mul(0x0000_0100_0000_01b3);
        }
        hash ^= 0xff;
        hash = hash.wrapping_mul(0x0000_0100_0000_01b3);
    };
    for path in &list {
        let name = path.strip_prefix(&root).unwrap_or(path);
        eat(name.to_string_lossy().replace('\\', "/").as_bytes());
        eat(&std::fs::read(path).unwrap_or_default());
    }
    println!("cargo:rustc-env=WEAROPT_BUILD_ID={hash:016x}");
    println!("cargo:rerun-if-changed=src");
    println!("cargo:rerun-if-changed=Cargo.toml");
    println!("cargo:rerun-if-changed=Cargo.lock");
    println!("cargo:rerun-if-changed=build.rs");
}
