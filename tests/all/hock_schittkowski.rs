//! The SQP on textbook problems: Hock–Schittkowski problems with inequality
//! constraints and bounds, written by hand from their published definitions
//! (W. Hock and K. Schittkowski, *Test Examples for Nonlinear Programming
//! Codes*, Lecture Notes in Economics and Mathematical Systems 187, Springer,
//! 1981; problem numbers below). Each optimum f* is the book's value, or its
//! closed form where the book's solution has one (given beside it).
//!
//! HS writes constraints as c(x) ≥ 0; here they are g = -c ≤ 0. Infinite
//! bounds are closed by a box ±1e3 around the standard start, which every
//! solution lies far inside. Every problem is solved from its standard start
//! with the default settings, to status `optimal` and 1e-6 relative in f
//! (|f - f*| / max(1, |f*|)), but for the problems listed in
//! `NOT_YET_SOLVED` (each with how its run ends). The set is checked against
//! an independent transcription (`scripts/hock_schittkowski.py`, which also
//! runs scipy's SLSQP on it): the printed table gives both solvers'
//! evaluation counts (`cargo test --release --test all hock_schittkowski:: --
//! --nocapture`).

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use wearopt::optimize::{minimize, NonlinearProgram, SqpSettings, SqpStatus};

const INF: f64 = f64::INFINITY;
const WIDE: f64 = 1e3;

struct Hs {
    number: u32,
    x0: Vec<f64>,
    lower: Vec<f64>,
    upper: Vec<f64>,
    f: fn(&[f64]) -> f64,
    c: fn(&[f64]) -> Vec<f64>,
    /// The optimum and where it comes from.
    fstar: f64,
    source: &'static str,
    outside: AtomicBool,
    calls: AtomicUsize,
}

impl Hs {
    #[allow(clippy::too_many_arguments)]
    fn new(
        number: u32,
        x0: &[f64],
        lower: &[f64],
        upper: &[f64],
        f: fn(&[f64]) -> f64,
        c: fn(&[f64]) -> Vec<f64>,
        fstar: f64,
        source: &'static str,
    ) -> Hs {
        Hs {
            number,
            x0: x0.to_vec(),
            lower: lower
                .iter()
                .zip(x0)
                .map(|(&l, &s)| if l == -INF { s - WIDE } else { l })
                .collect(),
            upper: upper
                .iter()
                .zip(x0)
                .map(|(&u, &s)| if u == INF { s + WIDE } else { u })
                .collect(),
            f,
            c,
            fstar,
            source,
            outside: AtomicBool::new(false),
            calls: AtomicUsize::new(0),
        }
    }

    fn check(&self, x: &[f64]) {
        if x.iter()
            .zip(self.lower.iter().zip(&self.upper))
            .any(|(v, (l, u))| v < l || v > u)
        {
            self.outside.store(true, Ordering::Relaxed);
        }
    }
}

impl NonlinearProgram for Hs {
    fn dimension(&self) -> usize {
        self.x0.len()
    }
    fn bounds(&self) -> (Vec<f64>, Vec<f64>) {
        (self.lower.clone(), self.upper.clone())
    }
    fn objective(&self, x: &[f64]) -> Option<f64> {
        self.check(x);
        self.calls.fetch_add(1, Ordering::Relaxed);
        Some((self.f)(x))
    }
    fn constraints(&self, x: &[f64]) -> Option<Vec<f64>> {
        self.check(x);
        Some((self.c)(x).into_iter().map(|c| -c).collect())
    }
}

fn problems() -> Vec<Hs> {
    let mut all = vec![
        Hs::new(
            1,
            &[-2.0, 1.0],
            &[-INF, -1.5],
            &[INF; 2],
            |x| 100.0 * (x[1] - x[0] * x[0]).powi(2) + (1.0 - x[0]).powi(2),
            |_| vec![],
            0.0,
            "HS 1 (Rosenbrock): f* = 0 at (1, 1)",
        ),
        Hs::new(
            3,
            &[10.0, 1.0],
            &[-INF, 0.0],
            &[INF; 2],
            |x| x[1] + 1e-5 * (x[1] - x[0]).powi(2),
            |_| vec![],
            0.0,
            "HS 3: f* = 0 at (0, 0)",
        ),
        Hs::new(
            4,
            &[1.125, 0.125],
            &[1.0, 0.0],
            &[INF; 2],
            |x| (x[0] + 1.0).powi(3) / 3.0 + x[1],
            |_| vec![],
            8.0 / 3.0,
            "HS 4: f* = 8/3 at (1, 0)",
        ),
        Hs::new(
            5,
            &[0.0, 0.0],
            &[-1.5, -3.0],
            &[4.0, 3.0],
            |x| (x[0] + x[1]).sin() + (x[0] - x[1]).powi(2) - 1.5 * x[0] + 2.5 * x[1] + 1.0,
            |_| vec![],
            -(3f64.sqrt()) / 2.0 - std::f64::consts::PI / 3.0,
            "HS 5: f* = -√3/2 - π/3 at (1/2 - π/3, -1/2 - π/3)",
        ),
        Hs::new(
            25,
            &[100.0, 12.5, 3.0],
            &[0.1, 0.0, 0.0],
            &[100.0, 25.6, 5.0],
            |x| {
                (1..=99)
                    .map(|i| {
                        let i = f64::from(i);
                        let u = 25.0 + (-50.0 * (0.01 * i).ln()).powf(2.0 / 3.0);
                        let r = -0.01 * i + (-(u - x[1]).abs().powf(x[2]) / x[0]).exp();
                        r * r
                    })
                    .sum()
            },
            |_| vec![],
            0.0,
            "HS 25: f* = 0 at (50, 25, 1.5)",
        ),
        Hs::new(
            38,
            &[-3.0, -1.0, -3.0, -1.0],
            &[-10.0; 4],
            &[10.0; 4],
            |x| {
                100.0 * (x[1] - x[0] * x[0]).powi(2)
                    + (1.0 - x[0]).powi(2)
                    + 90.0 * (x[3] - x[2] * x[2]).powi(2)
                    + (1.0 - x[2]).powi(2)
                    + 10.1 * ((x[1] - 1.0).powi(2) + (x[3] - 1.0).powi(2))
                    + 19.8 * (x[1] - 1.0) * (x[3] - 1.0)
            },
            |_| vec![],
            0.0,
            "HS 38 (Colville): f* = 0 at (1, 1, 1, 1)",
        ),
        Hs::new(
            110,
            &[9.0; 10],
            &[2.001; 10],
            &[9.999; 10],
            |x| {
                let logs: f64 = x
                    .iter()
                    .map(|&v| (v - 2.0).ln().powi(2) + (10.0 - v).ln().powi(2))
                    .sum();
                logs - x.iter().product::<f64>().powf(0.2)
            },
            |_| vec![],
            -45.77846971,
            "HS 110: f* = -45.77846971 at x_i = 9.35026583",
        ),
        Hs::new(
            10,
            &[-10.0, 10.0],
            &[-INF; 2],
            &[INF; 2],
            |x| x[0] - x[1],
            |x| vec![-3.0 * x[0] * x[0] + 2.0 * x[0] * x[1] - x[1] * x[1] + 1.0],
            -1.0,
            "HS 10: f* = -1 at (0, 1)",
        ),
        Hs::new(
            11,
            &[4.9, 0.1],
            &[-INF; 2],
            &[INF; 2],
            |x| (x[0] - 5.0).powi(2) + x[1] * x[1] - 25.0,
            |x| vec![-x[0] * x[0] + x[1]],
            -8.498464223,
            "HS 11: f* = -8.498464223",
        ),
        Hs::new(
            12,
            &[0.0, 0.0],
            &[-INF; 2],
            &[INF; 2],
            |x| 0.5 * x[0] * x[0] + x[1] * x[1] - x[0] * x[1] - 7.0 * x[0] - 7.0 * x[1],
            |x| vec![25.0 - 4.0 * x[0] * x[0] - x[1] * x[1]],
            -30.0,
            "HS 12: f* = -30 at (2, 3)",
        ),
        Hs::new(
            15,
            &[-2.0, 1.0],
            &[-INF, -INF],
            &[0.5, INF],
            |x| 100.0 * (x[1] - x[0] * x[0]).powi(2) + (1.0 - x[0]).powi(2),
            |x| vec![x[0] * x[1] - 1.0, x[0] + x[1] * x[1]],
            306.5,
            "HS 15: f* = 306.5 at (0.5, 2)",
        ),
        Hs::new(
            18,
            &[2.0, 2.0],
            &[2.0, 0.0],
            &[50.0, 50.0],
            |x| 0.01 * x[0] * x[0] + x[1] * x[1],
            |x| vec![x[0] * x[1] - 25.0, x[0] * x[0] + x[1] * x[1] - 25.0],
            5.0,
            "HS 18: f* = 5 at (√250, √2.5)",
        ),
        Hs::new(
            19,
            &[20.1, 5.84],
            &[13.0, 0.0],
            &[100.0, 100.0],
            |x| (x[0] - 10.0).powi(3) + (x[1] - 20.0).powi(3),
            |x| {
                vec![
                    (x[0] - 5.0).powi(2) + (x[1] - 5.0).powi(2) - 100.0,
                    -(x[1] - 5.0).powi(2) - (x[0] - 6.0).powi(2) + 82.81,
                ]
            },
            // Both rows active: x1 = 14.095, x2 = 5 - √(100 - 9.095²).
            {
                let x2 = 5.0 - (100.0f64 - 9.095 * 9.095).sqrt();
                (14.095f64 - 10.0).powi(3) + (x2 - 20.0).powi(3)
            },
            "HS 19: f* = -6961.81381 (closed form at x = (14.095, 5 - √(100 - 9.095²)))",
        ),
        Hs::new(
            21,
            &[-1.0, -1.0],
            &[2.0, -50.0],
            &[50.0, 50.0],
            |x| 0.01 * x[0] * x[0] + x[1] * x[1] - 100.0,
            |x| vec![10.0 * x[0] - x[1] - 10.0],
            -99.96,
            "HS 21: f* = -99.96 at (2, 0)",
        ),
        Hs::new(
            22,
            &[2.0, 2.0],
            &[-INF; 2],
            &[INF; 2],
            |x| (x[0] - 2.0).powi(2) + (x[1] - 1.0).powi(2),
            |x| vec![2.0 - x[0] - x[1], x[1] - x[0] * x[0]],
            1.0,
            "HS 22: f* = 1 at (1, 1)",
        ),
        Hs::new(
            23,
            &[3.0, 1.0],
            &[-50.0; 2],
            &[50.0; 2],
            |x| x[0] * x[0] + x[1] * x[1],
            |x| {
                vec![
                    x[0] + x[1] - 1.0,
                    x[0] * x[0] + x[1] * x[1] - 1.0,
                    9.0 * x[0] * x[0] + x[1] * x[1] - 9.0,
                    x[0] * x[0] - x[1],
                    x[1] * x[1] - x[0],
                ]
            },
            2.0,
            "HS 23: f* = 2 at (1, 1)",
        ),
        Hs::new(
            24,
            &[1.0, 0.5],
            &[0.0, 0.0],
            &[INF, INF],
            |x| ((x[0] - 3.0).powi(2) - 9.0) * x[1].powi(3) / (27.0 * 3f64.sqrt()),
            |x| {
                let s = 3f64.sqrt();
                vec![x[0] / s - x[1], x[0] + s * x[1], 6.0 - x[0] - s * x[1]]
            },
            -1.0,
            "HS 24: f* = -1 at (3, √3)",
        ),
        Hs::new(
            29,
            &[1.0, 1.0, 1.0],
            &[-INF; 3],
            &[INF; 3],
            |x| -x[0] * x[1] * x[2],
            |x| vec![48.0 - x[0] * x[0] - 2.0 * x[1] * x[1] - 4.0 * x[2] * x[2]],
            -16.0 * 2f64.sqrt(),
            "HS 29: f* = -16√2 = -22.627417 at (4, 2√2, 2)",
        ),
        Hs::new(
            30,
            &[1.0, 1.0, 1.0],
            &[1.0, -10.0, -10.0],
            &[10.0; 3],
            |x| x[0] * x[0] + x[1] * x[1] + x[2] * x[2],
            |x| vec![x[0] * x[0] + x[1] * x[1] - 1.0],
            1.0,
            "HS 30: f* = 1 at (1, 0, 0)",
        ),
        Hs::new(
            31,
            &[1.0, 1.0, 1.0],
            &[-10.0, 1.0, -10.0],
            &[10.0, 10.0, 1.0],
            |x| 9.0 * x[0] * x[0] + x[1] * x[1] + 9.0 * x[2] * x[2],
            |x| vec![x[0] * x[1] - 1.0],
            6.0,
            "HS 31: f* = 6 at (1/√3, √3, 0)",
        ),
        Hs::new(
            33,
            &[0.0, 0.0, 3.0],
            &[0.0; 3],
            &[INF, INF, 5.0],
            |x| (x[0] - 1.0) * (x[0] - 2.0) * (x[0] - 3.0) + x[2],
            |x| {
                vec![
                    x[2] * x[2] - x[0] * x[0] - x[1] * x[1],
                    x[0] * x[0] + x[1] * x[1] + x[2] * x[2] - 4.0,
                ]
            },
            2f64.sqrt() - 6.0,
            "HS 33: f* = √2 - 6 = -4.585786 at (0, √2, √2)",
        ),
        Hs::new(
            34,
            &[0.0, 1.05, 2.9],
            &[0.0; 3],
            &[100.0, 100.0, 10.0],
            |x| -x[0],
            |x| vec![x[1] - x[0].exp(), x[2] - x[1].exp()],
            -(10f64.ln().ln()),
            "HS 34: f* = -ln ln 10 = -0.834032445 at (ln ln 10, ln 10, 10)",
        ),
        Hs::new(
            35,
            &[0.5; 3],
            &[0.0; 3],
            &[INF; 3],
            |x| {
                9.0 - 8.0 * x[0] - 6.0 * x[1] - 4.0 * x[2]
                    + 2.0 * x[0] * x[0]
                    + 2.0 * x[1] * x[1]
                    + x[2] * x[2]
                    + 2.0 * x[0] * x[1]
                    + 2.0 * x[0] * x[2]
            },
            |x| vec![3.0 - x[0] - x[1] - 2.0 * x[2]],
            1.0 / 9.0,
            "HS 35: f* = 1/9 at (4/3, 7/9, 4/9)",
        ),
        Hs::new(
            36,
            &[10.0; 3],
            &[0.0; 3],
            &[20.0, 11.0, 42.0],
            |x| -x[0] * x[1] * x[2],
            |x| vec![72.0 - x[0] - 2.0 * x[1] - 2.0 * x[2]],
            -3300.0,
            "HS 36: f* = -3300 at (20, 11, 15)",
        ),
        Hs::new(
            37,
            &[10.0; 3],
            &[0.0; 3],
            &[42.0; 3],
            |x| -x[0] * x[1] * x[2],
            |x| {
                vec![
                    72.0 - x[0] - 2.0 * x[1] - 2.0 * x[2],
                    x[0] + 2.0 * x[1] + 2.0 * x[2],
                ]
            },
            -3456.0,
            "HS 37: f* = -3456 at (24, 12, 12)",
        ),
        Hs::new(
            43,
            &[0.0; 4],
            &[-INF; 4],
            &[INF; 4],
            |x| {
                x[0] * x[0] + x[1] * x[1] + 2.0 * x[2] * x[2] + x[3] * x[3]
                    - 5.0 * x[0]
                    - 5.0 * x[1]
                    - 21.0 * x[2]
                    + 7.0 * x[3]
            },
            |x| {
                vec![
                    8.0 - x[0] * x[0] - x[1] * x[1] - x[2] * x[2] - x[3] * x[3] - x[0] + x[1]
                        - x[2]
                        + x[3],
                    10.0 - x[0] * x[0] - 2.0 * x[1] * x[1] - x[2] * x[2] - 2.0 * x[3] * x[3]
                        + x[0]
                        + x[3],
                    5.0 - 2.0 * x[0] * x[0] - x[1] * x[1] - x[2] * x[2] - 2.0 * x[0] + x[1] + x[3],
                ]
            },
            -44.0,
            "HS 43 (Rosen–Suzuki): f* = -44 at (0, 1, 2, -1)",
        ),
        Hs::new(
            65,
            &[-5.0, 5.0, 0.0],
            &[-4.5, -4.5, -5.0],
            &[4.5, 4.5, 5.0],
            |x| (x[0] - x[1]).powi(2) + (x[0] + x[1] - 10.0).powi(2) / 9.0 + (x[2] - 5.0).powi(2),
            |x| vec![48.0 - x[0] * x[0] - x[1] * x[1] - x[2] * x[2]],
            0.9535288567,
            "HS 65: f* = 0.9535288567",
        ),
        Hs::new(
            66,
            &[0.0, 1.05, 2.9],
            &[0.0; 3],
            &[100.0, 100.0, 10.0],
            |x| 0.2 * x[2] - 0.8 * x[0],
            |x| vec![x[1] - x[0].exp(), x[2] - x[1].exp()],
            0.5181632741,
            "HS 66: f* = 0.5181632741",
        ),
        Hs::new(
            76,
            &[0.5; 4],
            &[0.0; 4],
            &[INF; 4],
            |x| {
                x[0] * x[0] + 0.5 * x[1] * x[1] + x[2] * x[2] + 0.5 * x[3] * x[3] - x[0] * x[2]
                    + x[2] * x[3]
                    - x[0]
                    - 3.0 * x[1]
                    + x[2]
                    - x[3]
            },
            |x| {
                vec![
                    5.0 - x[0] - 2.0 * x[1] - x[2] - x[3],
                    4.0 - 3.0 * x[0] - x[1] - 2.0 * x[2] + x[3],
                    x[1] + 4.0 * x[2] - 1.5,
                ]
            },
            -103.0 / 22.0,
            "HS 76: f* = -4.681818181 (= -103/22)",
        ),
        Hs::new(
            100,
            &[1.0, 2.0, 0.0, 4.0, 0.0, 1.0, 1.0],
            &[-INF; 7],
            &[INF; 7],
            |x| {
                (x[0] - 10.0).powi(2)
                    + 5.0 * (x[1] - 12.0).powi(2)
                    + x[2].powi(4)
                    + 3.0 * (x[3] - 11.0).powi(2)
                    + 10.0 * x[4].powi(6)
                    + 7.0 * x[5] * x[5]
                    + x[6].powi(4)
                    - 4.0 * x[5] * x[6]
                    - 10.0 * x[5]
                    - 8.0 * x[6]
            },
            |x| {
                vec![
                    127.0
                        - 2.0 * x[0] * x[0]
                        - 3.0 * x[1].powi(4)
                        - x[2]
                        - 4.0 * x[3] * x[3]
                        - 5.0 * x[4],
                    282.0 - 7.0 * x[0] - 3.0 * x[1] - 10.0 * x[2] * x[2] - x[3] + x[4],
                    196.0 - 23.0 * x[0] - x[1] * x[1] - 6.0 * x[5] * x[5] + 8.0 * x[6],
                    -4.0 * x[0] * x[0] - x[1] * x[1] + 3.0 * x[0] * x[1]
                        - 2.0 * x[2] * x[2]
                        - 5.0 * x[5]
                        + 11.0 * x[6],
                ]
            },
            680.6300573,
            "HS 100: f* = 680.6300573",
        ),
        Hs::new(
            113,
            &[2.0, 3.0, 5.0, 5.0, 1.0, 2.0, 7.0, 3.0, 6.0, 10.0],
            &[-INF; 10],
            &[INF; 10],
            |x| {
                x[0] * x[0] + x[1] * x[1] + x[0] * x[1] - 14.0 * x[0] - 16.0 * x[1]
                    + (x[2] - 10.0).powi(2)
                    + 4.0 * (x[3] - 5.0).powi(2)
                    + (x[4] - 3.0).powi(2)
                    + 2.0 * (x[5] - 1.0).powi(2)
                    + 5.0 * x[6] * x[6]
                    + 7.0 * (x[7] - 11.0).powi(2)
                    + 2.0 * (x[8] - 10.0).powi(2)
                    + (x[9] - 7.0).powi(2)
                    + 45.0
            },
            |x| {
                vec![
                    105.0 - 4.0 * x[0] - 5.0 * x[1] + 3.0 * x[6] - 9.0 * x[7],
                    -10.0 * x[0] + 8.0 * x[1] + 17.0 * x[6] - 2.0 * x[7],
                    8.0 * x[0] - 2.0 * x[1] - 5.0 * x[8] + 2.0 * x[9] + 12.0,
                    -3.0 * (x[0] - 2.0).powi(2) - 4.0 * (x[1] - 3.0).powi(2) - 2.0 * x[2] * x[2]
                        + 7.0 * x[3]
                        + 120.0,
                    -5.0 * x[0] * x[0] - 8.0 * x[1] - (x[2] - 6.0).powi(2) + 2.0 * x[3] + 40.0,
                    -0.5 * (x[0] - 8.0).powi(2) - 2.0 * (x[1] - 4.0).powi(2) - 3.0 * x[4] * x[4]
                        + x[5]
                        + 30.0,
                    -x[0] * x[0] - 2.0 * (x[1] - 2.0).powi(2) + 2.0 * x[0] * x[1] - 14.0 * x[4]
                        + 6.0 * x[5],
                    3.0 * x[0] - 6.0 * x[1] - 12.0 * (x[8] - 8.0).powi(2) + 7.0 * x[9],
                ]
            },
            24.3062091,
            "HS 113: f* = 24.3062091",
        ),
    ];
    all.extend(more_problems());
    all.sort_by_key(|p| p.number);
    all
}

/// The problems of the set the SQP does not yet solve to `optimal` within
/// 1e-6 of f* from the standard start with the default settings, and how each
/// run ends. The test fails when this list is wrong either way: a problem that
/// starts failing, or one that a change has fixed (then take it off).
const NOT_YET_SOLVED: &[(u32, &str)] = &[];

/// One problem of the independent Python transcription and its SLSQP runs
/// (`scripts/hock_schittkowski.py`, `tests/data/hock_schittkowski_slsqp.json`).
struct Reference {
    f_x0: f64,
    c_x0: Vec<f64>,
    /// SLSQP's objective calls (finite differences included) at ftol 1e-10,
    /// and whether it ended within 1e-6 of f*.
    slsqp_calls: u64,
    slsqp_solved: bool,
}

fn references() -> std::collections::BTreeMap<u32, Reference> {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/hock_schittkowski_slsqp.json"
    ))
    .expect("tests/data/hock_schittkowski_slsqp.json");
    let json: serde_json::Value = serde_json::from_str(&text).expect("valid JSON");
    json["problems"]
        .as_array()
        .expect("problems")
        .iter()
        .map(|p| {
            let tight = &p["slsqp_tight"];
            (
                p["number"].as_u64().expect("number") as u32,
                Reference {
                    f_x0: p["f_x0"].as_f64().expect("f_x0"),
                    c_x0: p["c_x0"]
                        .as_array()
                        .expect("c_x0")
                        .iter()
                        .map(|v| v.as_f64().expect("c_x0 value"))
                        .collect(),
                    slsqp_calls: tight["objective_calls"].as_u64().expect("calls"),
                    slsqp_solved: tight["rel"].as_f64().expect("rel") <= 1e-6,
                },
            )
        })
        .collect()
}

/// The set is the whole of it: every problem of the 1981 collection with
/// inequality constraints and bounds only whose standard start lies in its
/// box (59, listed with the exclusions and their reasons by
/// `scripts/hock_schittkowski.py`), each transcribed here independently of
/// that script and checked against it at the start: f(x0) and every row
/// c(x0) agree to 1e-12. HS 17, 20, 21 and 65 are solved besides, from the
/// starts of Schittkowski's later code (17, 20, 21) or projected (65).
#[test]
fn hock_schittkowski_problems_solve_to_optimal_from_their_standard_starts() {
    let settings = SqpSettings::default();
    let references = references();
    let all = problems();
    let numbers: Vec<u32> = all.iter().map(|p| p.number).collect();
    for n in references.keys() {
        assert!(numbers.contains(n), "HS {n} of the set is not solved here");
    }
    assert!(references.len() >= 50);
    let mut unsolved = Vec::new();
    let mut lines = Vec::new();
    for p in &all {
        if let Some(r) = references.get(&p.number) {
            let f = (p.f)(&p.x0);
            assert!(
                (f - r.f_x0).abs() <= 1e-12 * r.f_x0.abs().max(1.0),
                "HS {}: f(x0) = {f} here, {} in the script",
                p.number,
                r.f_x0
            );
            let c = (p.c)(&p.x0);
            assert_eq!(c.len(), r.c_x0.len(), "HS {}: rows", p.number);
            for (j, (a, b)) in c.iter().zip(&r.c_x0).enumerate() {
                assert!(
                    (a - b).abs() <= 1e-12 * b.abs().max(1.0),
                    "HS {} row {j}: c(x0) = {a} here, {b} in the script",
                    p.number
                );
            }
        }
        let r = minimize(p, &p.x0, &settings);
        let rel = (r.objective - p.fstar).abs() / p.fstar.abs().max(1.0);
        let slsqp = references.get(&p.number).map_or("—".to_string(), |q| {
            format!(
                "SLSQP {} ({:.1}x{})",
                q.slsqp_calls,
                r.evaluations as f64 / q.slsqp_calls as f64,
                if q.slsqp_solved {
                    ""
                } else {
                    ", SLSQP not within 1e-6"
                }
            )
        });
        let line = format!(
            "HS {:>3}: {} f = {:.12} (f* = {:.12}, rel {:.1e}), KKT {:.1e}, {} iterations, {} evaluations; {} [{}]",
            p.number, r.status, r.objective, p.fstar, rel, r.kkt_residual, r.iterations, r.evaluations, slsqp, p.source
        );
        println!("{line}");
        if r.status == SqpStatus::Optimal {
            // `optimal` never with a wrong answer.
            assert!(
                rel <= 1e-6 && r.kkt_residual <= settings.tolerance,
                "{line}"
            );
        } else {
            unsolved.push(p.number);
        }
        lines.push(line);
        assert!(
            !p.outside.load(Ordering::Relaxed),
            "HS {} evaluated outside its bounds",
            p.number
        );
        assert_eq!(
            r.evaluations,
            p.calls.load(Ordering::Relaxed),
            "HS {}",
            p.number
        );
        assert_eq!(r.multipliers.len(), (p.c)(&p.x0).len());
        assert!(r.multipliers.iter().all(|l| *l >= 0.0));
        assert!(r.objective.is_finite() && r.kkt_residual.is_finite());
    }
    let declared: Vec<u32> = NOT_YET_SOLVED.iter().map(|(n, _)| *n).collect();
    assert_eq!(unsolved, declared, "\n{}", lines.join("\n"));
}

/// The iteration table of one problem, for diagnosis.
#[test]
#[ignore = "diagnostic: HS=15 cargo test --test all hock_schittkowski::iteration_table -- --ignored --nocapture"]
fn iteration_table() {
    struct Print;
    impl argmin::core::observers::Observe<wearopt::optimize::SqpState> for Print {
        fn observe_iter(
            &mut self,
            _s: &wearopt::optimize::SqpState,
            kv: &argmin::core::KV,
        ) -> Result<(), argmin::core::Error> {
            let get = |k: &str| kv.get(k).and_then(|v| v.get_float()).unwrap_or(f64::NAN);
            println!(
                "f {:.6} viol {:.2e} kkt {:.2e} radius {:.2e} pen {:.2e} step {:.2e} ratio {:.3}",
                get("objective"),
                get("violation"),
                get("kkt"),
                get("radius"),
                get("penalty"),
                get("step"),
                get("ratio")
            );
            Ok(())
        }
    }
    let n: u32 = std::env::var("HS").map_or(15, |v| v.parse().expect("HS=<problem number>"));
    let all = problems();
    let p = all.iter().find(|p| p.number == n).unwrap();
    let r = wearopt::optimize::minimize_observed(p, &p.x0, &SqpSettings::default(), Some(Print));
    println!("{:?} {:?} {}", r.status, r.x, r.objective);
    assert_eq!(r.status, SqpStatus::Optimal);
}

fn rosenbrock(x: &[f64]) -> f64 {
    100.0 * (x[1] - x[0] * x[0]).powi(2) + (1.0 - x[0]).powi(2)
}

/// HS 57: a least-squares fit to 44 points (a_i, b_i).
fn hs57(x: &[f64]) -> f64 {
    const A: [f64; 44] = [
        8., 8., 10., 10., 10., 10., 12., 12., 12., 12., 14., 14., 14., 16., 16., 16., 18., 18.,
        20., 20., 20., 22., 22., 22., 24., 24., 24., 26., 26., 26., 28., 28., 30., 30., 30., 32.,
        32., 34., 36., 36., 38., 38., 40., 42.,
    ];
    const B: [f64; 44] = [
        0.49, 0.49, 0.48, 0.47, 0.48, 0.47, 0.46, 0.46, 0.45, 0.43, 0.45, 0.43, 0.43, 0.44, 0.43,
        0.43, 0.46, 0.45, 0.42, 0.42, 0.43, 0.41, 0.41, 0.40, 0.42, 0.40, 0.40, 0.41, 0.40, 0.41,
        0.41, 0.40, 0.40, 0.40, 0.38, 0.41, 0.40, 0.40, 0.41, 0.38, 0.40, 0.40, 0.39, 0.39,
    ];
    A.iter()
        .zip(&B)
        .map(|(a, b)| {
            let r = b - x[0] - (0.49 - x[0]) * (-x[1] * (a - 8.0)).exp();
            r * r
        })
        .sum()
}

/// HS 67: the quantities y2…y8 of an alkylation process, found by the two
/// fixed-point iterations of the published code (tolerances 1e-3 and 1e-4).
fn hs67_y(x: &[f64]) -> [f64; 9] {
    let mut y = [0.0; 9];
    y[2] = 1.6 * x[0];
    for _ in 0..=100 {
        y[3] = 1.22 * y[2] - x[0];
        y[6] = (x[1] + y[3]) / x[0];
        let y2c = 0.01 * x[0] * (112.0 + 13.167 * y[6] - 0.6667 * y[6] * y[6]);
        if (y2c - y[2]).abs() <= 1e-3 {
            break;
        }
        y[2] = y2c;
    }
    y[4] = 93.0;
    for _ in 0..=100 {
        y[5] = 86.35 + 1.098 * y[6] - 0.038 * y[6] * y[6] + 0.325 * (y[4] - 89.0);
        y[8] = -133.0 + 3.0 * y[5];
        y[7] = 35.82 - 0.222 * y[8];
        let y4c = 9.8e4 * x[2] / (y[2] * y[7] + 1e3 * x[2]);
        if (y4c - y[4]).abs() <= 1e-4 {
            break;
        }
        y[4] = y4c;
    }
    y
}

fn hs67_f(x: &[f64]) -> f64 {
    let y = hs67_y(x);
    -(0.063 * y[2] * y[5] - 5.04 * x[0] - 3.36 * y[3] - 0.035 * x[1] - 10.0 * x[2])
}

fn hs67_c(x: &[f64]) -> Vec<f64> {
    let y = hs67_y(x);
    let low = [0.0, 0.0, 85.0, 90.0, 3.0, 0.01, 145.0];
    let high = [5e3, 2e3, 93.0, 95.0, 12.0, 4.0, 162.0];
    (0..7)
        .map(|j| y[j + 2] - low[j])
        .chain((0..7).map(|j| high[j] - y[j + 2]))
        .collect()
}

/// HS 70: a fit of 19 points; where its logarithms are undefined the
/// published code returns Σ(x_i - 5)². Its 6.2832 is the published
/// constant, not 2π.
#[allow(clippy::approx_constant)]
fn hs70(x: &[f64]) -> f64 {
    const YO: [f64; 19] = [
        1.89e-3, 0.1038, 0.268, 0.506, 0.577, 0.604, 0.725, 0.898, 0.947, 0.845, 0.702, 0.528,
        0.385, 0.257, 0.159, 0.0869, 0.0453, 0.01509, 1.89e-3,
    ];
    let b = x[2] + (1.0 - x[2]) * x[3];
    let (h1, h2, h3) = (x[0] - 1.0, x[1] - 1.0, 1.0 / 7.658);
    let h5 = b * h3;
    let h4 = h5 / x[3];
    let h6 = 12.0 * x[0] / (12.0 * x[0] + 1.0);
    let h7 = 12.0 * x[1] / (12.0 * x[1] + 1.0);
    let (v10, v11, v12) = (x[1] / 6.2832, b / x[3], x[0] / 6.2832);
    if b < 0.0 || v10 < 0.0 || v11 < 0.0 || v12 < 0.0 {
        return x.iter().map(|v| (v - 5.0).powi(2)).sum();
    }
    let z1 = x[2] * b.powf(x[1]);
    let z2 = v10.sqrt();
    let z5 = 1.0 - x[2];
    let z6 = v11.powf(x[0]);
    let z7 = v12.sqrt();
    YO.iter()
        .enumerate()
        .map(|(i, yo)| {
            let c = if i == 0 { 0.1 } else { i as f64 };
            let u1 = z1 * z2 * (c * h3).powf(h2) * (x[1] * (1.0 - c * h5)).exp() * h7;
            let u2 = z5 * z6 * z7 * (c * h3).powf(h1) * (x[0] * (1.0 - c * h4)).exp() * h6;
            (u1 + u2 - yo).powi(2)
        })
        .sum()
}

const HS84_A: [f64; 21] = [
    -2.4345e4,
    -8.720288849e6,
    1.505125253e5,
    -1.566950325e2,
    4.764703222e5,
    7.294828271e5,
    -1.45421402e5,
    2.9311506e3,
    -40.427932,
    5.106192e3,
    1.571136e4,
    -1.550111084e5,
    4.36053352e3,
    12.9492344,
    1.0236884e4,
    1.3176786e4,
    -3.266695104e5,
    7.39068412e3,
    -27.8986976,
    1.6643076e4,
    3.0988146e4,
];

fn hs84_f(x: &[f64]) -> f64 {
    let a = &HS84_A;
    -(a[0] + x[0] * (a[1] + a[2] * x[1] + a[3] * x[2] + a[4] * x[3] + a[5] * x[4]))
}

fn hs84_c(x: &[f64]) -> Vec<f64> {
    let a = &HS84_A;
    let b = [2.94e5, 2.94e5, 2.772e5];
    let v: Vec<f64> = (1..=3)
        .map(|i| {
            let k = 5 * i; // a(k+2) … a(k+6), 1-based
            x[0] * (a[k + 1]
                + a[k + 2] * x[1]
                + a[k + 3] * x[2]
                + a[k + 4] * x[3]
                + a[k + 5] * x[4])
        })
        .collect();
    v.iter()
        .copied()
        .chain(v.iter().zip(&b).map(|(v, b)| b - v))
        .collect()
}

/// HS 85: the quantities y1…y17 and c1…c17 of the published code.
fn hs85_yc(x: &[f64]) -> ([f64; 18], [f64; 18]) {
    let mut y = [0.0; 18];
    let mut c = [0.0; 18];
    y[1] = x[1] + x[2] + 41.6;
    c[1] = 0.024 * x[3] - 4.62;
    y[2] = 12.5 / c[1] + 12.0;
    let v3 = y[2] * x[0];
    c[2] = (3.535e-4 * x[0] + 0.5311) * x[0] + 0.08705 * v3;
    c[3] = 0.052 * x[0] + 78.0 + 2.377e-3 * v3;
    y[3] = c[2] / c[3];
    y[4] = 19.0 * y[3];
    let v1 = x[0] - y[3];
    c[4] = (0.1956 * v1 / x[1] + 0.04782) * v1 + 0.6376 * y[4] + 1.594 * y[3];
    c[5] = 100.0 * x[1];
    c[6] = v1 - y[4];
    c[7] = 0.95 - c[4] / c[5];
    y[5] = c[6] * c[7];
    let v2 = y[5] + y[4];
    y[6] = v1 - v2;
    c[8] = 0.995 * v2;
    y[7] = c[8] / y[1];
    y[8] = c[8] / 3.798e3;
    c[9] = y[7] - 0.0663 * y[7] / y[8] - 0.3153;
    y[9] = 96.82 / c[9] + 0.321 * y[1];
    y[10] = 1.29 * y[5] + 1.258 * y[4] + 2.29 * y[3] + 1.71 * y[6];
    y[11] = 1.71 * x[0] - 0.452 * y[4] + 0.58 * y[3];
    c[10] = 12.3 / 752.3;
    c[11] = 1.74125 * v3;
    c[12] = 0.995 * y[10] + 1.998e3;
    y[12] = c[10] * x[0] + c[11] / c[12];
    y[13] = c[12] - 1.75 * y[2];
    let v4 = y[9] + x[4];
    y[14] = 3.623e3 + 64.4 * x[1] + 58.4 * x[2] + 1.46312e5 / v4;
    c[13] = 0.995 * y[10] + 60.8 * x[1] + 48.0 * x[3] - 0.1121 * y[14] - 5.095e3;
    y[15] = y[13] / c[13];
    y[16] = 1.48e5 - 3.31e5 * y[15] + 40.0 * y[13] - 61.0 * y[15] * y[13];
    c[14] = 2.324e3 * y[10] - 2.874e7 * y[2];
    y[17] = 1.413e7 - 1.328e3 * y[10] - 531.0 * y[11] + c[14] / c[12];
    c[15] = y[13] / y[15] - y[13] / 0.52;
    c[16] = 1.104 - 0.72 * y[15];
    c[17] = v4;
    (y, c)
}

fn hs85_f(x: &[f64]) -> f64 {
    let (y, c) = hs85_yc(x);
    -(5.843e-7 * y[17]
        - 1.17e-4 * y[14]
        - 0.1365
        - 2.358e-5 * y[13]
        - 1.502e-6 * y[16]
        - 0.0321 * y[12]
        - 4.324e-3 * y[5]
        - 1e-4 * c[15] / c[16]
        - 37.48 * y[2] / c[12])
}

fn hs85_c(x: &[f64]) -> Vec<f64> {
    const A: [f64; 16] = [
        17.505, 11.275, 214.228, 7.458, 0.961, 1.612, 0.146, 107.99, 922.693, 926.832, 18.766,
        1.072163e3, 8.961448e3, 0.063, 7.108433e4, 2.802713e6,
    ];
    const B: [f64; 16] = [
        1.0536667e3,
        35.03,
        665.585,
        584.463,
        265.916,
        7.046,
        0.222,
        273.366,
        1.286105e3,
        1.444046e3,
        537.141,
        3.247039e3,
        2.6844086e4,
        0.386,
        1.4e5,
        1.2146108e7,
    ];
    let (y, c) = hs85_yc(x);
    let mut g = vec![1.5 * x[1] - x[2], y[1] - 213.1, 405.23 - y[1]];
    g.extend((0..16).map(|i| y[i + 2] - A[i]));
    g.extend((0..16).map(|i| B[i] - y[i + 2]));
    g.push(y[4] - 0.28 * y[5] / 0.72);
    g.push(21.0 - 3.496e3 * y[2] / c[12]);
    g.push(6.2212e4 / c[17] - 110.6 - y[1]);
    g
}

/// The data of HS 86 and HS 117 (Colville's first problem and its dual).
const COLVILLE_E: [f64; 5] = [-15.0, -27.0, -36.0, -18.0, -12.0];
const COLVILLE_D: [f64; 5] = [4.0, 8.0, 10.0, 6.0, 2.0];
const COLVILLE_C: [[f64; 5]; 5] = [
    [30.0, -20.0, -10.0, 32.0, -10.0],
    [-20.0, 39.0, -6.0, -31.0, 32.0],
    [-10.0, -6.0, 10.0, -6.0, -10.0],
    [32.0, -31.0, -6.0, 39.0, -20.0],
    [-10.0, 32.0, -10.0, -20.0, 30.0],
];
const COLVILLE_A: [[f64; 5]; 10] = [
    [-16.0, 2.0, 0.0, 1.0, 0.0],
    [0.0, -2.0, 0.0, 0.4, 2.0],
    [-3.5, 0.0, 2.0, 0.0, 0.0],
    [0.0, -2.0, 0.0, -4.0, -1.0],
    [0.0, -9.0, -2.0, 1.0, -2.8],
    [2.0, 0.0, -4.0, 0.0, 0.0],
    [-1.0, -1.0, -1.0, -1.0, -1.0],
    [-1.0, -2.0, -3.0, -2.0, -1.0],
    [1.0, 2.0, 3.0, 4.0, 5.0],
    [1.0, 1.0, 1.0, 1.0, 1.0],
];
const COLVILLE_B: [f64; 10] = [-40.0, -2.0, -0.25, -4.0, -4.0, -1.0, -40.0, -60.0, 5.0, 1.0];

fn quadratic_form(y: &[f64]) -> f64 {
    (0..5)
        .map(|i| (0..5).map(|j| COLVILLE_C[i][j] * y[i] * y[j]).sum::<f64>())
        .sum()
}

fn hs86_f(x: &[f64]) -> f64 {
    (0..5)
        .map(|i| COLVILLE_E[i] * x[i] + COLVILLE_D[i] * x[i].powi(3))
        .sum::<f64>()
        + quadratic_form(x)
}

fn hs86_c(x: &[f64]) -> Vec<f64> {
    (0..10)
        .map(|i| (0..5).map(|j| COLVILLE_A[i][j] * x[j]).sum::<f64>() - COLVILLE_B[i])
        .collect()
}

fn hs117_f(x: &[f64]) -> f64 {
    let z = &x[10..15];
    let t3: f64 = (0..10).map(|i| COLVILLE_B[i] * x[i]).sum();
    let t2: f64 = (0..5).map(|j| COLVILLE_D[j] * z[j].powi(3)).sum();
    -(t3 - quadratic_form(z) - 2.0 * t2)
}

fn hs117_c(x: &[f64]) -> Vec<f64> {
    let z = &x[10..15];
    (0..5)
        .map(|j| {
            let t4: f64 = (0..5).map(|i| COLVILLE_C[i][j] * z[i]).sum();
            let t5: f64 = (0..10).map(|i| COLVILLE_A[i][j] * x[i]).sum();
            2.0 * t4 + 3.0 * COLVILLE_D[j] * z[j] * z[j] + COLVILLE_E[j] - t5
        })
        .collect()
}

fn hs93_f(x: &[f64]) -> f64 {
    let v1 = x[0] + x[1] + x[2];
    let v2 = x[0] + 1.57 * x[1] + x[3];
    let v3 = x[0] * x[3];
    let v4 = x[2] * x[1];
    0.0204 * v3 * v1
        + 0.0187 * v4 * v2
        + 0.0607 * v3 * v1 * x[4] * x[4]
        + 0.0437 * v4 * v2 * x[5] * x[5]
}

fn hs93_c(x: &[f64]) -> Vec<f64> {
    vec![
        1e-3 * x.iter().product::<f64>() - 2.07,
        1.0 - 6.2e-4 * x[0] * x[3] * x[4] * x[4] * (x[0] + x[1] + x[2])
            - 5.8e-4 * x[1] * x[2] * x[5] * x[5] * (x[0] + 1.57 * x[1] + x[3]),
    ]
}

fn hs95_f(x: &[f64]) -> f64 {
    4.3 * x[0] + 31.8 * x[1] + 63.3 * x[2] + 15.8 * x[3] + 68.5 * x[4] + 4.7 * x[5]
}

/// HS 95–98 share their rows and differ in the right-hand sides b.
fn hs95_rows(x: &[f64], b: [f64; 4]) -> Vec<f64> {
    vec![
        17.1 * x[0] + 38.2 * x[1] + 204.2 * x[2] + 212.3 * x[3] + 623.4 * x[4] + 1.4955e3 * x[5]
            - 169.0 * x[0] * x[2]
            - 3.58e3 * x[2] * x[4]
            - 3.81e3 * x[3] * x[4]
            - 1.85e4 * x[3] * x[5]
            - 2.43e4 * x[4] * x[5]
            - b[0],
        17.9 * x[0] + 36.8 * x[1] + 113.9 * x[2] + 169.7 * x[3] + 337.8 * x[4] + 1.3852e3 * x[5]
            - 139.0 * x[0] * x[2]
            - 2.45e3 * x[3] * x[4]
            - 1.66e4 * x[3] * x[5]
            - 1.72e4 * x[4] * x[5]
            - b[1],
        -273.0 * x[1] - 70.0 * x[3] - 819.0 * x[4] + 2.6e4 * x[3] * x[4] - b[2],
        159.9 * x[0] - 311.0 * x[1] + 587.0 * x[3] + 391.0 * x[4] + 2.198e3 * x[5]
            - 1.4e4 * x[0] * x[5]
            - b[3],
    ]
}

/// HS 101–103 share their terms and differ in the exponent a of x7.
fn hs101_f_a(x: &[f64], a: f64) -> f64 {
    10.0 * x[0] * x[3].powi(2) * x[6].powf(a) / (x[1] * x[5].powi(3))
        + 15.0 * x[2] * x[3] / (x[0] * x[1].powi(2) * x[4] * x[6].sqrt())
        + 20.0 * x[1] * x[5] / (x[0].powi(2) * x[3] * x[4].powi(2))
        + 25.0 * x[0].powi(2) * x[1].powi(2) * x[4].sqrt() * x[6] / (x[2] * x[5].powi(2))
}

fn hs101_c_a(x: &[f64], a: f64) -> Vec<f64> {
    let f = hs101_f_a(x, a);
    let [x1, x2, x3, x4, x5, x6, x7] = [x[0], x[1], x[2], x[3], x[4], x[5], x[6]];
    vec![
        1.0 - 0.5 * x1.sqrt() * x7 / (x3 * x6 * x6)
            - 0.7 * x1.powi(3) * x2 * x6 * x7.sqrt() / (x3 * x3)
            - 0.2 * x3 * x6.powf(2.0 / 3.0) * x7.powf(0.25) / (x2 * x4.sqrt()),
        1.0 - 1.3 * x2 * x6 / (x1.sqrt() * x3 * x5)
            - 0.8 * x3 * x6 * x6 / (x4 * x5)
            - 3.1 * x2.sqrt() * x6.powf(1.0 / 3.0) / (x1 * x4 * x4 * x5),
        1.0 - 2.0 * x1 * x5 * x7.powf(1.0 / 3.0) / (x3.powf(1.5) * x6)
            - 0.1 * x2 * x5 / ((x3 * x7).sqrt() * x6)
            - x2 * x3.sqrt() * x5 / x1
            - 0.65 * x3 * x5 * x7 / (x2 * x2 * x6),
        1.0 - 0.2 * x2 * x5.sqrt() * x7.powf(1.0 / 3.0) / (x1 * x1 * x4)
            - 0.3 * x1.sqrt() * x2 * x2 * x3 * x4.powf(1.0 / 3.0) * x7.powf(0.25)
                / x5.powf(2.0 / 3.0)
            - 0.4 * x3 * x5 * x7.powf(0.75) / (x1.powi(3) * x2 * x2)
            - 0.5 * x4 * x7.sqrt() / (x3 * x3),
        f - 100.0,
        3e3 - f,
    ]
}

fn hs104_f(x: &[f64]) -> f64 {
    0.4 * (x[0].powf(0.67) / x[6].powf(0.67) + x[1].powf(0.67) / x[7].powf(0.67)) + 10.0
        - x[0]
        - x[1]
}

fn hs104_c(x: &[f64]) -> Vec<f64> {
    let a = 0.0588;
    let f = hs104_f(x);
    vec![
        -a * x[4] * x[6] - 0.1 * x[0] + 1.0,
        -a * x[5] * x[7] - 0.1 * x[0] - 0.1 * x[1] + 1.0,
        (-4.0 * x[2] - 2.0 * x[2].powf(-0.71)) / x[4] - a * x[2].powf(-1.3) * x[6] + 1.0,
        (-4.0 * x[3] - 2.0 * x[3].powf(-0.71)) / x[5] - a * x[3].powf(-1.3) * x[7] + 1.0,
        f - 1.0,
        4.2 - f,
    ]
}

fn hs106_c(x: &[f64]) -> Vec<f64> {
    vec![
        1.0 - 2.5e-3 * (x[3] + x[5]),
        1.0 - 2.5e-3 * (x[4] + x[6] - x[3]),
        1.0 - 0.01 * (x[7] - x[4]),
        -833.33252 * x[3] - 100.0 * x[0] + 8.3333333e4 + x[0] * x[5],
        -1.25e3 * x[4] - x[1] * x[3] + 1.25e3 * x[3] + x[1] * x[6],
        -1.25e6 - x[2] * x[4] + 2.5e3 * x[4] + x[2] * x[7],
    ]
}

fn hs108_c(x: &[f64]) -> Vec<f64> {
    vec![
        1.0 - x[2] * x[2] - x[3] * x[3],
        1.0 - x[8] * x[8],
        1.0 - x[4] * x[4] - x[5] * x[5],
        1.0 - x[0] * x[0] - (x[1] - x[8]).powi(2),
        1.0 - (x[0] - x[4]).powi(2) - (x[1] - x[5]).powi(2),
        1.0 - (x[0] - x[6]).powi(2) - (x[1] - x[7]).powi(2),
        1.0 - (x[2] - x[4]).powi(2) - (x[3] - x[5]).powi(2),
        1.0 - (x[2] - x[6]).powi(2) - (x[3] - x[7]).powi(2),
        1.0 - x[6] * x[6] - (x[7] - x[8]).powi(2),
        x[0] * x[3] - x[1] * x[2],
        x[2] * x[8],
        -x[4] * x[8],
        x[4] * x[7] - x[5] * x[6],
    ]
}

fn hs116_c(x: &[f64]) -> Vec<f64> {
    vec![
        x[2] - x[1],
        x[1] - x[0],
        1.0 - 2e-3 * (x[6] - x[7]),
        x[10] + x[11] + x[12] - 50.0,
        250.0 - x[10] - x[11] - x[12],
        x[12] - 1.262626 * x[9] + 1.231059 * x[2] * x[9],
        x[4] - 0.03475 * x[1] - 0.975 * x[1] * x[4] + 9.75e-3 * x[1] * x[1],
        x[5] - 0.03475 * x[2] - 0.975 * x[2] * x[5] + 9.75e-3 * x[2] * x[2],
        x[4] * x[6] - x[0] * x[7] - x[3] * x[6] + x[3] * x[7],
        -2e-3 * (x[1] * x[8] + x[4] * x[7] - x[0] * x[7] - x[5] * x[8]) - x[5] - x[4] + 1.0,
        x[1] * x[8] - x[2] * x[9] - x[5] * x[8] - 500.0 * (x[1] - x[5]) + x[1] * x[9],
        x[1] - 0.9 - 2e-3 * (x[1] * x[9] - x[2] * x[9]),
        x[3] - 0.03475 * x[0] - 0.975 * x[0] * x[3] + 9.75e-3 * x[0] * x[0],
        x[10] - 1.262626 * x[7] + 1.231059 * x[0] * x[7],
        x[11] - 1.262626 * x[8] + 1.231059 * x[1] * x[8],
    ]
}

fn hs118_f(x: &[f64]) -> f64 {
    (0..5)
        .map(|m| {
            let (a, b, c) = (x[3 * m], x[3 * m + 1], x[3 * m + 2]);
            2.3 * a + 1e-4 * a * a + 1.7 * b + 1e-4 * b * b + 2.2 * c + 1.5e-4 * c * c
        })
        .sum()
}

fn hs118_c(x: &[f64]) -> Vec<f64> {
    let mut g = Vec::with_capacity(29);
    // Ramp limits between consecutive periods (1-based X(3i+k) - X(3i+k-3)).
    for k in 0..3 {
        for i in 1..=4 {
            g.push(x[3 * i + k] - x[3 * i + k - 3] + 7.0);
        }
    }
    for (k, down) in [(0, 6.0), (1, 7.0), (2, 6.0)] {
        for i in 1..=4 {
            g.push(x[3 * i + k - 3] - x[3 * i + k] + down);
        }
    }
    for (m, demand) in [60.0, 50.0, 70.0, 85.0, 100.0].iter().enumerate() {
        g.push(x[3 * m] + x[3 * m + 1] + x[3 * m + 2] - demand);
    }
    g
}

/// HS 88–92 (time-optimal heating of a slab): μ_j, j = 1…30, are the roots
/// of μ tan μ = 1 in ((j-1)π, (j-1)π + π/2), found by Newton's method on
/// μ - (j-1)π - atan(1/μ) to full precision (the published code stops at a
/// residual of 1e-5, which leaves the constraint at its published solution
/// -2.9e-8 instead of ~0).
fn heating_roots() -> &'static [f64; 30] {
    static ROOTS: std::sync::OnceLock<[f64; 30]> = std::sync::OnceLock::new();
    ROOTS.get_or_init(|| {
        std::array::from_fn(|j| {
            let p = std::f64::consts::PI * j as f64;
            let mut mu = p + 1.0;
            for _ in 0..60 {
                let h = mu - p - (1.0 / mu).atan();
                mu -= h / (1.0 + 1.0 / (1.0 + mu * mu));
            }
            mu
        })
    })
}

fn heating_row(x: &[f64]) -> Vec<f64> {
    let n = x.len();
    // t[k] = Σ_{i ≥ k} x_i².
    let mut t = vec![0.0; n];
    t[n - 1] = x[n - 1] * x[n - 1];
    for k in (0..n - 1).rev() {
        t[k] = t[k + 1] + x[k] * x[k];
    }
    let sign = |k: usize| if k.is_multiple_of(2) { 1.0 } else { -1.0 };
    let decay = |a: f64| if a > -100.0 { a.exp() } else { 0.0 };
    let h: f64 = heating_roots()
        .iter()
        .map(|&mu| {
            let (s, c) = mu.sin_cos();
            let a = 2.0 * s / (mu + s * c);
            let dcos = (s / mu - c) / (mu * mu);
            let mu2 = mu * mu;
            let mut rho = sign(n);
            for i in 1..n {
                rho += sign(n - i) * 2.0 * decay(-mu2 * t[n - i]);
            }
            rho = (rho + decay(-mu2 * t[0])) / (-mu2);
            mu2 * a * rho * (mu * s * rho - 2.0 * dcos)
        })
        .sum();
    vec![1e-4 - h - 2.0 / 15.0]
}

fn heating(number: u32, n: usize, fstar: f64, source: &'static str) -> Hs {
    let x0: Vec<f64> = (0..n)
        .map(|i| if i % 2 == 0 { 0.5 } else { -0.5 })
        .collect();
    Hs::new(
        number,
        &x0,
        &vec![-INF; n],
        &vec![INF; n],
        |x| x.iter().map(|v| v * v).sum(),
        heating_row,
        fstar,
        source,
    )
}

fn more_problems() -> Vec<Hs> {
    vec![
        heating(88, 2, 1.36265680997, "HS 88: f* = 1.36265680997"),
        heating(89, 3, 1.36265680508, "HS 89: f* = 1.36265680508"),
        heating(90, 4, 1.36265681317, "HS 90: f* = 1.36265681317"),
        heating(91, 5, 1.36265680910, "HS 91: f* = 1.36265680910"),
        heating(92, 6, 1.36265681213, "HS 92: f* = 1.36265681213"),
        Hs::new(
            17,
            &[-2.0, 1.0],
            &[-2.0, -INF],
            &[0.5, 1.0],
            rosenbrock,
            |x| vec![x[1] * x[1] - x[0], x[0] * x[0] - x[1]],
            1.0,
            "HS 17: f* = 1 at (0, 0)",
        ),
        Hs::new(
            20,
            &[0.1, 1.0],
            &[-0.5, -INF],
            &[0.5, INF],
            rosenbrock,
            |x| {
                vec![
                    x[1] * x[1] + x[0],
                    x[0] * x[0] + x[1],
                    x[0] * x[0] + x[1] * x[1] - 1.0,
                ]
            },
            81.5 - 25.0 * 3f64.sqrt(),
            "HS 20: f* = 81.5 - 25√3 at (1/2, √3/2)",
        ),
        Hs::new(
            44,
            &[0.0; 4],
            &[0.0; 4],
            &[INF; 4],
            |x| x[0] - x[1] - x[2] - x[0] * x[2] + x[0] * x[3] + x[1] * x[2] - x[1] * x[3],
            |x| {
                vec![
                    8.0 - x[0] - 2.0 * x[1],
                    12.0 - 4.0 * x[0] - x[1],
                    12.0 - 3.0 * x[0] - 4.0 * x[1],
                    8.0 - 2.0 * x[2] - x[3],
                    8.0 - x[2] - 2.0 * x[3],
                    5.0 - x[2] - x[3],
                ]
            },
            -15.0,
            "HS 44: f* = -15 at (0, 3, 0, 4)",
        ),
        Hs::new(
            57,
            &[0.42, 5.0],
            &[0.4, -4.0],
            &[INF; 2],
            hs57,
            |x| vec![-x[0] * x[1] + 0.49 * x[1] - 0.09],
            0.0284596697213,
            "HS 57: f* = 0.0284596697213",
        ),
        Hs::new(
            58,
            &[-2.0, 1.0],
            &[-2.0, -INF],
            &[0.5, INF],
            rosenbrock,
            |x| {
                vec![
                    x[1] * x[1] - x[0],
                    x[0] * x[0] - x[1],
                    x[0] * x[0] + x[1] * x[1] - 1.0,
                ]
            },
            // Both x1² = x2 and x1² + x2² = 1 bind: x2 = (√5 - 1)/2, x1 = -√x2
            // (the published 3.19033354957 is 1.0e-6 low).
            (1.0 + ((5f64.sqrt() - 1.0) / 2.0).sqrt()).powi(2),
            "HS 58: f* = (1 + √((√5 - 1)/2))² = 3.1903367446 at (-√x2, (√5 - 1)/2)",
        ),
        Hs::new(
            64,
            &[1.0; 3],
            &[1e-5; 3],
            &[INF; 3],
            |x| 5.0 * x[0] + 5e4 / x[0] + 20.0 * x[1] + 7.2e4 / x[1] + 10.0 * x[2] + 1.44e5 / x[2],
            |x| vec![1.0 - 4.0 / x[0] - 32.0 / x[1] - 120.0 / x[2]],
            6299.84242821,
            "HS 64: f* = 6299.84242821",
        ),
        Hs::new(
            67,
            &[1745.0, 12000.0, 110.0],
            &[1e-5; 3],
            &[2e3, 1.6e4, 120.0],
            hs67_f,
            hs67_c,
            -1162.03650728,
            "HS 67: f* = -1162.03650728",
        ),
        Hs::new(
            70,
            &[2.0, 4.0, 0.04, 2.0],
            &[1e-5; 4],
            &[100.0, 100.0, 1.0, 100.0],
            hs70,
            |x| vec![x[2] + (1.0 - x[2]) * x[3]],
            0.00749846356143,
            "HS 70: f* = 0.00749846356143",
        ),
        Hs::new(
            72,
            &[1.0; 4],
            &[1e-3; 4],
            &[4e5, 3e5, 2e5, 1e5],
            |x| 1.0 + x.iter().sum::<f64>(),
            |x| {
                vec![
                    -4.0 / x[0] - 2.25 / x[1] - 1.0 / x[2] - 0.25 / x[3] + 0.0401,
                    -0.16 / x[0] - 0.36 / x[1] - 0.64 * (1.0 / x[2] + 1.0 / x[3]) + 0.010085,
                ]
            },
            727.679376021,
            "HS 72: f* = 727.679376021",
        ),
        Hs::new(
            83,
            &[78.0, 33.0, 27.0, 27.0, 27.0],
            &[78.0, 33.0, 27.0, 27.0, 27.0],
            &[102.0, 45.0, 45.0, 45.0, 45.0],
            |x| 5.3578547 * x[2] * x[2] + 0.8356891 * x[0] * x[4] + 37.293239 * x[0] - 4.0792141e4,
            |x| {
                let v1 = 85.334407 + 5.6858e-3 * x[1] * x[4] + 6.262e-4 * x[0] * x[3]
                    - 2.2053e-3 * x[2] * x[4];
                let v2 = 80.51249
                    + 7.1317e-3 * x[1] * x[4]
                    + 2.9955e-3 * x[0] * x[1]
                    + 2.1813e-3 * x[2] * x[2]
                    - 90.0;
                let v3 = 9.300961
                    + 4.7026e-3 * x[2] * x[4]
                    + 1.2547e-3 * x[0] * x[2]
                    + 1.9085e-3 * x[2] * x[3]
                    - 20.0;
                vec![v1, v2, v3, 92.0 - v1, 20.0 - v2, 5.0 - v3]
            },
            -30665.5386717,
            "HS 83 (Colville 3): f* = -30665.5386717",
        ),
        Hs::new(
            84,
            &[2.52, 2.0, 37.5, 9.25, 6.8],
            &[0.0, 1.2, 20.0, 9.0, 6.5],
            &[1e3, 2.4, 60.0, 9.3, 7.0],
            hs84_f,
            hs84_c,
            -5280335.13306,
            "HS 84: f* = -5280335.13306",
        ),
        Hs::new(
            85,
            &[900.0, 80.0, 115.0, 267.0, 27.0],
            &[704.4148, 68.6, 0.0, 193.0, 25.0],
            &[906.3855, 288.88, 134.75, 287.0966, 84.1988],
            hs85_f,
            hs85_c,
            -1.9051553,
            "HS 85: f* = -1.9051553",
        ),
        Hs::new(
            86,
            &[0.0, 0.0, 0.0, 0.0, 1.0],
            &[0.0; 5],
            &[INF; 5],
            hs86_f,
            hs86_c,
            -32.3486789716,
            "HS 86 (Colville 1): f* = -32.3486789716",
        ),
        Hs::new(
            93,
            &[5.54, 4.4, 12.02, 11.82, 0.702, 0.852],
            &[0.0; 6],
            &[INF; 6],
            hs93_f,
            hs93_c,
            135.075961229,
            "HS 93: f* = 135.075961229",
        ),
        Hs::new(
            95,
            &[0.0; 6],
            &[0.0; 6],
            &[0.31, 0.046, 0.068, 0.042, 0.028, 0.0134],
            hs95_f,
            |x| hs95_rows(x, [4.97, -1.88, -29.08, -78.02]),
            0.0156195144282,
            "HS 95: f* = 0.0156195144282",
        ),
        Hs::new(
            96,
            &[0.0; 6],
            &[0.0; 6],
            &[0.31, 0.046, 0.068, 0.042, 0.028, 0.0134],
            hs95_f,
            |x| hs95_rows(x, [4.97, -1.88, -69.08, -118.02]),
            0.0156195134384,
            "HS 96: f* = 0.0156195134384",
        ),
        Hs::new(
            97,
            &[0.0; 6],
            &[0.0; 6],
            &[0.31, 0.046, 0.068, 0.042, 0.028, 0.0134],
            hs95_f,
            |x| hs95_rows(x, [32.97, 25.12, -29.08, -78.02]),
            3.1358089,
            "HS 97: f* = 3.1358089",
        ),
        Hs::new(
            98,
            &[0.0; 6],
            &[0.0; 6],
            &[0.31, 0.046, 0.068, 0.042, 0.028, 0.0134],
            hs95_f,
            |x| hs95_rows(x, [32.97, 25.12, -124.08, -173.02]),
            3.1358089,
            "HS 98: f* = 3.1358089",
        ),
        Hs::new(
            101,
            &[6.0; 7],
            &[0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.01],
            &[10.0; 7],
            |x| hs101_f_a(x, -0.25),
            |x| hs101_c_a(x, -0.25),
            1809.76476556,
            "HS 101: f* = 1809.76476556",
        ),
        Hs::new(
            102,
            &[6.0; 7],
            &[0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.01],
            &[10.0; 7],
            |x| hs101_f_a(x, 0.125),
            |x| hs101_c_a(x, 0.125),
            911.880571336,
            "HS 102: f* = 911.880571336",
        ),
        Hs::new(
            103,
            &[6.0; 7],
            &[0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 0.01],
            &[10.0; 7],
            |x| hs101_f_a(x, 0.5),
            |x| hs101_c_a(x, 0.5),
            543.667958424,
            "HS 103: f* = 543.667958424",
        ),
        Hs::new(
            104,
            &[6.0, 3.0, 0.4, 0.2, 6.0, 6.0, 1.0, 0.5],
            &[0.1; 8],
            &[10.0; 8],
            hs104_f,
            hs104_c,
            3.95116343955,
            "HS 104: f* = 3.95116343955",
        ),
        Hs::new(
            106,
            &[5000.0, 5000.0, 5000.0, 200.0, 350.0, 150.0, 225.0, 425.0],
            &[100.0, 1000.0, 1000.0, 10.0, 10.0, 10.0, 10.0, 10.0],
            &[1e4, 1e4, 1e4, 1e3, 1e3, 1e3, 1e3, 1e3],
            |x| x[0] + x[1] + x[2],
            hs106_c,
            7049.2480,
            "HS 106: f* = 7049.2480",
        ),
        Hs::new(
            108,
            &[1.0; 9],
            &[-INF, -INF, -INF, -INF, -INF, -INF, -INF, -INF, 0.0],
            &[INF; 9],
            |x| {
                -0.5 * (x[0] * x[3] - x[1] * x[2] + x[2] * x[8] - x[4] * x[8] + x[4] * x[7]
                    - x[5] * x[6])
            },
            hs108_c,
            -0.866025403841,
            "HS 108: f* = -√3/2 = -0.866025403841",
        ),
        Hs::new(
            116,
            &[
                0.5, 0.8, 0.9, 0.1, 0.14, 0.5, 489.0, 80.0, 650.0, 450.0, 150.0, 150.0, 150.0,
            ],
            &[
                0.1, 0.1, 0.1, 1e-4, 0.1, 0.1, 0.1, 0.1, 500.0, 0.1, 1.0, 1e-4, 1e-4,
            ],
            &[
                1.0, 1.0, 1.0, 0.1, 0.9, 0.9, 1e3, 1e3, 1e3, 500.0, 150.0, 150.0, 150.0,
            ],
            |x| x[10] + x[11] + x[12],
            hs116_c,
            // The book's FEX, 97.5884089805, is 9.2e-6 above a point feasible
            // to 1e-13 (x7 = 574.07757, not 574.08031); later collections
            // list this lower value.
            97.5875095537,
            "HS 116: f* = 97.5875095537 (FEX 97.5884089805 is 9.2e-6 above)",
        ),
        Hs::new(
            117,
            &{
                let mut x = [1e-3; 15];
                x[6] = 60.0;
                x
            },
            &[0.0; 15],
            &[INF; 15],
            hs117_f,
            hs117_c,
            32.3486789791,
            "HS 117 (Colville 2): f* = 32.3486789791",
        ),
        Hs::new(
            118,
            &[
                20.0, 55.0, 15.0, 20.0, 60.0, 20.0, 20.0, 60.0, 20.0, 20.0, 60.0, 20.0, 20.0, 60.0,
                20.0,
            ],
            &[
                8.0, 43.0, 3.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
            ],
            &[
                21.0, 57.0, 16.0, 90.0, 120.0, 60.0, 90.0, 120.0, 60.0, 90.0, 120.0, 60.0, 90.0,
                120.0, 60.0,
            ],
            hs118_f,
            hs118_c,
            664.820449993,
            "HS 118: f* = 664.820449993",
        ),
    ]
}
