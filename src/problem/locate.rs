//! Turning a byte span from the TOML deserializer into a dotted key such as
//! `bodies.a.material` or `constraint[1].max`, by walking the span-preserving
//! document tree ([`toml::de::DeTable`]).

use std::ops::Range;

use toml::de::{DeTable, DeValue};
use toml::Spanned;

/// One step of a path: a table key or an array index.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) enum Segment {
    Key(String),
    Index(usize),
}

/// Renders a path as written in messages: `constraint[1].max`.
pub(crate) fn render(path: &[Segment]) -> String {
    let mut out = String::new();
    for segment in path {
        match segment {
            Segment::Key(k) => {
                if !out.is_empty() {
                    out.push('.');
                }
                out.push_str(k);
            }
            Segment::Index(i) => out.push_str(&format!("[{i}]")),
        }
    }
    out
}

/// What a span turned out to be.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Hit {
    /// Path to the key or value.
    pub path: Vec<Segment>,
    /// The span is the key itself (as for "unknown field"), not its value.
    pub is_key: bool,
}

/// Finds the key or value whose span is exactly `span`; failing that, the innermost
/// value whose span contains it.
pub(crate) fn find(root: &Spanned<DeTable<'_>>, span: &Range<usize>) -> Option<Hit> {
    let mut path = Vec::new();
    if let Some(hit) = exact_in_table(root.get_ref(), span, &mut path) {
        return Some(hit);
    }
    let mut best: Option<(usize, Vec<Segment>)> = None;
    containing_in_table(root.get_ref(), span, &mut path, &mut best);
    best.map(|(_, path)| Hit {
        path,
        is_key: false,
    })
}

fn exact_in_table(
    table: &DeTable<'_>,
    span: &Range<usize>,
    path: &mut Vec<Segment>,
) -> Option<Hit> {
    for (key, value) in table.iter() {
        path.push(Segment::Key(key.get_ref().to_string()));
        if key.span() == *span || value.span() == *span {
            let hit = Hit {
                path: path.clone(),
                is_key: key.span() == *span,
            };
            path.pop();
            return Some(hit);
        }
        let found = exact_in_value(value.get_ref(), span, path);
        path.pop();
        if found.is_some() {
            return found;
        }
    }
    None
}

fn exact_in_value(
    value: &DeValue<'_>,
    span: &Range<usize>,
    path: &mut Vec<Segment>,
) -> Option<Hit> {
    match value {
        DeValue::Table(table) => exact_in_table(table, span, path),
        DeValue::Array(array) => {
            for (i, item) in array.iter().enumerate() {
                path.push(Segment::Index(i));
                if item.span() == *span {
                    let hit = Hit {
                        path: path.clone(),
                        is_key: false,
                    };
                    path.pop();
                    return Some(hit);
                }
                let found = exact_in_value(item.get_ref(), span, path);
                path.pop();
                if found.is_some() {
                    return found;
                }
            }
            None
        }
        _ => None,
    }
}

fn contains(outer: &Range<usize>, inner: &Range<usize>) -> bool {
    outer.start <= inner.start && inner.end <= outer.end
}

fn containing_in_table(
    table: &DeTable<'_>,
    span: &Range<usize>,
    path: &mut Vec<Segment>,
    best: &mut Option<(usize, Vec<Segment>)>,
) {
    for (key, value) in table.iter() {
        path.push(Segment::Key(key.get_ref().to_string()));
        containing_in_value(value, span, path, best);
        path.pop();
    }
}

fn containing_in_value(
    value: &Spanned<DeValue<'_>>,
    span: &Range<usize>,
    path: &mut Vec<Segment>,
    best: &mut Option<(usize, Vec<Segment>)>,
) {
    let vs = value.span();
    if contains(&vs, span) {
        let width = vs.end - vs.start;
        if best.as_ref().is_none_or(|(w, _)| width <= *w) {
            *best = Some((width, path.clone()));
        }
    }
    match value.get_ref() {
        DeValue::Table(table) => containing_in_table(table, span, path, best),
        DeValue::Array(array) => {
            for (i, item) in array.iter().enumerate() {
                path.push(Segment::Index(i));
                containing_in_value(item, span, path, best);
                path.pop();
            }
        }
        _ => {}
    }
}
