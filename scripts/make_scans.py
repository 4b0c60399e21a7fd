#!/usr/bin/env python3
"""Writes the height-map files wearopt ships and tests with, independently of wearopt.

    python3 scripts/make_scans.py        (needs numpy; run from the repository root)

1. problems/scans/self-affine.{gsf,npy,x3p}: a seeded, synthetic, self-affine (Hurst 0.8)
   Gaussian random surface, 256 x 256 points of 20 nm (a 5.12 um AFM scan), rms height
   4 nm, roll-off wavelength 1.28 um, roughness down to the pixel scale (as a real scan
   has). The same heights in three formats; the .npy carries no units (pixel size and
   height unit come from the user).
2. tests/data/scans/grid*.*: a 5 x 4 grid h[j][i] = (10 j + i) nm (i along x, j along y)
   with the point i = 2, j = 1 missing, in every format and variant the readers support,
   written by hand from the published formats (Gwyddion's GSF and text-matrix export,
   ISO 25178-72 X3P, NumPy .npy via numpy itself).

Each file is written from its specification, not by wearopt, so that the readers are
tested against an independent writer.
"""
import hashlib
import io
import os
import zipfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def gsf_bytes(h, xreal, yreal, xyunits="m", zunits="m"):
    """Gwyddion Simple Field: header lines, 1-4 NULs to a multiple of 4, f32 LE data."""
    ny, nx = h.shape
    head = "Gwyddion Simple Field 1.0\n"
    head += f"XRes = {nx}\nYRes = {ny}\n"
    head += f"XReal = {xreal!r}\nYReal = {yreal!r}\n"
    if xyunits is not None:
        head += f"XYUnits = {xyunits}\n"
    if zunits is not None:
        head += f"ZUnits = {zunits}\n"
    head += "Title = wearopt test data\n"
    b = head.encode("utf-8")
    b += b"\0" * (4 - len(b) % 4)
    return b + np.ascontiguousarray(h, dtype="<f4").tobytes()


def x3p_bytes(h, dx, dy, dtype="D", inc=1.0, off=0.0, mask=None, inline=False):
    """ISO 25178-72: zip with main.xml, bindata/data.bin, optional bindata/valid.bin."""
    ny, nx = h.shape
    np_type = {"I": "<i2", "L": "<i4", "F": "<f4", "D": "<f8"}[dtype]
    raw = (h - off) / inc
    if dtype in "IL":
        raw = np.where(np.isnan(raw), 0, np.round(raw))
    data = np.ascontiguousarray(raw, dtype=np_type).tobytes()  # x fastest (row-major)
    files = {}
    if inline:
        items = "".join(
            "<Datum/>" if np.isnan(v) else f"<Datum>{float(v)!r}</Datum>"
            for v in raw.ravel()
        )
        record3 = f"<DataList>{items}</DataList>"
    else:
        files["bindata/data.bin"] = data
        record3 = (
            "<DataLink><PointDataLink>bindata/data.bin</PointDataLink>"
            f"<MD5ChecksumPointData>{hashlib.md5(data).hexdigest()}</MD5ChecksumPointData>"
        )
        if mask is not None:
            bits = np.packbits(mask.ravel().astype(np.uint8), bitorder="little").tobytes()
            files["bindata/valid.bin"] = bits
            record3 += (
                "<ValidPointsLink>bindata/valid.bin</ValidPointsLink>"
                f"<MD5ChecksumValidPoints>{hashlib.md5(bits).hexdigest()}</MD5ChecksumValidPoints>"
            )
        record3 += "</DataLink>"

    def axis(name, kind, t, increment, offset):
        return (
            f"<{name}><AxisType>{kind}</AxisType><DataType>{t}</DataType>"
            f"<Increment>{increment!r}</Increment><Offset>{offset!r}</Offset></{name}>"
        )

    xml = (
        '<?xml version="1.0" encoding="UTF-8"?>\n'
        '<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2">'
        "<Record1><Revision>ISO5436 - 2000</Revision><FeatureType>SUR</FeatureType><Axes>"
        + axis("CX", "I", "D", dx, 0.0)
        + axis("CY", "I", "D", dy, 0.0)
        + axis("CZ", "A", dtype, inc, off)
        + "</Axes></Record1>"
        "<Record2><Date>2026-11-23T00:00:00.0+00:00</Date><Creator>wearopt scripts/make_scans.py</Creator>"
        "<Instrument><Manufacturer>none</Manufacturer><Model>synthetic</Model><Serial>0</Serial>"
        "<Version>1</Version></Instrument><CalibrationDate>2026-11-23T00:00:00.0+00:00</CalibrationDate>"
        "<ProbingSystem><Type>NonContacting</Type><Identification>none</Identification></ProbingSystem>"
        "<Comment>synthetic</Comment></Record2>"
        f"<Record3><MatrixDimension><SizeX>{nx}</SizeX><SizeY>{ny}</SizeY><SizeZ>1</SizeZ></MatrixDimension>"
        + record3
        + "</Record3><Record4><ChecksumFile>md5checksum.hex</ChecksumFile></Record4></p:ISO5436_2>\n"
    ).encode("utf-8")
    buf = io.BytesIO()
    def entry(name):  # a fixed time stamp: the same bytes on every run
        return zipfile.ZipInfo(name, date_time=(2026, 11, 23, 0, 0, 0))

    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as z:
        z.writestr(entry("main.xml"), xml, zipfile.ZIP_DEFLATED)
        for name, content in files.items():
            z.writestr(entry(name), content, zipfile.ZIP_DEFLATED)
        z.writestr(entry("md5checksum.hex"), f"{hashlib.md5(xml).hexdigest()} *main.xml\n", zipfile.ZIP_DEFLATED)
    return buf.getvalue()


def write(path, data):
    full = os.path.join(ROOT, path)
    with open(full, "wb") as f:
        f.write(data)
    print(f"wrote {path} ({len(data)} bytes)")


def self_affine(n, pixel, hurst, rolloff_wavelength, rms, seed):
    """Spectral method: Gaussian amplitudes on the FFT grid, C(q) ~ q^(-2(1+H)) above the
    roll-off, flat below, up to the Nyquist wavenumber; real part, scaled to rms."""
    rng = np.random.default_rng(seed)
    q1 = 2 * np.pi * np.fft.fftfreq(n, d=pixel)
    qx, qy = np.meshgrid(q1, q1)
    q = np.hypot(qx, qy)
    qr = 2 * np.pi / rolloff_wavelength
    c = np.maximum(q, qr) ** (-2 * (1 + hurst))
    c[0, 0] = 0.0
    spec = (rng.standard_normal((n, n)) + 1j * rng.standard_normal((n, n))) * np.sqrt(c)
    h = np.real(np.fft.ifft2(spec))
    h -= h.mean()
    return h * (rms / h.std())


def main():
    # 1. The shipped scan.
    n, pixel = 256, 20e-9
    h = self_affine(n, pixel, hurst=0.8, rolloff_wavelength=1.28e-6, rms=4e-9, seed=20261123)
    length = n * pixel
    write("problems/scans/self-affine.gsf", gsf_bytes(h, length, length))
    write("problems/scans/self-affine.x3p", x3p_bytes(h, pixel, pixel, "D"))
    buf = io.BytesIO()
    np.save(buf, h * 1e9)  # in nanometres: the user gives --height-unit nm
    write("problems/scans/self-affine-nm.npy", buf.getvalue())

    # 2. The reader test grid, heights in nm, point (i=2, j=1) missing.
    g = np.array([[10.0 * j + i for i in range(5)] for j in range(4)])
    g[1, 2] = np.nan
    valid = ~np.isnan(g)
    gm = g * 1e-9
    d = "tests/data/scans/"
    write(d + "grid.gsf", gsf_bytes(g, 5.0, 2.0, xyunits="um", zunits="nm"))
    write(d + "grid-no-units.gsf", gsf_bytes(g, 5.0, 2.0, xyunits=None, zunits=None))
    buf = io.BytesIO()
    np.save(buf, g)
    write(d + "grid.npy", buf.getvalue())
    buf = io.BytesIO()
    np.save(buf, np.asfortranarray(g))
    write(d + "grid-fortran.npy", buf.getvalue())
    buf = io.BytesIO()
    np.save(buf, g.astype(">f4"))
    write(d + "grid-be-f4.npy", buf.getvalue())
    rows = "\n".join("\t".join("NaN" if np.isnan(v) else f"{v:g}" for v in r) for r in g)
    write(
        d + "grid-gwyddion.txt",
        (
            "# Channel: Height\n# Width: 5.000 µm\n# Height: 2.000 µm\n# Value units: nm\n"
            + rows
            + "\n"
        ).encode("utf-8"),
    )
    write(d + "grid-bare.txt", (rows + "\n").encode("utf-8"))
    # X3P: doubles in metres with NaN; int16 with increment/offset and a mask; int32; inline.
    write(d + "grid-D.x3p", x3p_bytes(gm, 1e-6, 0.5e-6, "D"))
    write(d + "grid-I-mask.x3p", x3p_bytes(np.where(valid, gm, 5e-9), 1e-6, 0.5e-6, "I", inc=1e-9, off=5e-9, mask=valid))
    write(d + "grid-L.x3p", x3p_bytes(np.where(valid, gm, 0.0), 1e-6, 0.5e-6, "L", inc=1e-10, off=0.0, mask=valid))
    write(d + "grid-F-inline.x3p", x3p_bytes(gm, 1e-6, 0.5e-6, "F", inline=True))


if __name__ == "__main__":
    main()
