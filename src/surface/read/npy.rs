//! NumPy `.npy` (format versions 1.0, 2.0, 3.0, as NumPy's `numpy.lib.format` documents
//! it): the magic `\x93NUMPY`, two version bytes, the header length (u16 little-endian in
//! 1.0, u32 in 2.0 and 3.0), a Python dict literal with `descr`, `fortran_order` and
//! `shape`, then the array data.
//!
//! Read by hand: the header is three keys of a Python literal, and the crates that read
//! `.npy` (npyz, ndarray-npy) parse it with a general Python-literal parser that brings a
//! parser generator and big integers into the build. A 2-D array is an image, shape
//! (ny, nx): rows along y, columns along x; a 1-D array is a profile. Element types: float
//! f4, f8 and integer i1, i2, i4, i8, u1, u2, u4, u8, either byte order.

use super::{grid_size, Format, Scan};

const MAGIC: &[u8] = b"\x93NUMPY";

/// A value of the header dict.
#[derive(Debug, PartialEq)]
enum Value {
    Str(String),
    Bool(bool),
    Tuple(Vec<usize>),
}

/// Parses `{'descr': '<f8', 'fortran_order': False, 'shape': (3, 4), }`.
fn parse_dict(s: &str) -> Result<Vec<(String, Value)>, String> {
    let s = s.trim();
    let inner = s
        .strip_prefix('{')
        .and_then(|r| r.strip_suffix('}'))
        .ok_or("the header is not a Python dict {...}")?;
    let mut rest = inner.trim_start();
    let mut out = Vec::new();
    let quoted = |r: &str| -> Result<(String, usize), String> {
        let q = r.chars().next().ok_or("unexpected end of the header")?;
        if q != '\'' && q != '"' {
            return Err(format!("expected a quoted string at {:?}", head(r)));
        }
        let end = r[1..].find(q).ok_or("unterminated string in the header")?;
        Ok((r[1..1 + end].to_string(), end + 2))
    };
    while !rest.is_empty() {
        let (key, used) = quoted(rest)?;
        rest = rest[used..].trim_start();
        rest = rest
            .strip_prefix(':')
            .ok_or_else(|| format!("expected ':' after '{key}'"))?
            .trim_start();
        let value = if rest.starts_with('\'') || rest.starts_with('"') {
            let (v, used) = quoted(rest)?;
            rest = &rest[used..];
            Value::Str(v)
        } else if let Some(r) = rest.strip_prefix("True") {
            rest = r;
            Value::Bool(true)
        } else if let Some(r) = rest.strip_prefix("False") {
            rest = r;
            Value::Bool(false)
        } else if let Some(r) = rest.strip_prefix('(') {
            let end = r.find(')').ok_or("unterminated tuple in the header")?;
            let dims = r[..end]
                .split(',')
                .map(str::trim)
                .filter(|t| !t.is_empty())
                .map(|t| {
                    t.trim_end_matches('L')
                        .parse::<usize>()
                        .map_err(|_| format!("shape entry {t:?} is not a non-negative integer"))
                })
                .collect::<Result<Vec<_>, _>>()?;
            rest = &r[end + 1..];
            Value::Tuple(dims)
        } else {
            return Err(format!(
                "cannot read the value of '{key}' at {:?}",
                head(rest)
            ));
        };
        out.push((key, value));
        rest = rest.trim_start();
        if let Some(r) = rest.strip_prefix(',') {
            rest = r.trim_start();
        } else if !rest.is_empty() {
            return Err(format!("expected ',' at {:?}", head(rest)));
        }
    }
    Ok(out)
}

fn head(s: &str) -> String {
    s.chars().take(30).collect()
}

/// (little endian?, kind, bytes) of a `descr` such as `<f8`.
fn dtype(descr: &str) -> Result<(bool, char, usize), String> {
    let bad = || {
        format!("element type descr = {descr:?} is not supported; expected a float (<f8, <f4) or integer type")
    };
    let mut chars = descr.chars();
    let order = chars.next().ok_or_else(bad)?;
    let kind = chars.next().ok_or_else(bad)?;
    let size: usize = chars.as_str().parse().map_err(|_| bad())?;
    let little = match order {
        '<' | '=' => true,
        '>' => false,
        '|' if size == 1 => true,
        _ => return Err(bad()),
    };
    match (kind, size) {
        ('f', 4 | 8) | ('i' | 'u', 1 | 2 | 4 | 8) => Ok((little, kind, size)),
        _ => Err(bad()),
    }
}

fn decode(little: bool, kind: char, c: &[u8]) -> f64 {
    let mut b = [0u8; 8];
    let n = c.len();
    if little {
        b[..n].copy_from_slice(c);
    } else {
        for (k, &x) in c.iter().rev().enumerate() {
            b[k] = x;
        }
    }
    match (kind, n) {
        ('f', 4) => f32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
        ('f', _) => f64::from_le_bytes(b),
        ('i', 1) => b[0] as i8 as f64,
        ('i', 2) => i16::from_le_bytes([b[0], b[1]]) as f64,
        ('i', 4) => i32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
        ('i', _) => i64::from_le_bytes(b) as f64,
        ('u', 1) => b[0] as f64,
        ('u', 2) => u16::from_le_bytes([b[0], b[1]]) as f64,
        ('u', 4) => u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64,
        _ => u64::from_le_bytes(b) as f64,
    }
}

pub(super) fn read(bytes: &[u8]) -> Result<Scan, String> {
    if bytes.len() < 10 || &bytes[..6] != MAGIC {
        return Err("the file does not start with the NumPy magic \\x93NUMPY".into());
    }
    let major = bytes[6];
    let (len, start): (usize, usize) = match major {
        1 => (u16::from_le_bytes([bytes[8], bytes[9]]) as usize, 10),
        2 | 3 => {
            if bytes.len() < 12 {
                return Err("truncated header".into());
            }
            (
                u32::from_le_bytes([bytes[8], bytes[9], bytes[10], bytes[11]]) as usize,
                12,
            )
        }
        v => return Err(format!("format version {v}.{} is not 1, 2 or 3", bytes[7])),
    };
    let end = start
        .checked_add(len)
        .filter(|&e| e <= bytes.len())
        .ok_or("the header is longer than the file (truncated?)")?;
    let header = std::str::from_utf8(&bytes[start..end])
        .map_err(|_| "the header is not text".to_string())?;
    let dict = parse_dict(header)?;
    let get = |k: &str| dict.iter().find(|(key, _)| key == k).map(|(_, v)| v);
    let Some(Value::Str(descr)) = get("descr") else {
        return Err("the header has no 'descr' string".into());
    };
    let Some(Value::Bool(fortran)) = get("fortran_order") else {
        return Err("the header has no 'fortran_order' True/False".into());
    };
    let Some(Value::Tuple(shape)) = get("shape") else {
        return Err("the header has no 'shape' tuple".into());
    };
    let (little, kind, size) = dtype(descr)?;
    let (ny, nx) = match shape.as_slice() {
        [n] => (1, *n),
        [r, c] => (*r, *c),
        s => {
            return Err(format!(
                "shape {s:?}: expected a 2-D array (ny, nx) or a 1-D profile"
            ))
        }
    };
    let n = grid_size(nx, ny)?;
    let data = &bytes[end..];
    if data.len() != n * size {
        return Err(format!(
            "shape {shape:?} of {descr} needs {} data bytes, the file has {}",
            n * size,
            data.len()
        ));
    }
    let raw: Vec<f64> = data
        .chunks_exact(size)
        .map(|c| decode(little, kind, c))
        .collect();
    let values = if *fortran && ny > 1 {
        // Column-major: element (j, i) is at i * ny + j.
        let mut v = vec![0.0; n];
        for j in 0..ny {
            for i in 0..nx {
                v[j * nx + i] = raw[i * ny + j];
            }
        }
        v
    } else {
        raw
    };
    Ok(Scan {
        format: Format::Npy,
        nx,
        ny,
        values,
        height_unit: None,
        pixel_size: None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn header_dict() {
        let d =
            parse_dict("{'descr': '<f8', 'fortran_order': False, 'shape': (3, 4), }   ").unwrap();
        assert_eq!(d[0], ("descr".into(), Value::Str("<f8".into())));
        assert_eq!(d[1], ("fortran_order".into(), Value::Bool(false)));
        assert_eq!(d[2], ("shape".into(), Value::Tuple(vec![3, 4])));
        assert_eq!(
            parse_dict("{'shape': (5,)}").unwrap()[0].1,
            Value::Tuple(vec![5])
        );
        assert!(parse_dict("{'descr': '<f8'").is_err());
        assert!(parse_dict("{'shape': (a, 4)}").is_err());
    }

    #[test]
    fn dtypes() {
        assert_eq!(dtype("<f8").unwrap(), (true, 'f', 8));
        assert_eq!(dtype(">f4").unwrap(), (false, 'f', 4));
        assert_eq!(dtype("|u1").unwrap(), (true, 'u', 1));
        assert!(dtype("<c16").is_err());
        assert!(dtype("|f8").is_err());
        assert!(dtype("").is_err());
        assert_eq!(decode(false, 'f', &1.5f32.to_be_bytes()), 1.5);
        assert_eq!(decode(true, 'i', &(-3i16).to_le_bytes()), -3.0);
    }
}
