//! ISO 25178-72 XML (`.x3p`): a zip holding `main.xml` and, unless the data are inline,
//! a binary point file (usually `bindata/data.bin`).
//!
//! `main.xml` gives, under `Record1/Axes`, the axes CX, CY (AxisType `I`: incremental, with
//! Increment = pixel size in metres) and CZ (DataType `I` int16, `L` int32, `F` float32,
//! `D` float64; height = Offset + Increment × stored value, in metres); under `Record3`,
//! `MatrixDimension` (SizeX, SizeY, SizeZ = 1) and either `DataLink/PointDataLink` (the
//! binary file, little-endian, x fastest) or `DataList` (one `Datum` per point, empty = not
//! measured). An optional `ValidPointsLink` names a bit mask: one bit per point, least
//! significant bit first, 1 = valid. All lengths of the format are in metres.

use std::io::{Cursor, Read};

use roxmltree::{Document, Node};

use super::{grid_size, Format, Scan};

/// The one child element of `node` with local name `name`.
fn child<'a, 'i>(node: Node<'a, 'i>, name: &str) -> Option<Node<'a, 'i>> {
    node.children()
        .find(|c| c.is_element() && c.tag_name().name() == name)
}

/// The first descendant element named `name`.
fn find<'a, 'i>(node: Node<'a, 'i>, name: &str) -> Option<Node<'a, 'i>> {
    node.descendants()
        .find(|c| c.is_element() && c.tag_name().name() == name)
}

fn text_of(node: Node, path: &str) -> Result<String, String> {
    let mut n = node;
    for part in path.split('/') {
        n = child(n, part).ok_or_else(|| format!("main.xml has no {path}"))?;
    }
    Ok(n.text().unwrap_or("").trim().to_string())
}

fn number(node: Node, path: &str) -> Result<f64, String> {
    let t = text_of(node, path)?;
    t.parse::<f64>()
        .ok()
        .filter(|x| x.is_finite())
        .ok_or_else(|| format!("{path} = {t:?} is not a finite number"))
}

fn count(node: Node, path: &str) -> Result<usize, String> {
    let t = text_of(node, path)?;
    t.parse::<usize>()
        .map_err(|_| format!("{path} = {t:?} is not a non-negative integer"))
}

/// Reads one member of the archive, refusing more than `limit` bytes (no zip bombs).
fn member(
    zip: &mut zip::ZipArchive<Cursor<&[u8]>>,
    name: &str,
    limit: usize,
) -> Result<Vec<u8>, String> {
    let file = zip
        .by_name(name)
        .map_err(|e| format!("the archive has no readable {name:?}: {e}"))?;
    let mut out = Vec::new();
    file.take(limit as u64 + 1)
        .read_to_end(&mut out)
        .map_err(|e| format!("{name}: {e}"))?;
    if out.len() > limit {
        return Err(format!("{name} is larger than the {limit} bytes expected"));
    }
    Ok(out)
}

/// Bytes per stored value of an X3P data type.
fn width(data_type: &str) -> Result<usize, String> {
    match data_type {
        "I" => Ok(2),
        "L" => Ok(4),
        "F" => Ok(4),
        "D" => Ok(8),
        other => Err(format!(
            "Record1/Axes/CZ/DataType = {other:?}; expected I, L, F or D"
        )),
    }
}

fn decode(data_type: &str, c: &[u8]) -> f64 {
    match data_type {
        "I" => i16::from_le_bytes([c[0], c[1]]) as f64,
        "L" => i32::from_le_bytes([c[0], c[1], c[2], c[3]]) as f64,
        "F" => f32::from_le_bytes([c[0], c[1], c[2], c[3]]) as f64,
        _ => f64::from_le_bytes([c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]]),
    }
}

pub(super) fn read(bytes: &[u8]) -> Result<Scan, String> {
    let mut zip =
        zip::ZipArchive::new(Cursor::new(bytes)).map_err(|e| format!("not a zip archive: {e}"))?;
    let xml = member(&mut zip, "main.xml", 16 << 20)?;
    let xml = String::from_utf8(xml).map_err(|_| "main.xml is not UTF-8".to_string())?;
    let doc = Document::parse(&xml).map_err(|e| format!("main.xml: {e}"))?;
    let root = doc.root_element();
    let axes = find(root, "Axes").ok_or("main.xml has no Record1/Axes")?;
    let (cx, cy, cz) = (
        child(axes, "CX").ok_or("main.xml has no Axes/CX")?,
        child(axes, "CY").ok_or("main.xml has no Axes/CY")?,
        child(axes, "CZ").ok_or("main.xml has no Axes/CZ")?,
    );
    let mut pixel = [0.0; 2];
    for (k, (axis, name)) in [(cx, "CX"), (cy, "CY")].into_iter().enumerate() {
        let kind = text_of(axis, "AxisType")?;
        if kind != "I" {
            return Err(format!(
                "Axes/{name}/AxisType = {kind:?}: only incremental (I) lateral axes are supported"
            ));
        }
        let inc = number(axis, "Increment")?;
        if inc <= 0.0 {
            return Err(format!("Axes/{name}/Increment = {inc}: must be positive"));
        }
        pixel[k] = inc;
    }
    let data_type = text_of(cz, "DataType")?;
    let size = width(&data_type)?;
    // Increment and Offset of CZ are optional (default 1 and 0).
    let inc_z = if child(cz, "Increment").is_some() {
        number(cz, "Increment")?
    } else {
        1.0
    };
    let off_z = if child(cz, "Offset").is_some() {
        number(cz, "Offset")?
    } else {
        0.0
    };
    let dims = find(root, "MatrixDimension").ok_or("main.xml has no Record3/MatrixDimension")?;
    let nx = count(dims, "SizeX")?;
    let ny = count(dims, "SizeY")?;
    let nz = count(dims, "SizeZ")?;
    if nz != 1 {
        return Err(format!(
            "SizeZ = {nz}: only one layer (SizeZ = 1) is supported"
        ));
    }
    let n = grid_size(nx, ny)?;

    let mut values: Vec<f64> = if let Some(link) = find(root, "PointDataLink") {
        let name = link.text().unwrap_or("").trim().to_string();
        let data = member(&mut zip, &name, n * size)?;
        if data.len() != n * size {
            return Err(format!(
                "{name} holds {} bytes; SizeX × SizeY = {nx} × {ny} values of type {data_type} need {}",
                data.len(),
                n * size
            ));
        }
        data.chunks_exact(size)
            .map(|c| decode(&data_type, c))
            .collect()
    } else if let Some(list) = find(root, "DataList") {
        let mut v = Vec::with_capacity(n);
        for d in list
            .children()
            .filter(|c| c.is_element() && c.tag_name().name() == "Datum")
        {
            if v.len() == n {
                return Err(format!(
                    "DataList holds more than SizeX × SizeY = {n} points"
                ));
            }
            let t = d.text().unwrap_or("").trim();
            if t.is_empty() {
                v.push(f64::NAN);
            } else {
                let x = t
                    .parse::<f64>()
                    .ok()
                    .filter(|x| x.is_finite())
                    .ok_or_else(|| format!("DataList point {} = {t:?} is not a number", v.len()))?;
                v.push(x);
            }
        }
        if v.len() != n {
            return Err(format!(
                "DataList holds {} points; SizeX × SizeY = {nx} × {ny} needs {n}",
                v.len()
            ));
        }
        v
    } else {
        return Err(
            "main.xml has neither Record3/DataLink/PointDataLink nor Record3/DataList".into(),
        );
    };
    for v in &mut values {
        *v = off_z + inc_z * *v;
    }
    if let Some(link) = find(root, "ValidPointsLink") {
        let name = link.text().unwrap_or("").trim().to_string();
        let need = n.div_ceil(8);
        let mask = member(&mut zip, &name, need)?;
        if mask.len() != need {
            return Err(format!(
                "{name} holds {} bytes; {n} points need {need} mask bytes",
                mask.len()
            ));
        }
        for (k, v) in values.iter_mut().enumerate() {
            if mask[k / 8] >> (k % 8) & 1 == 0 {
                *v = f64::NAN;
            }
        }
    }
    Ok(Scan {
        format: Format::X3p,
        nx,
        ny,
        values,
        height_unit: Some(1.0),
        pixel_size: Some((pixel[0], pixel[1])),
    })
}
