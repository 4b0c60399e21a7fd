//! Helpers shared by the integration tests: the reference-table reader and a
//! minimal XML well-formedness checker for the SVGs (balanced tags, one root,
//! quoted unique attributes, known entities). Each test crate uses a part.
#![allow(dead_code)]

use std::collections::HashMap;
use std::path::{Path, PathBuf};

/// Where the 40-digit reference tables live (`WEAROPT_REFERENCE_DIR` overrides).
pub fn data_dir() -> PathBuf {
    std::env::var_os("WEAROPT_REFERENCE_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data")))
}

/// The Lennard-Jones curves in a committed file of tests/data (the solver's,
/// written by `scripts/lennard_jones_table.sh`).
pub fn committed_curves(name: &str) -> Vec<wearopt::model::lennard_jones::table::Curve> {
    let path = format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    wearopt::model::lennard_jones::table::parse(&text).expect("it parses")
}

/// Rows of a reference table as (column name → text) maps; `#` lines are comments.
pub fn table(name: &str) -> Vec<HashMap<String, String>> {
    let text = std::fs::read_to_string(data_dir().join(name)).expect("reference table present");
    let mut lines = text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty());
    let header: Vec<String> = lines
        .next()
        .unwrap()
        .split(',')
        .map(str::to_string)
        .collect();
    lines
        .map(|l| {
            header
                .iter()
                .cloned()
                .zip(l.split(',').map(str::to_string))
                .collect()
        })
        .collect()
}

/// A table cell as f64: "inf" parses, and "1e-26467" underflows to 0, as wanted.
/// Relative error of `got` against `want`, measured against `max(scale, |want|)`
/// (exact agreement is 0, whatever the magnitudes).
pub fn rel(got: f64, want: f64, scale: f64) -> f64 {
    if got == want {
        0.0
    } else {
        (got - want).abs() / scale.max(want.abs()).max(f64::MIN_POSITIVE)
    }
}

pub fn num(s: &str) -> f64 {
    s.parse().unwrap_or_else(|_| panic!("not a number: {s}"))
}

/// One start tag: name and attributes.
#[derive(Debug)]
pub struct Element {
    pub name: String,
    pub attributes: HashMap<String, String>,
}

/// Checks entity references in text or an attribute value.
fn check_entities(s: &str) -> Result<(), String> {
    let mut rest = s;
    while let Some(i) = rest.find('&') {
        let tail = &rest[i + 1..];
        let end = tail
            .find(';')
            .ok_or_else(|| format!("unterminated entity in {s:?}"))?;
        let name = &tail[..end];
        let ok = matches!(name, "amp" | "lt" | "gt" | "quot" | "apos")
            || (name.starts_with('#') && name.len() > 1);
        if !ok {
            return Err(format!("unknown entity &{name}; in {s:?}"));
        }
        rest = &tail[end + 1..];
    }
    if s.contains('<') {
        return Err(format!("raw '<' in {s:?}"));
    }
    Ok(())
}

/// A minimal XML well-formedness check for the SVG we write (declaration,
/// elements, quoted attributes, entities, no comments or CDATA): every tag
/// closed in order, one root. Returns the start tags in document order.
pub fn parse_xml(doc: &str) -> Result<Vec<Element>, String> {
    let mut s = doc;
    if let Some(rest) = s.strip_prefix("<?xml") {
        let end = rest.find("?>").ok_or("unterminated XML declaration")?;
        s = &rest[end + 2..];
    }
    let mut stack: Vec<String> = Vec::new();
    let mut elements = Vec::new();
    let mut roots = 0;
    loop {
        let Some(lt) = s.find('<') else {
            check_entities(s)?;
            if !s.trim().is_empty() {
                return Err(format!("text after the root: {s:?}"));
            }
            break;
        };
        let text = &s[..lt];
        check_entities(text)?;
        if text.contains('>') {
            return Err(format!("stray '>' in text {text:?}"));
        }
        if stack.is_empty() && !text.trim().is_empty() {
            return Err(format!("text outside the root: {text:?}"));
        }
        s = &s[lt + 1..];
        if let Some(rest) = s.strip_prefix('/') {
            let gt = rest.find('>').ok_or("unterminated end tag")?;
            let name = rest[..gt].trim();
            match stack.pop() {
                Some(open) if open == name => {}
                other => return Err(format!("</{name}> closes {other:?}")),
            }
            s = &rest[gt + 1..];
            continue;
        }
        let name_end = s
            .find(|c: char| c.is_whitespace() || c == '>' || c == '/')
            .ok_or("unterminated start tag")?;
        let name = s[..name_end].to_string();
        if name.is_empty()
            || !name
                .chars()
                .all(|c| c.is_alphanumeric() || "-_:.".contains(c))
        {
            return Err(format!("bad element name {name:?}"));
        }
        s = &s[name_end..];
        let mut attributes = HashMap::new();
        let self_closing;
        loop {
            s = s.trim_start();
            if let Some(rest) = s.strip_prefix("/>") {
                self_closing = true;
                s = rest;
                break;
            }
            if let Some(rest) = s.strip_prefix('>') {
                self_closing = false;
                s = rest;
                break;
            }
            let eq = s
                .find('=')
                .ok_or_else(|| format!("attribute without value in <{name}>"))?;
            let key = s[..eq].trim().to_string();
            if key.is_empty() || key.contains(char::is_whitespace) {
                return Err(format!("bad attribute name {key:?} in <{name}>"));
            }
            let rest = &s[eq + 1..];
            let quote = rest.chars().next().ok_or("unterminated attribute")?;
            if quote != '"' && quote != '\'' {
                return Err(format!("unquoted attribute {key} in <{name}>"));
            }
            let close = rest[1..]
                .find(quote)
                .ok_or("unterminated attribute value")?;
            let value = &rest[1..1 + close];
            check_entities(value)?;
            if attributes.insert(key.clone(), value.to_string()).is_some() {
                return Err(format!("duplicate attribute {key} in <{name}>"));
            }
            s = &rest[close + 2..];
        }
        if stack.is_empty() {
            roots += 1;
        }
        if !self_closing {
            stack.push(name.clone());
        }
        elements.push(Element { name, attributes });
    }
    if !stack.is_empty() {
        return Err(format!("unclosed elements {stack:?}"));
    }
    if roots != 1 {
        return Err(format!("{roots} root elements"));
    }
    Ok(elements)
}

/// The `wearopt` binary of this build.
pub fn wearopt() -> assert_cmd::Command {
    assert_cmd::Command::cargo_bin("wearopt").expect("binary builds")
}

/// Runs `cmd`, checks that it exits with `code`, and returns its stdout.
pub fn stdout(cmd: &mut assert_cmd::Command, code: i32) -> Vec<u8> {
    cmd.assert().code(code).get_output().stdout.clone()
}

/// Runs `cmd`, checks that it exits with `code`, and returns its stderr.
pub fn stderr(cmd: &mut assert_cmd::Command, code: i32) -> Vec<u8> {
    cmd.assert().code(code).get_output().stderr.clone()
}

/// A shipped problem (`problems/{stem}.toml`) under another asperity law
/// (`adhesion_model = "{law}"` in place of its own), written beside the test
/// binaries; its path. For tests that pin one law's landscape on a shipped
/// scene (the hub's JKR pull-off of 1e-63 N, say) after the scene moved on.
pub fn under_law(stem: &str, law: &str) -> PathBuf {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("problems").join(format!("{stem}.toml")))
        .expect("shipped problem");
    let line = text
        .lines()
        .find(|l| l.starts_with("adhesion_model"))
        .expect("the problem names its law");
    let text = text.replacen(line, &format!("adhesion_model = \"{law}\""), 1);
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"));
    let path = dir.join(format!("{stem}-{law}.toml"));
    // Tests run in parallel: each writes its own file and renames it into
    // place, so no reader sees a half-written one.
    let own = dir.join(format!(
        "{stem}-{law}.{:?}.part",
        std::thread::current().id()
    ));
    std::fs::write(&own, text).expect("tmp is writable");
    std::fs::rename(&own, &path).expect("tmp is writable");
    path
}

/// How much of an accuracy campaign a test runs. The default run keeps one
/// representative case of each claim (the law holds its stated error there);
/// the full campaign, behind `#[ignore]`, measures the stated error over every
/// case and checks that it is the worst one found (within [0.5, margin] of it).
/// Run every campaign before changing a law or its table:
/// `cargo test --release --test all -- --ignored campaign`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scope {
    /// One representative case per claim: fast, in the default run.
    Representative,
    /// Every case the stated error was measured on.
    Every,
}

impl Scope {
    /// `all` under `Every`; the items of `all` at `picks` under `Representative`.
    pub fn pick<T: Clone>(self, all: &[T], picks: &[usize]) -> Vec<T> {
        match self {
            Scope::Every => all.to_vec(),
            Scope::Representative => picks.iter().map(|&i| all[i].clone()).collect(),
        }
    }

    /// The measured `worst` against the `stated` error: at most `margin` times it
    /// always, and at least half of it over the whole campaign (the statement is
    /// the measurement, not a loose bound).
    pub fn as_stated(self, worst: f64, stated: f64, margin: f64) {
        assert!(
            worst <= margin * stated,
            "{worst:e} above the stated {stated:e}"
        );
        if self == Scope::Every {
            assert!(
                worst >= 0.5 * stated,
                "{worst:e} far below the stated {stated:e}"
            );
        }
    }
}
