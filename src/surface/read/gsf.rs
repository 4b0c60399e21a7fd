//! Gwyddion Simple Field (`.gsf`), as specified on gwyddion.net: the line
//! `Gwyddion Simple Field 1.0`, then `Key = Value` lines (XRes and YRes required; XReal,
//! YReal, XYUnits, ZUnits and others optional), then 1 to 4 NUL bytes so that the data
//! starts at a multiple of 4, then XRes·YRes little-endian IEEE f32, row by row.

use super::{grid_size, length_unit, Format, Scan};

const MAGIC: &str = "Gwyddion Simple Field 1.0";

pub(super) fn read(bytes: &[u8]) -> Result<Scan, String> {
    let nul = bytes
        .iter()
        .position(|&b| b == 0)
        .ok_or("no NUL byte ends the header (truncated file?)")?;
    let header = std::str::from_utf8(&bytes[..nul])
        .map_err(|e| format!("the header is not UTF-8 text (byte {})", e.valid_up_to()))?;
    let mut lines = header.lines();
    let first = lines.next().unwrap_or("").trim_end_matches('\r');
    if first != MAGIC {
        return Err(format!(
            "the first line is {:?}, not {MAGIC:?}",
            first.chars().take(60).collect::<String>()
        ));
    }
    let (mut xres, mut yres) = (None, None);
    let (mut xreal, mut yreal) = (None, None);
    let (mut xy_units, mut z_units) = (None, None);
    for line in lines {
        let line = line.trim();
        if line.is_empty() {
            continue;
        }
        let Some((key, value)) = line.split_once('=') else {
            return Err(format!("header line {line:?} is not `Key = Value`"));
        };
        let (key, value) = (key.trim(), value.trim());
        let positive_int = |v: &str| -> Result<usize, String> {
            v.parse::<usize>()
                .ok()
                .filter(|&n| n > 0)
                .ok_or_else(|| format!("{key} = {v:?}: must be a positive integer"))
        };
        let positive_real = |v: &str| -> Result<f64, String> {
            v.parse::<f64>()
                .ok()
                .filter(|x| x.is_finite() && *x > 0.0)
                .ok_or_else(|| format!("{key} = {v:?}: must be a positive number"))
        };
        match key {
            "XRes" => xres = Some(positive_int(value)?),
            "YRes" => yres = Some(positive_int(value)?),
            "XReal" => xreal = Some(positive_real(value)?),
            "YReal" => yreal = Some(positive_real(value)?),
            "XYUnits" => xy_units = Some(value.to_string()),
            "ZUnits" => z_units = Some(value.to_string()),
            _ => {}
        }
    }
    let nx = xres.ok_or("the header has no XRes")?;
    let ny = yres.ok_or("the header has no YRes")?;
    let n = grid_size(nx, ny)?;
    let xy_unit = match &xy_units {
        None => None,
        Some(u) => {
            Some(length_unit(u).ok_or_else(|| format!("XYUnits = {u:?} is not a length unit"))?)
        }
    };
    let height_unit = match &z_units {
        None => None,
        Some(u) => {
            Some(length_unit(u).ok_or_else(|| format!("ZUnits = {u:?} is not a length unit"))?)
        }
    };
    let offset = (nul / 4 + 1) * 4;
    if bytes.len() < offset || bytes[nul..offset].iter().any(|&b| b != 0) {
        return Err(format!(
            "the header must be followed by NUL bytes up to byte {offset} (a multiple of 4)"
        ));
    }
    let data = &bytes[offset..];
    if data.len() != 4 * n {
        return Err(format!(
            "XRes × YRes = {nx} × {ny} needs {} data bytes, the file has {}",
            4 * n,
            data.len()
        ));
    }
    let values = data
        .chunks_exact(4)
        .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]) as f64)
        .collect();
    let pixel_size = match (xreal, yreal, xy_unit) {
        (Some(xr), Some(yr), Some(unit)) => Some((xr * unit / nx as f64, yr * unit / ny as f64)),
        _ => None,
    };
    Ok(Scan {
        format: Format::Gsf,
        nx,
        ny,
        values,
        height_unit,
        pixel_size,
    })
}

/// Writes a GSF file (for tests, benches and the shipped example): heights in metres,
/// lateral sizes in metres.
pub fn write(nx: usize, ny: usize, xreal: f64, yreal: f64, heights: &[f64]) -> Vec<u8> {
    let mut out = format!(
        "{MAGIC}\nXRes = {nx}\nYRes = {ny}\nXReal = {xreal:e}\nYReal = {yreal:e}\nXYUnits = m\nZUnits = m\n"
    )
    .into_bytes();
    let pad = 4 - out.len() % 4;
    out.extend(std::iter::repeat_n(0u8, pad));
    for h in heights {
        out.extend_from_slice(&(*h as f32).to_le_bytes());
    }
    out
}
