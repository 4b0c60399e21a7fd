//! A small SVG line-plot exporter: linear or log10 axes, several series with a
//! legend, markers, a title and axis labels with units. Written by hand (SVG is
//! a little XML), so it costs no dependency; every piece of text is escaped.
//!
//! ```
//! use wearopt::report::svg::{Axis, LinePlot, Marker, Series};
//! let svg = LinePlot::new(
//!     "Wear against load",
//!     Axis::linear("load").with_unit("µN"),
//!     Axis::log("wear rate").with_unit("m³/m"),
//! )
//! .with_series(Series::new("θ = 10", vec![(1.0, 1e-18), (2.0, 3e-18)]).with_marker(Marker::Square))
//! .to_svg();
//! assert!(svg.starts_with("<?xml"));
//! ```
//!
//! Points that cannot be drawn (not finite, or ≤ 0 on a log axis) are left out and
//! break the series' line there. Axis ranges default to the drawable data widened to
//! "nice" ticks (1, 2, 5 × 10^k on linear axes, decades on log axes).

use std::fmt::Write as _;

/// How an axis maps values to positions.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scale {
    /// Evenly spaced values.
    Linear,
    /// Evenly spaced decades (values must be > 0).
    Log,
}

/// One axis: label, optional unit, scale and optional fixed range.
#[derive(Debug, Clone, PartialEq)]
pub struct Axis {
    /// What the axis shows, e.g. "non-dimensional load P̄".
    pub label: String,
    /// The unit, shown as "label (unit)"; None for none (non-dimensional).
    pub unit: Option<String>,
    /// Linear or log10.
    pub scale: Scale,
    /// A fixed range (lo < hi; both > 0 on a log axis); None fits the data.
    pub range: Option<(f64, f64)>,
}

impl Axis {
    /// A linear axis fitted to the data.
    pub fn linear(label: impl Into<String>) -> Self {
        Axis {
            label: label.into(),
            unit: None,
            scale: Scale::Linear,
            range: None,
        }
    }

    /// A log10 axis fitted to the data.
    pub fn log(label: impl Into<String>) -> Self {
        Axis {
            scale: Scale::Log,
            ..Axis::linear(label)
        }
    }

    /// Sets the unit.
    pub fn with_unit(mut self, unit: impl Into<String>) -> Self {
        self.unit = Some(unit.into());
        self
    }

    /// Fixes the range instead of fitting it to the data.
    pub fn with_range(mut self, lo: f64, hi: f64) -> Self {
        self.range = Some((lo, hi));
        self
    }

    /// The label with its unit.
    pub fn title(&self) -> String {
        match &self.unit {
            Some(u) if !u.is_empty() => format!("{} ({u})", self.label),
            _ => self.label.clone(),
        }
    }

    fn drawable(&self, v: f64) -> bool {
        v.is_finite() && (self.scale == Scale::Linear || v > 0.0)
    }

    /// Value → axis coordinate (log10 on a log axis).
    fn coord(&self, v: f64) -> f64 {
        match self.scale {
            Scale::Linear => v,
            Scale::Log => v.log10(),
        }
    }
}

/// The symbol drawn at a series' points.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Marker {
    /// No symbol (line only).
    None,
    /// A filled circle.
    Circle,
    /// A filled square.
    Square,
    /// A filled upward triangle.
    Triangle,
    /// A filled diamond.
    Diamond,
    /// An × of two strokes.
    Cross,
}

impl Marker {
    /// The markers in the order [`LinePlot`] hands them to series that keep the default.
    pub const CYCLE: [Marker; 5] = [
        Marker::Circle,
        Marker::Square,
        Marker::Triangle,
        Marker::Diamond,
        Marker::Cross,
    ];
}

/// One named series of (x, y) points.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// The legend entry.
    pub name: String,
    /// The points, drawn in the given order.
    pub points: Vec<(f64, f64)>,
    /// Join the points with a line.
    pub line: bool,
    /// The marker; None picks one from [`Marker::CYCLE`] by the series' position.
    pub marker: Option<Marker>,
    /// Draw a marker at every n-th point (1: all; the first and last always get one).
    pub marker_every: usize,
    /// Stroke and fill colour (any SVG colour); None picks one from [`PALETTE`].
    pub color: Option<String>,
}

impl Series {
    /// A line with markers at every point, colour and marker picked by position.
    pub fn new(name: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Series {
            name: name.into(),
            points,
            line: true,
            marker: None,
            marker_every: 1,
            color: None,
        }
    }

    /// Sets the marker.
    pub fn with_marker(mut self, marker: Marker) -> Self {
        self.marker = Some(marker);
        self
    }

    /// Markers only, no line (a scatter, e.g. a Pareto front's points).
    pub fn without_line(mut self) -> Self {
        self.line = false;
        self
    }

    /// A marker at every n-th point only (n ≥ 1).
    pub fn with_marker_every(mut self, n: usize) -> Self {
        self.marker_every = n.max(1);
        self
    }

    /// Sets the colour.
    pub fn with_color(mut self, color: impl Into<String>) -> Self {
        self.color = Some(color.into());
        self
    }
}

/// Okabe–Ito colours (distinguishable with the common colour-vision deficiencies),
/// without the yellow that vanishes on white.
pub const PALETTE: [&str; 7] = [
    "#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000",
];

/// Words beside one point of a plot: the point is ringed and the text set on a
/// white halo beside it, on the side with room, never outside the plot's frame.
#[derive(Debug, Clone, PartialEq)]
pub struct Label {
    /// The point, in the axes' units.
    pub at: (f64, f64),
    /// The words.
    pub text: String,
    /// The ring's and the text's colour.
    pub color: String,
}

/// A plot: title, two axes, series. Render with [`LinePlot::to_svg`].
#[derive(Debug, Clone, PartialEq)]
pub struct LinePlot {
    /// Shown above the plot.
    pub title: String,
    /// Horizontal axis.
    pub x: Axis,
    /// Vertical axis.
    pub y: Axis,
    /// The series, in legend order.
    pub series: Vec<Series>,
    /// Words written beside points of the plot (a knee, a jump), drawn over the
    /// series and kept inside the frame.
    pub labels: Vec<Label>,
    /// Total width in px.
    pub width: f64,
    /// Total height in px.
    pub height: f64,
}

const MARGIN_LEFT: f64 = 84.0;
const MARGIN_TOP: f64 = 48.0;
const MARGIN_BOTTOM: f64 = 62.0;
const FONT: &str = "font-family=\"DejaVu Sans, Arial, Helvetica, sans-serif\"";

/// Escapes text for XML content and attribute values.
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            // Control characters other than tab/newline are not allowed in XML 1.0.
            c if (c as u32) < 0x20 && c != '\t' && c != '\n' => out.push(' '),
            c => out.push(c),
        }
    }
    out
}

/// A tick: its axis coordinate, its label (empty for a minor tick).
struct Tick {
    at: f64,
    label: String,
}

/// The shortest string for a tick value.
fn tick_label(v: f64) -> String {
    let v = if v == 0.0 { 0.0 } else { v }; // no "-0"
    let a = v.abs();
    if v == 0.0 || (1e-4..1e6).contains(&a) {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

/// Nice linear ticks covering [lo, hi]: the widened range and the ticks.
fn linear_ticks(lo: f64, hi: f64, fixed: bool) -> ((f64, f64), Vec<Tick>) {
    let raw = (hi - lo) / 5.0;
    let mut exp = raw.log10().floor() as i32;
    let mut m = [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .find(|m| m * 10f64.powi(exp) >= raw * (1.0 - 1e-9))
        .unwrap_or(10.0);
    // At least four labelled ticks: inside [lo, hi] on a fixed range (which keeps
    // only those), on the covering range otherwise; the next smaller step of the
    // 1–2–5 series until there are.
    let inside = |step: f64| {
        let (a, b) = if fixed {
            ((lo / step - 1e-9).ceil(), (hi / step + 1e-9).floor())
        } else {
            ((lo / step + 1e-9).floor(), (hi / step - 1e-9).ceil())
        };
        (b - a) as i64 + 1
    };
    for _ in 0..6 {
        if inside(m * 10f64.powi(exp)) >= 4 {
            break;
        }
        (m, exp) = match m as i64 {
            10 => (5.0, exp),
            5 => (2.0, exp),
            2 => (1.0, exp),
            _ => (5.0, exp - 1),
        };
    }
    if m == 10.0 {
        (m, exp) = (1.0, exp + 1);
    }
    let mag = 10f64.powi(exp);
    // step = m · 10^exp; tick k is the double nearest k·m·10^exp, read from its
    // decimal form so that 0.1 steps print as 0.3, not 0.30000000000000004, and
    // 5e-146 steps as 1.5e-145, not 1.4999999999999994e-145 (10^146 is not exact).
    let step = m * mag;
    let value = |k: i64| -> f64 {
        let n = k * m as i64;
        format!("{n}e{exp}").parse().unwrap_or(n as f64 * mag)
    };
    let k0 = (lo / step + 1e-9).floor() as i64;
    let k1 = (hi / step - 1e-9).ceil() as i64;
    let ticks = (k0..=k1)
        .map(|k| {
            let v = value(k);
            Tick {
                at: v,
                label: tick_label(v),
            }
        })
        .collect();
    ((value(k0), value(k1)), ticks)
}

/// Decade ticks (with 2…9 minors when few decades) covering [lo, hi] (log10
/// coordinates). At least four are labelled: over one or two decades the minors 2
/// and 5 are labelled too.
fn log_ticks(lo: f64, hi: f64) -> ((f64, f64), Vec<Tick>) {
    let d0 = (lo + 1e-9).floor() as i32;
    let d1 = ((hi - 1e-9).ceil() as i32).max(d0 + 1);
    let decades = d1 - d0;
    let every = ((decades + 7) / 8).max(1); // at most ~8 labelled decades
    let mut ticks = Vec::new();
    for d in d0..=d1 {
        let label = if (d - d0) % every == 0 {
            let v: f64 = format!("1e{d}").parse().unwrap_or(f64::NAN);
            tick_label(v)
        } else {
            String::new()
        };
        ticks.push(Tick {
            at: d as f64,
            label,
        });
        if decades <= 4 && d < d1 {
            for m in 2..10 {
                let label = if decades <= 2 && (m == 2 || m == 5) {
                    let v: f64 = format!("{m}e{d}").parse().unwrap_or(f64::NAN);
                    tick_label(v)
                } else {
                    String::new()
                };
                ticks.push(Tick {
                    at: d as f64 + (m as f64).log10(),
                    label,
                });
            }
        }
    }
    ((d0 as f64, d1 as f64), ticks)
}

/// The axis range in axis coordinates and its ticks.
fn axis_layout(axis: &Axis, values: impl Iterator<Item = f64>) -> ((f64, f64), Vec<Tick>) {
    let (mut lo, mut hi) = match axis.range {
        Some((a, b)) if axis.drawable(a) && axis.drawable(b) && a < b => {
            (axis.coord(a), axis.coord(b))
        }
        _ => values
            .filter(|&v| axis.drawable(v))
            .map(|v| axis.coord(v))
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), c| {
                (l.min(c), h.max(c))
            }),
    };
    if lo > hi {
        // No drawable data.
        (lo, hi) = match axis.scale {
            Scale::Linear => (0.0, 1.0),
            Scale::Log => (0.0, 1.0),
        };
    }
    if lo == hi && lo == 0.0 && axis.scale == Scale::Linear {
        // Every value is zero (e.g. a front that never wears): the axis starts at
        // the data, with no negative ticks for what may be a quantity ≥ 0.
        hi = 1.0;
    } else if lo == hi {
        let pad = match axis.scale {
            Scale::Linear => (lo.abs() * 0.1).max(1e-300),
            Scale::Log => 0.5,
        };
        lo -= pad;
        hi += pad;
    }
    let ((nlo, nhi), ticks) = match axis.scale {
        Scale::Linear => linear_ticks(lo, hi, axis.range.is_some()),
        Scale::Log => log_ticks(lo, hi),
    };
    if axis.range.is_some() {
        // A fixed range is kept exactly; ticks outside it are dropped.
        let eps = (hi - lo) * 1e-9;
        let ticks = ticks
            .into_iter()
            .filter(|t| t.at >= lo - eps && t.at <= hi + eps)
            .collect();
        ((lo, hi), ticks)
    } else {
        ((nlo, nhi), ticks)
    }
}

fn marker_svg(out: &mut String, marker: Marker, x: f64, y: f64, color: &str) {
    let r = 3.2;
    let _ = match marker {
        Marker::None => Ok(()),
        Marker::Circle => writeln!(
            out,
            "<circle cx=\"{x:.2}\" cy=\"{y:.2}\" r=\"{r}\" fill=\"{color}\"/>"
        ),
        Marker::Square => writeln!(
            out,
            "<rect x=\"{:.2}\" y=\"{:.2}\" width=\"{w:.2}\" height=\"{w:.2}\" fill=\"{color}\"/>",
            x - r * 0.9,
            y - r * 0.9,
            w = 1.8 * r
        ),
        Marker::Triangle => writeln!(
            out,
            "<polygon points=\"{:.2},{:.2} {:.2},{:.2} {:.2},{:.2}\" fill=\"{color}\"/>",
            x,
            y - 1.2 * r,
            x + 1.1 * r,
            y + 0.8 * r,
            x - 1.1 * r,
            y + 0.8 * r
        ),
        Marker::Diamond => writeln!(
            out,
            "<polygon points=\"{:.2},{:.2} {:.2},{:.2} {:.2},{:.2} {:.2},{:.2}\" fill=\"{color}\"/>",
            x,
            y - 1.3 * r,
            x + 1.1 * r,
            y,
            x,
            y + 1.3 * r,
            x - 1.1 * r,
            y
        ),
        Marker::Cross => writeln!(
            out,
            "<path d=\"M{:.2},{:.2}L{:.2},{:.2}M{:.2},{:.2}L{:.2},{:.2}\" stroke=\"{color}\" stroke-width=\"1.6\" fill=\"none\"/>",
            x - r,
            y - r,
            x + r,
            y + r,
            x - r,
            y + r,
            x + r,
            y - r
        ),
    };
}

/// The average advance of a glyph of the plots' sans-serif font, in em (an upper
/// estimate for DejaVu Sans, the widest of the fonts named; bold is about 10 % wider).
pub const TEXT_EM: f64 = 0.62;

/// The title's lines: (text, baseline y, font size). One line at 16 px when it fits
/// the width less 24 px; else two lines split at the space nearest the middle, at the
/// size that fits (at most 16 px).
fn title_lines(title: &str, w: f64, top: f64) -> Vec<(String, f64, f64)> {
    let room = w - 24.0;
    let width = |t: &str, size: f64| 1.1 * TEXT_EM * size * t.chars().count() as f64;
    if width(title, 16.0) <= room {
        return vec![(title.to_string(), top - 18.0, 16.0)];
    }
    let chars: Vec<char> = title.chars().collect();
    let mid = chars.len() / 2;
    let split = (0..chars.len())
        .filter(|&i| chars[i] == ' ')
        .min_by_key(|&i| i.abs_diff(mid));
    let (a, b) = match split {
        Some(i) => (
            chars[..i].iter().collect::<String>(),
            chars[i + 1..].iter().collect::<String>(),
        ),
        None => (title.to_string(), String::new()),
    };
    let longest = a.chars().count().max(b.chars().count()).max(1);
    let size = (room / (1.1 * TEXT_EM * longest as f64)).min(16.0);
    if b.is_empty() {
        return vec![(a, top - 18.0, size)];
    }
    vec![(a, top - 14.0 - 1.15 * size, size), (b, top - 14.0, size)]
}

impl LinePlot {
    /// An empty 760 × 480 plot.
    pub fn new(title: impl Into<String>, x: Axis, y: Axis) -> Self {
        LinePlot {
            title: title.into(),
            x,
            y,
            series: Vec::new(),
            labels: Vec::new(),
            width: 760.0,
            height: 480.0,
        }
    }

    /// Adds a series.
    pub fn with_series(mut self, series: Series) -> Self {
        self.series.push(series);
        self
    }

    /// Adds a label beside the point `at` (in the axes' units).
    pub fn with_label(
        mut self,
        at: (f64, f64),
        text: impl Into<String>,
        color: impl Into<String>,
    ) -> Self {
        self.labels.push(Label {
            at,
            text: text.into(),
            color: color.into(),
        });
        self
    }

    /// The SVG document (UTF-8, standalone, with an XML declaration).
    pub fn to_svg(&self) -> String {
        let (w, h) = (self.width.max(200.0), self.height.max(150.0));
        // The legend sits right of the plot; its width follows the longest name.
        let longest = self
            .series
            .iter()
            .map(|s| s.name.chars().count())
            .max()
            .unwrap_or(0);
        let legend_w = if self.series.is_empty() {
            20.0
        } else {
            (62.0 + TEXT_EM * 13.0 * longest as f64).clamp(100.0, 0.42 * w)
        };
        let (left, top) = (MARGIN_LEFT, MARGIN_TOP);
        let right = w - legend_w;
        let bottom = h - MARGIN_BOTTOM;

        let ((x0, x1), xticks) = axis_layout(
            &self.x,
            self.series
                .iter()
                .flat_map(|s| s.points.iter().map(|p| p.0)),
        );
        let ((y0, y1), yticks) = axis_layout(
            &self.y,
            self.series
                .iter()
                .flat_map(|s| s.points.iter().map(|p| p.1)),
        );
        let px = |c: f64| left + (c - x0) / (x1 - x0) * (right - left);
        let py = |c: f64| bottom - (c - y0) / (y1 - y0) * (bottom - top);

        let mut o = String::new();
        let _ = writeln!(
            o,
            "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>"
        );
        let _ = writeln!(
            o,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" {FONT} font-size=\"13\">"
        );
        let _ = writeln!(o, "<title>{}</title>", escape(&self.title));
        let _ = writeln!(
            o,
            "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<defs><clipPath id=\"plot-area\"><rect x=\"{left}\" y=\"{top}\" width=\"{:.2}\" height=\"{:.2}\"/></clipPath></defs>",
            right - left,
            bottom - top
        );
        // The title is centred on the whole width; a long one is broken into two lines
        // and, if still too wide, set smaller, so that it never leaves the view box.
        for (line, y, size) in title_lines(&self.title, w, top) {
            let _ = writeln!(
                o,
                "<text class=\"title\" x=\"{:.2}\" y=\"{y:.2}\" text-anchor=\"middle\" font-size=\"{size:.1}\" font-weight=\"bold\">{}</text>",
                w / 2.0,
                escape(&line)
            );
        }

        // Grid, ticks and tick labels.
        let _ = writeln!(o, "<g class=\"x-axis\">");
        for t in &xticks {
            let x = px(t.at);
            let major = !t.label.is_empty();
            let _ = writeln!(
                o,
                "<line x1=\"{x:.2}\" y1=\"{top}\" x2=\"{x:.2}\" y2=\"{bottom}\" stroke=\"{}\" stroke-width=\"1\"/>",
                if major { "#dddddd" } else { "#f0f0f0" }
            );
            let len = if major { 6.0 } else { 3.0 };
            let _ = writeln!(
                o,
                "<line x1=\"{x:.2}\" y1=\"{bottom}\" x2=\"{x:.2}\" y2=\"{:.2}\" stroke=\"black\"/>",
                bottom + len
            );
            if major {
                let _ = writeln!(
                    o,
                    "<text x=\"{x:.2}\" y=\"{:.2}\" text-anchor=\"middle\">{}</text>",
                    bottom + 20.0,
                    escape(&t.label)
                );
            }
        }
        // Centred under the plot; a title too long for the width is set smaller.
        let x_title = self.x.title();
        let centre = (left + right) / 2.0;
        let room = 2.0 * (centre.min(w - centre) - 4.0);
        let wide = TEXT_EM * 14.0 * x_title.chars().count() as f64;
        let x_size = if wide <= room {
            "14".to_string()
        } else {
            format!("{:.1}", 14.0 * room / wide)
        };
        let _ = writeln!(
            o,
            "<text class=\"x-label\" x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"middle\" font-size=\"{x_size}\">{}</text>\n</g>",
            centre,
            h - 16.0,
            escape(&x_title)
        );
        let _ = writeln!(o, "<g class=\"y-axis\">");
        for t in &yticks {
            let y = py(t.at);
            let major = !t.label.is_empty();
            let _ = writeln!(
                o,
                "<line x1=\"{left}\" y1=\"{y:.2}\" x2=\"{right:.2}\" y2=\"{y:.2}\" stroke=\"{}\" stroke-width=\"1\"/>",
                if major { "#dddddd" } else { "#f0f0f0" }
            );
            let len = if major { 6.0 } else { 3.0 };
            let _ = writeln!(
                o,
                "<line x1=\"{:.2}\" y1=\"{y:.2}\" x2=\"{left}\" y2=\"{y:.2}\" stroke=\"black\"/>",
                left - len
            );
            if major {
                let _ = writeln!(
                    o,
                    "<text x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"end\">{}</text>",
                    left - 9.0,
                    y + 4.5,
                    escape(&t.label)
                );
            }
        }
        let (lx, ly) = (18.0, (top + bottom) / 2.0);
        let _ = writeln!(
            o,
            "<text class=\"y-label\" x=\"{lx}\" y=\"{ly:.2}\" text-anchor=\"middle\" font-size=\"14\" transform=\"rotate(-90 {lx} {ly:.2})\">{}</text>\n</g>",
            escape(&self.y.title())
        );
        let _ = writeln!(
            o,
            "<rect class=\"frame\" x=\"{left}\" y=\"{top}\" width=\"{:.2}\" height=\"{:.2}\" fill=\"none\" stroke=\"black\"/>",
            right - left,
            bottom - top
        );

        // Series, clipped to the plot area.
        let mut legend = String::new();
        for (i, s) in self.series.iter().enumerate() {
            let color = s
                .color
                .clone()
                .unwrap_or_else(|| PALETTE[i % PALETTE.len()].to_string());
            let color = escape(&color);
            let marker = s.marker.unwrap_or(Marker::CYCLE[i % Marker::CYCLE.len()]);
            let _ = writeln!(
                o,
                "<g class=\"series\" data-name=\"{}\" clip-path=\"url(#plot-area)\">",
                escape(&s.name)
            );
            let pts: Vec<Option<(f64, f64)>> = s
                .points
                .iter()
                .map(|&(x, y)| {
                    (self.x.drawable(x) && self.y.drawable(y))
                        .then(|| (px(self.x.coord(x)), py(self.y.coord(y))))
                })
                .collect();
            if s.line {
                for run in pts.split(|p| p.is_none()).filter(|r| r.len() >= 2) {
                    let coords: Vec<String> = run
                        .iter()
                        .flatten()
                        .map(|(x, y)| format!("{x:.2},{y:.2}"))
                        .collect();
                    let _ = writeln!(
                        o,
                        "<polyline fill=\"none\" stroke=\"{color}\" stroke-width=\"1.8\" stroke-linejoin=\"round\" points=\"{}\"/>",
                        coords.join(" ")
                    );
                }
            }
            let _ = writeln!(o, "</g>");
            // Markers are not clipped (a marker on an axis is drawn whole); those
            // outside the plot area are left out.
            let _ = writeln!(o, "<g class=\"markers\" data-name=\"{}\">", escape(&s.name));
            let inside = |x: f64, y: f64| {
                x >= left - 0.01 && x <= right + 0.01 && y >= top - 0.01 && y <= bottom + 0.01
            };
            let last = pts.len().saturating_sub(1);
            for (k, p) in pts.iter().enumerate() {
                if let Some((x, y)) = p {
                    if (k % s.marker_every == 0 || k == last) && inside(*x, *y) {
                        marker_svg(&mut o, marker, *x, *y, &color);
                    }
                }
            }
            let _ = writeln!(o, "</g>");

            // Legend entry.
            let ey = top + 14.0 + 22.0 * i as f64;
            let ex = right + 14.0;
            let _ = writeln!(legend, "<g class=\"legend-entry\">");
            if s.line {
                let _ = writeln!(
                    legend,
                    "<line x1=\"{ex:.2}\" y1=\"{ey:.2}\" x2=\"{:.2}\" y2=\"{ey:.2}\" stroke=\"{color}\" stroke-width=\"1.8\"/>",
                    ex + 26.0
                );
            }
            marker_svg(&mut legend, marker, ex + 13.0, ey, &color);
            // A name too long for the legend column is set smaller.
            let room = w - (ex + 34.0) - 6.0;
            let size = (room / (TEXT_EM * s.name.chars().count().max(1) as f64)).min(13.0);
            let _ = writeln!(
                legend,
                "<text x=\"{:.2}\" y=\"{:.2}\" font-size=\"{size:.1}\">{}</text>\n</g>",
                ex + 34.0,
                ey + 4.5,
                escape(&s.name)
            );
        }
        if !self.series.is_empty() {
            let _ = writeln!(o, "<g class=\"legend\">\n{legend}</g>");
        }
        // Labels: a ring round the point, the text beside it on a white halo, to
        // the right where it fits, else to the left; above the point unless too
        // near the top.
        for l in &self.labels {
            let (x, y) = l.at;
            if !(self.x.drawable(x) && self.y.drawable(y)) {
                continue;
            }
            let (cx, cy) = (px(self.x.coord(x)), py(self.y.coord(y)));
            if !(left..=right).contains(&cx) || !(top..=bottom).contains(&cy) {
                continue;
            }
            let color = escape(&l.color);
            let size = 12.0;
            let width = TEXT_EM * size * l.text.chars().count() as f64;
            let (tx, anchor) = if cx + 10.0 + width <= right - 4.0 {
                (cx + 10.0, "start")
            } else if cx - 10.0 - width >= left + 4.0 {
                (cx - 10.0, "end")
            } else {
                // Too long for either side: start at the frame's left edge.
                (left + 4.0, "start")
            };
            let ty = if cy - 10.0 - size >= top + 2.0 {
                cy - 10.0
            } else {
                cy + 10.0 + size
            };
            let _ = writeln!(
                o,
                "<g class=\"label\">\n<circle cx=\"{cx:.2}\" cy=\"{cy:.2}\" r=\"7\" fill=\"none\" stroke=\"{color}\" stroke-width=\"2\"/>\n<text x=\"{tx:.2}\" y=\"{ty:.2}\" text-anchor=\"{anchor}\" font-size=\"{size}\" fill=\"{color}\" stroke=\"white\" stroke-width=\"3\" paint-order=\"stroke\">{}</text>\n</g>",
                escape(&l.text)
            );
        }
        let _ = writeln!(o, "</svg>");
        o
    }
}

/// A horizontal bar chart of signed values (e.g. elasticities): one bar per label
/// from a zero line, the value printed beside each bar. 760 px wide.
pub fn bar_chart(title: &str, value_label: &str, bars: &[(String, f64)]) -> String {
    let w = 760.0;
    let row = 30.0;
    let top = 56.0;
    let h = top + row * bars.len().max(1) as f64 + 56.0;
    let (left, right) = (190.0, w - 120.0);
    let finite: Vec<f64> = bars.iter().map(|b| b.1).filter(|v| v.is_finite()).collect();
    let lo = finite.iter().copied().fold(0.0f64, f64::min);
    let hi = finite.iter().copied().fold(0.0f64, f64::max);
    let span = if hi - lo > 0.0 { hi - lo } else { 1.0 };
    let px = |v: f64| left + (v - lo) / span * (right - left);
    let mut o = String::new();
    let _ = writeln!(
        o,
        "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" {FONT} font-size=\"13\">"
    );
    let _ = writeln!(o, "<title>{}</title>", escape(title));
    let _ = writeln!(o, "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>");
    let _ = writeln!(
        o,
        "<text class=\"title\" x=\"{:.2}\" y=\"28\" text-anchor=\"middle\" font-size=\"16\" font-weight=\"bold\">{}</text>",
        w / 2.0,
        escape(title)
    );
    let zero = px(0.0);
    for (i, (label, v)) in bars.iter().enumerate() {
        let y = top + row * i as f64;
        let _ = writeln!(
            o,
            "<text x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"end\">{}</text>",
            left - 10.0,
            y + row / 2.0 + 4.5,
            escape(label)
        );
        if v.is_finite() {
            let (x0, x1) = if *v >= 0.0 {
                (zero, px(*v))
            } else {
                (px(*v), zero)
            };
            let _ = writeln!(
                o,
                "<rect class=\"bar\" x=\"{x0:.2}\" y=\"{:.2}\" width=\"{:.2}\" height=\"{:.2}\" fill=\"{}\"/>",
                y + 5.0,
                (x1 - x0).max(0.5),
                row - 10.0,
                if *v >= 0.0 { PALETTE[0] } else { PALETTE[1] }
            );
        }
        // Values in their own column at the right, clear of bars and names.
        let text = if v.is_finite() {
            format!("{v:+.4}")
        } else {
            "—".to_string()
        };
        let _ = writeln!(
            o,
            "<text class=\"value\" x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"end\">{}</text>",
            w - 14.0,
            y + row / 2.0 + 4.5,
            escape(&text)
        );
    }
    let bottom = top + row * bars.len().max(1) as f64;
    let _ = writeln!(
        o,
        "<line x1=\"{zero:.2}\" y1=\"{:.2}\" x2=\"{zero:.2}\" y2=\"{bottom:.2}\" stroke=\"black\"/>",
        top - 4.0
    );
    let _ = writeln!(
        o,
        "<text class=\"x-label\" x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"middle\" font-size=\"14\">{}</text>",
        (left + right) / 2.0,
        h - 18.0,
        escape(value_label)
    );
    let _ = writeln!(o, "</svg>");
    o
}

/// A horizontal bar chart of positive values on a log10 axis (e.g. the wear rate of
/// each candidate material, which differ by decades): one bar per label, drawn from
/// the axis' lowest decade, with its value (already worded by the caller) beside it.
/// A bar whose value is not positive and finite is drawn as none, its text "—".
/// 760 px wide; decades labelled below the bars.
pub fn log_bar_chart(title: &str, value_label: &str, bars: &[(String, f64, String)]) -> String {
    let w = 760.0;
    let row = 30.0;
    let top = 56.0;
    let n = bars.len().max(1) as f64;
    let h = top + row * n + 80.0;
    // Room for the longest name at the left and the longest value at the right (at
    // 13 px); a name longer than half the width is cut with an ellipsis.
    let chars = |t: &str| t.chars().count() as f64;
    let em = TEXT_EM * 13.0;
    let longest = bars.iter().map(|b| chars(&b.0)).fold(0.0, f64::max);
    let left = (24.0 + em * longest).clamp(120.0, w / 2.0);
    let fits = ((left - 24.0) / em).floor() as usize;
    let widest_value = bars.iter().map(|b| chars(&b.2)).fold(1.0, f64::max);
    let right = w - 34.0 - em * widest_value;
    let logs: Vec<f64> = bars
        .iter()
        .map(|b| b.1)
        .filter(|v| v.is_finite() && *v > 0.0)
        .map(f64::log10)
        .collect();
    let lo = logs.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = logs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let (lo, hi) = if lo.is_finite() && hi.is_finite() {
        // Whole decades, at least one below the smallest bar so that it shows.
        let a = (lo.floor() - if lo == lo.floor() { 1.0 } else { 0.0 }).max(-330.0);
        let b = hi.ceil().max(a + 1.0).min(330.0);
        (a, b)
    } else {
        (0.0, 1.0)
    };
    let px = |l: f64| left + (l - lo) / (hi - lo) * (right - left);
    let mut o = String::new();
    let _ = writeln!(
        o,
        "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\" {FONT} font-size=\"13\">"
    );
    let _ = writeln!(o, "<title>{}</title>", escape(title));
    let _ = writeln!(o, "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>");
    let _ = writeln!(
        o,
        "<text class=\"title\" x=\"{:.2}\" y=\"28\" text-anchor=\"middle\" font-size=\"16\" font-weight=\"bold\">{}</text>",
        w / 2.0,
        escape(title)
    );
    let bottom = top + row * n;
    // Decade grid and labels: at most about eight labels.
    let decades = (hi - lo).round() as i64;
    let step = (decades as f64 / 8.0).ceil().max(1.0) as i64;
    let mut d = 0;
    while d <= decades {
        let l = lo + d as f64;
        let x = px(l);
        let _ = writeln!(
            o,
            "<line x1=\"{x:.2}\" y1=\"{:.2}\" x2=\"{x:.2}\" y2=\"{bottom:.2}\" stroke=\"#dddddd\"/>",
            top - 4.0
        );
        let _ = writeln!(
            o,
            "<text class=\"tick\" x=\"{x:.2}\" y=\"{:.2}\" text-anchor=\"middle\">{}</text>",
            bottom + 18.0,
            escape(&tick_label(
                format!("1e{}", l as i64).parse().unwrap_or(f64::NAN)
            ))
        );
        d += step;
    }
    for (i, (label, v, text)) in bars.iter().enumerate() {
        let y = top + row * i as f64;
        let _ = writeln!(
            o,
            "<text x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"end\">{}</text>",
            left - 10.0,
            y + row / 2.0 + 4.5,
            escape(&if label.chars().count() > fits {
                let mut t: String = label.chars().take(fits.saturating_sub(1)).collect();
                t.push('…');
                t
            } else {
                label.clone()
            })
        );
        let drawn = v.is_finite() && *v > 0.0;
        if drawn {
            let x1 = px(v.log10().clamp(lo, hi));
            let _ = writeln!(
                o,
                "<rect class=\"bar\" x=\"{left:.2}\" y=\"{:.2}\" width=\"{:.2}\" height=\"{:.2}\" fill=\"{}\"/>",
                y + 5.0,
                (x1 - left).max(0.5),
                row - 10.0,
                PALETTE[0]
            );
        }
        let _ = writeln!(
            o,
            "<text class=\"value\" x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"end\">{}</text>",
            w - 14.0,
            y + row / 2.0 + 4.5,
            escape(if drawn { text } else { "—" })
        );
    }
    let _ = writeln!(
        o,
        "<line x1=\"{left:.2}\" y1=\"{:.2}\" x2=\"{left:.2}\" y2=\"{bottom:.2}\" stroke=\"black\"/>",
        top - 4.0
    );
    let _ = writeln!(
        o,
        "<text class=\"x-label\" x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"middle\" font-size=\"14\">{}</text>",
        (left + right) / 2.0,
        h - 18.0,
        escape(value_label)
    );
    let _ = writeln!(o, "</svg>");
    o
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn escapes_markup() {
        assert_eq!(
            escape("a<b & \"c\" 'd'>"),
            "a&lt;b &amp; &quot;c&quot; &apos;d&apos;&gt;"
        );
    }

    #[test]
    fn linear_ticks_are_round() {
        let ((lo, hi), ticks) = linear_ticks(0.05, 5.0, false);
        assert_eq!((lo, hi), (0.0, 5.0));
        let labels: Vec<&str> = ticks.iter().map(|t| t.label.as_str()).collect();
        assert_eq!(labels, ["0", "1", "2", "3", "4", "5"]);
        // Steps of 0.1 print as 0.3, not 0.30000000000000004; no "-0".
        let ((lo, hi), ticks) = linear_ticks(-0.23, 0.27, false);
        assert_eq!((lo, hi), (-0.3, 0.3));
        let labels: Vec<&str> = ticks.iter().map(|t| t.label.as_str()).collect();
        assert_eq!(labels, ["-0.3", "-0.2", "-0.1", "0", "0.1", "0.2", "0.3"]);
        let ((lo, hi), _) = linear_ticks(2.0e-9, 7.5e-9, false);
        assert_eq!((lo, hi), (2e-9, 8e-9));
        // Far from 1 the ticks are the decimal values themselves (10^146 is not a
        // double: dividing by it printed 1.4999999999999994e-145).
        let ((lo, hi), ticks) = linear_ticks(0.0, 1.309e-145, false);
        assert_eq!((lo, hi), (0.0, 1.5e-145));
        let labels: Vec<&str> = ticks.iter().map(|t| t.label.as_str()).collect();
        assert_eq!(labels, ["0", "5e-146", "1e-145", "1.5e-145"]);
        // A fixed range keeps at least four labelled ticks inside it (−7.5 … 18
        // had only 0 and 10 at a step of 10).
        let (_, ticks) = linear_ticks(-7.5, 18.0, true);
        let inside = ticks
            .iter()
            .filter(|t| (-7.5..=18.0).contains(&t.at))
            .count();
        assert!(inside >= 4, "{inside}");
        let ((_, hi), ticks) = linear_ticks(0.0, 2.7e200, false);
        assert_eq!(hi, 3e200);
        assert_eq!(ticks[1].label, "1e200");
    }

    #[test]
    fn log_axis_drops_non_positive_points() {
        let svg = LinePlot::new("t", Axis::log("x"), Axis::linear("y"))
            .with_series(Series::new(
                "s",
                vec![(-1.0, 1.0), (1.0, 2.0), (10.0, 3.0), (100.0, 4.0)],
            ))
            .to_svg();
        let line = svg.lines().find(|l| l.starts_with("<polyline")).unwrap();
        assert_eq!(line.matches(',').count(), 3);
        assert!(svg.contains(">1</text>") && svg.contains(">100</text>"));
    }

    /// Every log axis labels at least four ticks: decades over three or more,
    /// 1, 2 and 5 of each decade over one or two (a front over 1e7…1e8 Pa had
    /// only its two ends labelled).
    #[test]
    fn log_axes_label_at_least_four_ticks() {
        for (lo, hi) in [
            (7.0, 8.0),
            (7.2, 7.9),
            (-17.0, -15.0),
            (0.0, 3.0),
            (-300.0, -1.0),
        ] {
            let (_, ticks) = log_ticks(lo, hi);
            let labels: Vec<&str> = ticks
                .iter()
                .filter(|t| !t.label.is_empty())
                .map(|t| t.label.as_str())
                .collect();
            assert!(labels.len() >= 4, "{lo}…{hi}: {labels:?}");
        }
        let (_, ticks) = log_ticks(7.0, 8.0);
        let labels: Vec<&str> = ticks
            .iter()
            .filter(|t| !t.label.is_empty())
            .map(|t| t.label.as_str())
            .collect();
        assert_eq!(labels, ["1e7", "2e7", "5e7", "1e8"]);
    }

    /// Data that are all zero (a front that never wears) get an axis from 0 to 1,
    /// not -1 to 1: no negative ticks for a quantity that may not be negative. A
    /// constant non-zero value keeps a ±10 % band around it.
    #[test]
    fn all_zero_data_start_the_axis_at_zero() {
        let zeros = Axis::linear("wear");
        let ((lo, hi), ticks) = axis_layout(&zeros, [0.0, 0.0, 0.0].into_iter());
        assert_eq!((lo, hi), (0.0, 1.0));
        assert!(ticks
            .iter()
            .all(|t| t.at >= 0.0 && !t.label.starts_with('-')));
        let ((lo, hi), _) = axis_layout(&zeros, [5.0, 5.0].into_iter());
        assert!(lo < 5.0 && hi > 5.0 && lo >= 4.0 && hi <= 6.0, "{lo} {hi}");
    }
}
