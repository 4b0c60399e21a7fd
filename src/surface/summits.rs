//! The cross-check by counting summits (SURFACES.md §6).

use rayon::prelude::*;
use serde::Serialize;

use super::HeightMap;

/// Summits counted on the map: points higher than all 8 neighbours, all of them valid.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SummitCount {
    /// Number of summits.
    pub count: usize,
    /// Points that could be summits: valid, not on the border, all 8 neighbours valid.
    pub candidates: usize,
    /// count / (candidates Δx Δy), m⁻².
    pub density: f64,
    /// Population standard deviation of summit heights, m (None with fewer than 2).
    pub sigma: Option<f64>,
    /// Mean summit height above the mean plane, m (None without summits).
    pub mean_height: Option<f64>,
    /// Mean of 1/κ with κ = −½ (h_xx + h_yy), m (None without summits).
    pub mean_radius: Option<f64>,
}

#[derive(Clone, Copy, Default)]
struct Row {
    count: usize,
    candidates: usize,
    sum_h: f64,
    sum_r: f64,
}

impl SummitCount {
    /// Counts the summits of a (levelled) 2-D map. Heights are summed in a second pass
    /// around their mean for an accurate spread; rows combine in order (thread-count
    /// independent).
    pub fn of(map: &HeightMap) -> SummitCount {
        let (nx, ny) = (map.nx(), map.ny());
        let (dx, dy) = (map.pixel_size_x(), map.pixel_size_y());
        if nx < 3 || ny < 3 {
            return SummitCount {
                count: 0,
                candidates: 0,
                density: 0.0,
                sigma: None,
                mean_height: None,
                mean_radius: None,
            };
        }
        // Summit heights per row (kept for the second pass).
        let rows: Vec<(Row, Vec<f64>)> = (1..ny - 1)
            .into_par_iter()
            .map(|j| {
                let (up, mid, down) = (map.row(j - 1), map.row(j), map.row(j + 1));
                let mut r = Row::default();
                let mut heights = Vec::new();
                for i in 1..nx - 1 {
                    let h = mid[i];
                    let around = [
                        up[i - 1],
                        up[i],
                        up[i + 1],
                        mid[i - 1],
                        mid[i + 1],
                        down[i - 1],
                        down[i],
                        down[i + 1],
                    ];
                    if h.is_nan() || around.iter().any(|a| a.is_nan()) {
                        continue;
                    }
                    r.candidates += 1;
                    if around.iter().all(|&a| h > a) {
                        let hxx = (mid[i + 1] - 2.0 * h + mid[i - 1]) / (dx * dx);
                        let hyy = (down[i] - 2.0 * h + up[i]) / (dy * dy);
                        let kappa = -0.5 * (hxx + hyy);
                        r.count += 1;
                        r.sum_h += h;
                        r.sum_r += 1.0 / kappa;
                        heights.push(h);
                    }
                }
                (r, heights)
            })
            .collect();
        let mut t = Row::default();
        for (r, _) in &rows {
            t.count += r.count;
            t.candidates += r.candidates;
            t.sum_h += r.sum_h;
            t.sum_r += r.sum_r;
        }
        let density = if t.candidates == 0 {
            0.0
        } else {
            t.count as f64 / (t.candidates as f64 * dx * dy)
        };
        let n = t.count as f64;
        let mean_height = (t.count > 0).then(|| t.sum_h / n);
        let sigma = (t.count > 1).then(|| {
            let m = t.sum_h / n;
            let ss: f64 = rows
                .iter()
                .map(|(_, hs)| hs.iter().map(|h| (h - m) * (h - m)).sum::<f64>())
                .sum();
            (ss / n).sqrt()
        });
        SummitCount {
            count: t.count,
            candidates: t.candidates,
            density,
            sigma,
            mean_height,
            mean_radius: (t.count > 0).then(|| t.sum_r / n),
        }
    }
}
