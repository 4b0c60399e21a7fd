//! ASCII matrix: rows of heights along y, columns along x, separated by whitespace (or
//! commas and semicolons). Lines starting with `#` are comments, except Gwyddion's
//! header lines `# Width: 5.000 µm`, `# Height: 5.000 µm` (the real sizes) and
//! `# Value units: m`, which give the pixel size (real size / points) and the height unit.
//! `NaN` marks a missing point. With decimal commas ("1,25"; `decimal_comma`) the
//! columns are separated by whitespace or semicolons only; a file written so and read
//! without it is refused (each height would split into two columns).

use super::{grid_size, length_unit, Format, Scan};
use crate::units::{parse_quantity, Dimension};

pub(super) fn read(bytes: &[u8], decimal_comma: bool) -> Result<Scan, String> {
    let text = std::str::from_utf8(bytes)
        .map_err(|e| format!("not UTF-8 text (byte {})", e.valid_up_to()))?;
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let (mut width, mut height, mut unit) = (None, None, None);
    let mut values = Vec::new();
    let mut nx = 0usize;
    let mut ny = 0usize;
    for (k, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() {
            continue;
        }
        if let Some(comment) = line.strip_prefix('#') {
            if let Some((key, value)) = comment.split_once(':') {
                let value = value.trim();
                let length = || {
                    parse_quantity(value, Dimension::Length)
                        .ok()
                        .filter(|x| x.is_finite() && *x > 0.0)
                        .filter(|_| value.chars().any(|c| c.is_alphabetic() || c == 'Å'))
                        .ok_or_else(|| {
                            format!(
                                "line {}: {} = {value:?} is not a length with a unit",
                                k + 1,
                                key.trim()
                            )
                        })
                };
                match key.trim() {
                    "Width" => width = Some(length()?),
                    "Height" => height = Some(length()?),
                    "Value units" => {
                        unit = Some(length_unit(value).ok_or_else(|| {
                            format!(
                                "line {}: Value units = {value:?} is not a length unit",
                                k + 1
                            )
                        })?)
                    }
                    _ => {}
                }
            }
            continue;
        }
        if !decimal_comma && decimal_commas(line) {
            return Err(format!(
                "line {}: {:?} writes its decimals with commas: read so, every height would split into two columns; give --decimal-comma (decimal_comma = true in a problem file's [roughness])",
                k + 1,
                line.chars().take(40).collect::<String>()
            ));
        }
        let start = values.len();
        let separator = |c: char| c.is_whitespace() || c == ';' || (c == ',' && !decimal_comma);
        for token in line.split(separator).filter(|t| !t.is_empty()) {
            let owned;
            let token = if decimal_comma && token.contains(',') {
                owned = token.replacen(',', ".", 1);
                owned.as_str()
            } else {
                token
            };
            let x: f64 = token.parse().map_err(|_| {
                format!(
                    "line {}: {:?} is not a number",
                    k + 1,
                    token.chars().take(40).collect::<String>()
                )
            })?;
            if x.is_infinite() {
                return Err(format!("line {}: infinite value {token:?}", k + 1));
            }
            values.push(x);
        }
        let row = values.len() - start;
        if ny == 0 {
            nx = row;
        } else if row != nx {
            return Err(format!(
                "line {}: {row} values, but the first row has {nx}; every row must have as many",
                k + 1
            ));
        }
        ny += 1;
    }
    if ny == 0 {
        return Err("no rows of numbers".into());
    }

    grid_size(nx, ny)?;
    let pixel_size = match (width, height) {
        (Some(w), Some(h)) => Some((w / nx as f64, h / ny as f64)),
        (Some(w), None) if ny == 1 => Some((w / nx as f64, w / nx as f64)),
        _ => None,
    };
    Ok(Scan {
        format: Format::Ascii,
        nx,
        ny,
        values,
        height_unit: unit,
        pixel_size,
    })
}

/// Whether a data line writes decimals with commas: split on whitespace and
/// semicolons, every token is an integer, NaN or a decimal-comma number
/// (`-1,25`, `3,5e-9`), and at least one has a comma. A comma-separated row of
/// three or more integers is one token with several commas, so it does not
/// count; a matrix needs three columns, so two integers joined by a comma
/// cannot be a row.
fn decimal_commas(line: &str) -> bool {
    let mut any = false;
    for token in line
        .split(|c: char| c.is_whitespace() || c == ';')
        .filter(|t| !t.is_empty())
    {
        if token.eq_ignore_ascii_case("nan") {
            continue;
        }
        let body = token.strip_prefix(['-', '+']).unwrap_or(token);
        let (mantissa, exponent) = match body.find(['e', 'E']) {
            Some(i) => (&body[..i], Some(&body[i + 1..])),
            None => (body, None),
        };
        if let Some(e) = exponent {
            let e = e.strip_prefix(['-', '+']).unwrap_or(e);
            if e.is_empty() || !e.chars().all(|c| c.is_ascii_digit()) {
                return false;
            }
        }
        let digits = |s: &str| !s.is_empty() && s.chars().all(|c| c.is_ascii_digit());
        match mantissa.split_once(',') {
            Some((a, b)) if (a.is_empty() || digits(a)) && digits(b) => any = true,
            None if digits(mantissa) => {}
            _ => return false,
        }
    }
    any
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decimal_commas_are_told_from_separators() {
        assert!(decimal_commas("1,25 -0,5 3,5e-9"));
        assert!(decimal_commas("1,25;2,5;NaN;4"));
        assert!(decimal_commas("0 0,5 1"));
        assert!(!decimal_commas("1.25 2.5 3"));
        assert!(!decimal_commas("1,2,3"));
        assert!(!decimal_commas("1.5, 2.5, 3.5"));
        assert!(!decimal_commas("1 2 3"));
    }

    #[test]
    fn a_decimal_comma_file_is_refused_or_read() {
        let text = b"1,5 2,5 3,5\n4,5 5,5 6,5\n7 8 9,25\n";
        let e = read(text, false).unwrap_err();
        assert!(e.contains("--decimal-comma"), "{e}");
        let scan = read(text, true).unwrap();
        assert_eq!((scan.nx, scan.ny), (3, 3));
        assert_eq!(scan.values, [1.5, 2.5, 3.5, 4.5, 5.5, 6.5, 7.0, 8.0, 9.25]);
        // A comma-separated matrix with decimal points reads as before.
        let scan = read(b"1.5,2.5,3.5\n4,5,6\n7,8,9\n", false).unwrap();
        assert_eq!(scan.values[..3], [1.5, 2.5, 3.5]);
    }
}
