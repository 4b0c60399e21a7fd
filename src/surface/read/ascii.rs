//! ASCII matrix: rows of heights along y, columns along x, separated by whitespace (or
//! commas and semicolons). Lines starting with `#` are comments, except Gwyddion's
//! header lines `# Width: 5.000 µm`, `# Height: 5.000 µm` (the real sizes) and
//! `# Value units: m`, which give the pixel size (real size / points) and the height unit.
//! `NaN` marks a missing point.

use super::{grid_size, length_unit, Format, Scan};
use crate::units::{parse_quantity, Dimension};

pub(super) fn read(bytes: &[u8]) -> Result<Scan, String> {
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
        let start = values.len();
        for token in line
            .split(|c: char| c.is_whitespace() || c == ',' || c == ';')
            .filter(|t| !t.is_empty())
        {
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
