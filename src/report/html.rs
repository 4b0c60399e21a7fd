//! Self-contained HTML pages (`--format html`): one file with its style inline, the
//! tables and the plots as inline SVG, and no URL of any kind, so that a designer can
//! mail it and it renders the same offline.

use std::fmt::Write as _;

use super::svg::escape;

/// A page being written: sections of headings, tables, lists and figures.
pub struct Page {
    title: String,
    body: String,
}

const STYLE: &str = "body{font-family:'DejaVu Sans',Arial,Helvetica,sans-serif;max-width:1100px;margin:1.5em auto;padding:0 1em;color:#111;line-height:1.4}\
h1{font-size:1.5em;margin-bottom:0.2em}h2{font-size:1.15em;margin-top:1.6em;border-bottom:1px solid #ccc}\
table{border-collapse:collapse;margin:0.5em 0;display:block;max-width:100%;overflow-x:auto}td,th{padding:0.2em 0.8em;border-bottom:1px solid #e4e4e4;text-align:left;vertical-align:top}\
th{background:#f3f3f3}td.num{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}\
.status{font-weight:bold}.warn{color:#8a3b00}.warn li{margin:0.2em 0}.note{color:#444}\
figure{margin:1em 0}figcaption{font-size:0.9em;color:#444}svg{max-width:100%;height:auto}pre{background:#f7f7f7;padding:0.6em;overflow-x:auto}@media (max-width:900px){td,th{padding:0.15em 0.4em}td.num{white-space:normal}}@media print{@page{size:A4;margin:12mm}body{max-width:none;margin:0;padding:0;font-size:9pt}table{display:table;overflow:visible;width:100%;font-size:7.5pt;page-break-inside:auto}tr{page-break-inside:avoid}td,th{padding:0.1em 0.3em}td.num{white-space:normal}td{overflow-wrap:anywhere}figure{page-break-inside:avoid}svg{max-height:120mm}pre{white-space:pre-wrap;font-size:7pt}}";

impl Page {
    /// A page with a title (also its first heading).
    pub fn new(title: &str) -> Page {
        let mut p = Page {
            title: title.to_string(),
            body: String::new(),
        };
        let _ = writeln!(p.body, "<h1>{}</h1>", escape(title));
        p
    }

    /// A section heading.
    pub fn heading(&mut self, text: &str) {
        let _ = writeln!(self.body, "<h2>{}</h2>", escape(text));
    }

    /// A paragraph of plain text; `class` styles it (e.g. "status").
    pub fn paragraph(&mut self, text: &str, class: Option<&str>) {
        match class {
            Some(c) => {
                let _ = writeln!(self.body, "<p class=\"{c}\">{}</p>", escape(text));
            }
            None => {
                let _ = writeln!(self.body, "<p>{}</p>", escape(text));
            }
        }
    }

    /// A table: header cells, then rows; cells after the first are right-aligned numbers
    /// unless `text_columns` says otherwise (by index).
    pub fn table(&mut self, header: &[&str], rows: &[Vec<String>], text_columns: &[usize]) {
        let _ = write!(self.body, "<table>\n<tr>");
        for h in header {
            let _ = write!(self.body, "<th>{}</th>", escape(h));
        }
        let _ = writeln!(self.body, "</tr>");
        for r in rows {
            let _ = write!(self.body, "<tr>");
            for (i, c) in r.iter().enumerate() {
                if i == 0 || text_columns.contains(&i) {
                    let _ = write!(self.body, "<td>{}</td>", escape(c));
                } else {
                    let _ = write!(self.body, "<td class=\"num\">{}</td>", escape(c));
                }
            }
            let _ = writeln!(self.body, "</tr>");
        }
        let _ = writeln!(self.body, "</table>");
    }

    /// A list; `class` "warn" or "note" styles it.
    pub fn list(&mut self, items: &[String], class: &str) {
        if items.is_empty() {
            return;
        }
        let _ = writeln!(self.body, "<ul class=\"{class}\">");
        for i in items {
            let _ = writeln!(self.body, "<li>{}</li>", escape(i));
        }
        let _ = writeln!(self.body, "</ul>");
    }

    /// A plot (an SVG document from [`super::svg`]) with a caption; `id` names it.
    pub fn figure(&mut self, id: &str, svg: &str, caption: &str) {
        let _ = writeln!(
            self.body,
            "<figure id=\"{}\">\n{}\n<figcaption>{}</figcaption>\n</figure>",
            escape(id),
            inline_svg(svg),
            escape(caption)
        );
    }

    /// Markup written by the caller (images, inline figures), as is.
    pub fn raw(&mut self, markup: &str) {
        let _ = writeln!(self.body, "<div>{markup}</div>");
    }

    /// The finished document.
    pub fn finish(self) -> String {
        format!(
            "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n<meta name=\"generator\" content=\"wearopt\"/>\n<title>{}</title>\n<style>{STYLE}</style>\n</head>\n<body>\n{}<p class=\"note\">Written by wearopt {}. The model, its equations and conventions: docs/model.md of the wearopt repository.</p>\n</body>\n</html>\n",
            escape(&self.title),
            self.body,
            env!("CARGO_PKG_VERSION")
        )
    }
}

/// An SVG document made fit for inline use in HTML: no XML declaration, and no
/// namespace attribute (HTML parsers place `<svg>` in the SVG namespace themselves; the
/// attribute would be the page's only URL).
pub fn inline_svg(svg: &str) -> String {
    let body = match svg.find("<svg") {
        Some(i) => &svg[i..],
        None => svg,
    };
    body.replacen(" xmlns=\"http://www.w3.org/2000/svg\"", "", 1)
        .trim_end()
        .to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_page_has_no_url() {
        let mut p = Page::new("t <1>");
        p.table(&["a", "b"], &[vec!["x".into(), "1 µm".into()]], &[]);
        p.figure(
            "f",
            &super::super::svg::LinePlot::new(
                "p",
                super::super::svg::Axis::linear("x"),
                super::super::svg::Axis::linear("y"),
            )
            .to_svg(),
            "cap",
        );
        let html = p.finish();
        assert!(!html.contains("http") && !html.contains("//"), "{html}");
        assert!(html.contains("<title>t &lt;1&gt;</title>"));
        assert!(html.contains("<svg ") && !html.contains("<?xml"));
    }
}
