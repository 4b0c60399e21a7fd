#!/usr/bin/env python3
"""Prints every HTML page of a folder to A4 PDF with headless Chromium and checks
that every table cell's text is in the PDF's text layer (pdftotext): nothing a
table shows may be cut off in print.

    cargo build --release && scripts/outputs target/release/wearopt /tmp/out
    python3 scripts/print_check.py /tmp/out

Needs chromium and pdftotext (Debian: chromium, poppler-utils). A cell is found
when its text, with all whitespace removed, occurs in the PDF's text with all
whitespace removed (a cell wrapped over two lines in print still reads in order).
Prints one line per page and every missing cell; exit 1 if any is missing.
"""

from __future__ import annotations

import argparse
import html.parser
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile


class Cells(html.parser.HTMLParser):
    """The text of every <td> and <th> of a page."""

    def __init__(self) -> None:
        super().__init__()
        self.cells: list[str] = []
        self._open: list[str] | None = None

    def handle_starttag(self, tag: str, attrs) -> None:
        if tag in ("td", "th"):
            self._open = []

    def handle_endtag(self, tag: str) -> None:
        if tag in ("td", "th") and self._open is not None:
            self.cells.append("".join(self._open))
            self._open = None

    def handle_data(self, data: str) -> None:
        if self._open is not None:
            self._open.append(data)


def squeeze(text: str) -> str:
    return re.sub(r"\s+", "", text.replace("\u00ad", ""))


def check(page: pathlib.Path, chromium: str, work: pathlib.Path) -> list[str]:
    pdf = work / (page.stem + ".pdf")
    subprocess.run(
        [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--no-pdf-header-footer",
         f"--print-to-pdf={pdf}", page.resolve().as_uri()],
        check=True, capture_output=True, timeout=120,
    )
    text = subprocess.run(["pdftotext", "-raw", str(pdf), "-"], check=True,
                          capture_output=True, text=True).stdout
    printed = squeeze(text)
    parser = Cells()
    parser.feed(page.read_text(encoding="utf-8"))
    return [c for c in parser.cells if squeeze(c) and squeeze(c) not in printed]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("folder", type=pathlib.Path)
    args = ap.parse_args()
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if chromium is None or shutil.which("pdftotext") is None:
        print("needs chromium and pdftotext (apt install chromium poppler-utils)", file=sys.stderr)
        return 2
    # scripts/outputs names pages NAME.html; any file that is an HTML document counts.
    pages = sorted(p for p in args.folder.rglob("*")
                   if p.is_file() and p.read_bytes()[:15].lower().startswith(b"<!doctype html"))
    failed = 0
    with tempfile.TemporaryDirectory() as tmp:
        for page in pages:
            missing = check(page, chromium, pathlib.Path(tmp))
            print(f"{page.name}: {'ok' if not missing else f'{len(missing)} cells missing'}")
            for m in missing:
                print(f"    missing: {m!r}")
            failed += bool(missing)
    print(f"{len(pages)} pages printed to A4, {failed} with cells missing from the print")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
