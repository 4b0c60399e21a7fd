"""Adhesive wear of rough micro-contacts (MEMS gears and hinges, NEMS switches,
storage heads): the rough-surface adhesion model, design optimisation, Pareto
fronts of wear against adhesion, and design-space sweeps.

Every function returns what the ``wearopt`` command line prints with
``--format json`` (same keys, same values, SI units), as plain Python objects:

>>> import wearopt
>>> r = wearopt.evaluate("problems/micro-gear.toml")
>>> r["status"], r["wear_rate"] > 0
('ok', True)

A ``problem`` is a path to a problem file (TOML) or a dict in the same schema::

    wearopt.evaluate({
        "contact": {"load": "10 uN", "nominal_area": "100 um^2",
                    "sliding_distance": "1 m", "wear_coefficient": 1e-4},
        "bodies": {"a": {"material": "polysilicon"}, "b": {"material": "polysilicon"}},
        "interface": {"work_of_adhesion": "0.1 J/m^2"},
        "roughness": {"sigma": "5 nm", "asperity_radius": "1 um",
                      "asperity_density": "10 um^-2"},
    })

Bad input raises ``ValueError`` with the message the command line prints, its
options named as this package's keyword arguments (``points=1: must lie in
2..=200`` where the command line says ``--points 1: …``); outcomes (``separated``, ``infeasible``, …) are statuses in the result. The
computations release the GIL, so calls from several threads run in parallel.
"""

from __future__ import annotations

import json as _json
import numbers as _numbers
import os as _os
from typing import Any, Dict, Iterable, Optional, Tuple, Union

import numpy as _np

from . import _wearopt


def _is_int(value: Any) -> bool:
    """An integer, Python's or NumPy's (``np.int64(10)``), not a bool."""
    return isinstance(value, _numbers.Integral) and not isinstance(value, (bool, _np.bool_))


def _is_number(value: Any) -> bool:
    """A real number, Python's or NumPy's (``np.float32(1)``), not a bool."""
    return isinstance(value, _numbers.Real) and not isinstance(value, (bool, _np.bool_))

__all__ = [
    "evaluate",
    "optimize",
    "pareto",
    "humidity",
    "uncertainty",
    "asperity",
    "roughness",
    "contact",
    "curve",
    "sweep",
    "merge",
    "fit_adhesion",
    "fit_wear",
    "figures",
    "accuracy",
]
__version__ = "0.1.0"

Problem = Union[str, "_os.PathLike[str]", Dict[str, Any]]


def _source(problem: Problem) -> Tuple[str, bool]:
    """(text, is_path): a path as given, or a dict as JSON text."""
    if isinstance(problem, dict):
        try:
            return _json.dumps(problem, allow_nan=False), False
        except (TypeError, ValueError) as e:
            raise ValueError(
                f"<problem dict>: not a problem-file dict ({e}); values must be "
                "strings, finite numbers, booleans, lists or dicts"
            ) from None
    if isinstance(problem, (str, _os.PathLike)):
        return _os.fspath(problem), True
    raise TypeError(
        f"problem must be a path (str or os.PathLike) or a dict, not {type(problem).__name__}"
    )


def evaluate(problem: Problem) -> Dict[str, Any]:
    """Evaluates one scene: separation, real area, contacts, pull-off, wear,
    sensitivities (the JSON of ``wearopt eval FILE --format json``).

    >>> r = wearopt.evaluate("problems/gold-switch.toml")
    >>> sorted(k for k in r if k.endswith("_index"))[:2]
    ['elastic_adhesion_index', 'plastic_adhesion_index']
    """
    return _json.loads(_wearopt.evaluate_json(*_source(problem)))


def optimize(problem: Problem) -> Dict[str, Any]:
    """Searches the study's ``[design]`` for the least wear under its
    constraints (the JSON of ``wearopt optimize FILE --format json``; a ranking
    of the materials when ``[design]`` lists ``materials``).

    >>> r = wearopt.optimize("problems/micro-gear-study.toml")
    >>> r["status"]
    'optimal'
    >>> ranking = wearopt.optimize("problems/materials-study.toml")["ranking"]
    >>> ranking[0]["rank"], ranking[0]["material"] in {"polysilicon", "silicon carbide", "diamond-like carbon"}
    (1, True)
    """
    return _json.loads(_wearopt.optimize_json(*_source(problem)))


def pareto(
    problem: Problem,
    points: Optional[int] = None,
    adhesion: Optional[str] = None,
    direction: Optional[str] = None,
) -> Dict[str, Any]:
    """The wear–adhesion trade-off of a study (the JSON of ``wearopt pareto
    FILE [--points N] [--adhesion M] [--direction D] --format json``): the
    ``[pareto]`` section's front with these in place of its own, or without a
    section, these and the defaults (``pull_off_force``, 15 points, ``low``).

    The points asked for describe the front; where the curve turns (the
    least wear holds past some adhesion), the dominated points past the turn
    (``front["turn"]``) are listed after the front's:

    >>> front = wearopt.pareto("problems/micro-gear.toml", points=5)
    >>> front["front"], front["turn"], len(front["points"])
    ([0, 1, 2, 3, 4], 4, 7)

    A robust study (a statistic objective or chance constraints) returns its
    robust front instead (docs/robust-design.md): against the probability of
    an event (``front_measure`` ``"probability"``, ``[pareto] event``) or
    against the adhesion measure, one robust optimum per level
    (``front_measure`` ``"adhesion"``).
    """
    if points is not None and not _is_int(points):
        raise TypeError(f"points must be an int or None, not {type(points).__name__}")
    points = None if points is None else int(points)
    if points is not None and points < 0:
        raise ValueError(f"points={points}: must lie in 2..=200")
    for name, value in (("adhesion", adhesion), ("direction", direction)):
        if value is not None and not isinstance(value, str):
            raise TypeError(f"{name} must be a str or None, not {type(value).__name__}")
    return _json.loads(_wearopt.pareto_json(*_source(problem), points, adhesion, direction))


def humidity(problem: Problem, from_: Any, to: Any, points: int) -> Dict[str, Any]:
    """The scene across relative humidity: separation, capillary load, pull-off
    force, apparent work of adhesion, wet fraction and wear rate at ``points``
    evenly spaced humidities from ``from_`` to ``to``, and the threshold humidity
    where the apparent work of adhesion reaches ten times its dry value (the JSON
    of ``wearopt humidity FILE --from RH0 --to RH1 --points N --format json``;
    ``from`` is a Python keyword, hence ``from_``). A humidity is a fraction
    (``0.5``) or a percentage string (``"50 %"``), as in a problem file.

    >>> r = wearopt.humidity("problems/micro-gear-humid.toml", 0.0, 0.9, 4)
    >>> [round(p["relative_humidity"], 2) for p in r["points"]]
    [0.0, 0.3, 0.6, 0.9]
    """
    given = []
    for name, value in (("from_", from_), ("to", to)):
        if isinstance(value, str):
            given.append(value)
        elif _is_number(value):
            x = float(value)
            # As the command line writes a number: 1, not 1.0.
            given.append(str(int(x)) if x.is_integer() and abs(x) < 1e15 else repr(x))
        else:
            raise TypeError(
                f"{name} must be a number (a relative humidity in [0, 1)) or a percentage string such as \"50 %\", not {type(value).__name__}"
            )
    if not _is_int(points):
        raise TypeError(f"points must be an int, not {type(points).__name__}")
    points = int(points)
    if points < 0:
        raise ValueError(f"points={points}: must lie in 2..=100000")
    return _json.loads(_wearopt.humidity_json(*_source(problem), given[0], given[1], points))


def uncertainty(
    problem: Problem,
    method: str = "sobol",
    samples: Optional[int] = None,
    seed: Optional[int] = None,
    shard: Optional[Tuple[int, int]] = None,
) -> Dict[str, Any]:
    """The scene under the scatter of its ``[uncertainty]`` inputs (the JSON of
    ``wearopt uncertainty FILE --method M [--samples N] [--seed S] --format json``):
    ``method`` is ``"sobol"`` (indices with 95 % intervals), ``"morris"``,
    ``"sampling"`` (percentiles with intervals, the empirical CDF as the numpy
    array ``cdf``, life B1/B10/B50) or ``"reliability"`` (the probability of each
    event with its interval, β, FORM, SORM, design points). Interval pairs come
    back as numpy arrays.

    ``shard=(i, n)`` evaluates the i-th of n parts of the study's samples
    (``wearopt uncertainty FILE --shard I/N``) and returns the part: a plain,
    JSON-serialisable dict (marked ``"wearopt": "uncertainty part"``, with the
    fingerprint, the range of samples it holds, the problem's text and the
    raw values) that :func:`merge` joins with the other parts into the
    document of the unsharded run. Not with ``"reliability"`` (sequential).

    >>> r = wearopt.uncertainty("problems/micro-gear-scatter.toml", "sampling", samples=256)
    >>> r["method"], r["samples"], [o["name"] for o in r["outputs"]]
    ('sampling', 256, ['wear_rate', 'pull_off_force', 'life_cycles'])
    >>> parts = [wearopt.uncertainty("problems/micro-gear-scatter.toml", "sampling",
    ...                              samples=64, shard=(i, 2)) for i in range(2)]
    >>> parts[1]["range"], wearopt.merge(parts)["samples"]
    ([32, 64], 64)
    """
    if not isinstance(method, str):
        raise TypeError(f"method must be a str, not {type(method).__name__}")
    for name, value in (("samples", samples), ("seed", seed)):
        if value is None:
            continue
        if isinstance(value, bool) or not isinstance(value, (int, _np.integer)):
            raise TypeError(f"{name} must be an int, not {type(value).__name__}")
        if value < 0:
            raise ValueError(f"{name}={value}: must be >= 0")
    if shard is not None:
        i, n = _shard(shard)
        return _json.loads(
            _wearopt.uncertainty_part_json(
                *_source(problem),
                method,
                None if samples is None else int(samples),
                None if seed is None else int(seed),
                i,
                n,
            )
        )
    doc = _json.loads(
        _wearopt.uncertainty_json(
            *_source(problem),
            method,
            None if samples is None else int(samples),
            None if seed is None else int(seed),
        )
    )
    return _arrays(doc)


def _shard(shard: Any) -> Tuple[int, int]:
    """``shard=(i, n)`` as two ints >= 0 (the range 0 <= i < n is checked in Rust)."""
    try:
        i, n = shard
    except (TypeError, ValueError):
        raise TypeError(f"shard must be a pair (i, n), not {shard!r}") from None
    for name, v in (("shard index", i), ("shard count", n)):
        if isinstance(v, bool) or not isinstance(v, (int, _np.integer)):
            raise TypeError(f"{name} must be an int, not {type(v).__name__}")
        if v < 0:
            raise ValueError(f"{name} {v}: must be >= 0")
    return int(i), int(n)


def _arrays(value: Any) -> Any:
    """Lists of numbers (intervals, the CDF) as numpy arrays, recursively."""
    if isinstance(value, dict):
        return {k: _arrays(v) for k, v in value.items()}
    if isinstance(value, list):
        if value and all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in value):
            return _np.asarray(value, dtype=float)
        return [_arrays(v) for v in value]
    return value


def asperity(
    tabor: Optional[float],
    from_: float,
    to: float,
    points: int,
    adhesion_model: str = "lennard_jones",
    *,
    radius: Any = None,
    work_of_adhesion: Any = None,
    modulus: Any = None,
    interatomic_distance: Any = None,
    fast: Optional[bool] = None,
) -> Dict[str, Any]:
    """One asperity's load against its interference in Maugis units: the
    self-consistent Lennard-Jones sphere at Tabor parameter ``tabor`` (or
    ``"jkr"``, ``"dmt"``), ``points`` evenly spaced interferences from ``from_``
    to ``to``, one row per branch (approach, unstable, contact), the pull-off and
    the jumps (the JSON of ``wearopt asperity --tabor MU --from D0 --to D1
    --points N --format json``).

    Instead of ``tabor`` (then ``None``), the sphere in SI: ``radius``,
    ``work_of_adhesion``, ``modulus`` (the composite E*) and
    ``interatomic_distance``, each a string with its unit or a number in SI
    (read only where plausible); μ follows, and each point gains ``load_n``,
    ``interference_m`` and ``contact_radius_m``. The Lennard-Jones rows are
    converged up to μ = 5 (``rows_accuracy``: ``"converged"``) and on the
    trace's mesh above (``"fast"``: converging them there takes minutes);
    ``fast=True`` or ``fast=False`` asks for one or the other at any μ.

    >>> c = wearopt.asperity(1.0, -1.0, 0.0, 3, fast=True)
    >>> round(c["pull_off"]["load"], 2), c["jump_in"] is not None
    (-1.67, True)
    """
    if tabor is not None and not _is_number(tabor):
        raise TypeError(f"tabor must be a number or None, not {type(tabor).__name__}")
    for name, value in (("from_", from_), ("to", to)):
        if not _is_number(value):
            raise TypeError(f"{name} must be a number, not {type(value).__name__}")
    if not _is_int(points):
        raise TypeError(f"points must be an int, not {type(points).__name__}")
    points = int(points)
    if points < 0:
        raise ValueError(f"points={points}: must lie in 2..=10000")
    if not isinstance(adhesion_model, str):
        raise TypeError(f"adhesion_model must be a str, not {type(adhesion_model).__name__}")
    if fast is not None and not isinstance(fast, bool):
        raise TypeError(f"fast must be a bool or None, not {type(fast).__name__}")
    return _json.loads(
        _wearopt.asperity_json(
            None if tabor is None else float(tabor),
            float(from_),
            float(to),
            points,
            adhesion_model,
            _quantity("radius", radius, "metres"),
            _quantity("work_of_adhesion", work_of_adhesion, "J/m²"),
            _quantity("modulus", modulus, "pascals"),
            _quantity("interatomic_distance", interatomic_distance, "metres"),
            fast,
        )
    )


def _quantity(name: str, value: Any, si_unit: str = "SI units") -> Optional[str]:
    """A quantity as the command line reads it: a string with a unit, or a number in SI."""
    if value is None or isinstance(value, str):
        return value
    if _is_number(value):
        return repr(float(value))
    raise TypeError(f"{name} must be a string with a unit or a number in {si_unit}, not {type(value).__name__}")


def _length(value: Any) -> Optional[str]:
    """A length as the command line reads it: a string with a unit, or metres."""
    return _quantity("a length", value, "metres")


def roughness(
    path: Any,
    cutoff: Any = None,
    level: str = "plane",
    pixel_size: Any = None,
    height_unit: Any = None,
    decimal_comma: bool = False,
) -> Dict[str, Any]:
    """σ, R and N of a measured surface (Gwyddion .gsf, ISO 25178-72 .x3p,
    NumPy .npy, ASCII matrix): the JSON of ``wearopt roughness FILE
    [--cutoff L] [--level none|plane|quadratic] [--pixel-size L]
    [--height-unit U] --format json``. Lengths are strings with units
    ("100 nm") or numbers in metres; ``height_unit`` is a unit ("nm") or a
    scale ("1e-9"). ``decimal_comma=True`` reads an ASCII matrix written with
    decimal commas ("1,25"), which is refused without it.

    ``path`` may also be the heights themselves: a 2-D array (rows along y,
    NaN where a point is missing) in metres, or in ``height_unit``; then
    ``pixel_size`` is required (square pixels).

    >>> r = wearopt.roughness("problems/scans/self-affine.gsf", cutoff="100 nm")
    >>> r["summit_sigma"] > 0 and r["summit_radius"] > 0 and r["summit_density"] > 0
    True
    >>> import numpy as np
    >>> z = np.load("problems/scans/self-affine-nm.npy")
    >>> a = wearopt.roughness(z, pixel_size="20 nm", height_unit="nm")
    >>> a["summit_sigma"] == wearopt.roughness("problems/scans/self-affine-nm.npy",
    ...                                        pixel_size="20 nm", height_unit="nm")["summit_sigma"]
    True
    """
    if height_unit is not None and not isinstance(height_unit, str):
        height_unit = repr(float(height_unit))
    if isinstance(path, (str, _os.PathLike)):
        return _json.loads(
            _wearopt.roughness_json(
                _os.fspath(path), _length(cutoff), level, _length(pixel_size), height_unit,
                bool(decimal_comma),
            )
        )
    heights = _float_array("heights", path)
    if heights.ndim == 1:
        heights = heights[None, :]
    if heights.ndim != 2:
        raise ValueError(f"heights: a 2-D array (rows along y) is needed, not {heights.ndim}-D")
    if pixel_size is None:
        raise ValueError('pixel_size=None: heights in an array carry no pixel size; give one, e.g. "10 nm"')
    return _json.loads(
        _wearopt.roughness_array_json(
            _np.ascontiguousarray(heights, dtype=_np.float64),
            _length(pixel_size),
            _length(cutoff),
            level,
            height_unit,
        )
    )


def contact(
    heights: Any,
    pixel_size: Any = None,
    modulus: Any = None,
    pressures: Any = None,
    hardness: Any = None,
    level: str = "plane",
    height_unit: Any = None,
    tolerance: float = 1e-10,
    fields: bool = False,
    work_of_adhesion: Any = None,
    adhesion_range: Any = None,
    coarse_grain: bool = False,
    decimal_comma: bool = False,
) -> Dict[str, Any]:
    """The exact contact of a height map against an elastic half-space of
    composite modulus E* at each mean pressure (periodic FFT boundary
    elements), beside the statistical model's real area on the same map: the
    JSON of ``wearopt contact SCAN --modulus E --pressure P1,… [--hardness H]
    --format json``. Pressures and moduli are strings with units ("150 GPa")
    or numbers in pascals; ``pressures`` is one or a list.

    ``heights`` is a 2-D array (rows along y) in metres, or in
    ``height_unit``, with square pixels of ``pixel_size``; or a path to a scan
    (.gsf, .x3p, .npy, ASCII), whose pixel size and unit it carries. With
    ``fields=True`` each point also holds ``pressure_field`` (Pa) and
    ``gap_field`` (m), arrays shaped like the map.

    With ``work_of_adhesion`` (γ, "50 mJ/m^2" or J/m²) and ``adhesion_range``
    (ρ, "1 nm" or metres) each point also holds ``adhesive``, the contact
    under the attraction −γ e^(−g/ρ) at the same mean pressure (with
    ``fields=True`` also ``adhesive_pressure_field`` and
    ``adhesive_gap_field``), and the document ``adhesion``: the resolution,
    the range solved (``coarse_grain=True`` raises an unresolved ρ instead of
    refusing it) and the map's pull-off (``pull_off_pressure``,
    ``pull_off_force``).

    >>> import numpy as np
    >>> z = np.load("problems/scans/self-affine-nm.npy")
    >>> c = wearopt.contact(z, pixel_size="20 nm", height_unit="nm",
    ...                     modulus="150 GPa", pressures=["50 MPa", "200 MPa"])
    >>> [round(p["real_area_fraction"], 3) for p in c["points"]]
    [0.017, 0.063]
    >>> c["points"][0]["area_ratio"] < 1   # the statistical model's area is low
    True
    """
    if modulus is None or pressures is None:
        raise TypeError("contact() needs modulus= (E*, e.g. \"150 GPa\") and pressures= (one or a list)")
    if height_unit is not None and not isinstance(height_unit, str):
        height_unit = repr(float(height_unit))
    if isinstance(pressures, (str, int, float)) and not isinstance(pressures, bool):
        pressures = [pressures]
    pressure_list = [_quantity("a pressure", p, "pascals") for p in pressures]
    e_star = _quantity("modulus", modulus, "pascals")
    cap = _quantity("hardness", hardness, "pascals")
    adhesion = dict(
        work_of_adhesion=_quantity("work_of_adhesion", work_of_adhesion, "J/m²"),
        adhesion_range=_length(adhesion_range),
        coarse_grain=bool(coarse_grain),
    )
    if isinstance(heights, (str, _os.PathLike)):
        text, p_fields, g_fields, ap_fields, ag_fields = _wearopt.contact_json(
            _os.fspath(heights), e_star, pressure_list, cap, level,
            _length(pixel_size), height_unit, float(tolerance), bool(fields),
            decimal_comma=bool(decimal_comma), **adhesion,
        )
    else:
        z = _float_array("heights", heights)
        if z.ndim != 2:
            raise ValueError(f"heights: a 2-D array (rows along y) is needed, not {z.ndim}-D")
        if pixel_size is None:
            raise ValueError('pixel_size=None: heights in an array carry no pixel size; give one, e.g. "10 nm"')
        text, p_fields, g_fields, ap_fields, ag_fields = _wearopt.contact_array(
            _np.ascontiguousarray(z, dtype=_np.float64), _length(pixel_size), e_star,
            pressure_list, cap, level, height_unit, float(tolerance), bool(fields),
            **adhesion,
        )
    doc = _json.loads(text)
    for point, p, g in zip(doc["points"], p_fields, g_fields):
        point["pressure_field"] = p
        point["gap_field"] = g
    for point, p, g in zip(doc["points"], ap_fields, ag_fields):
        point["adhesive_pressure_field"] = p
        point["adhesive_gap_field"] = g
    return doc


def _float_array(name: str, value: Any) -> _np.ndarray:
    a = _np.asarray(value)
    if a.dtype.kind not in "iuf":
        raise TypeError(
            f"{name} must hold real numbers (integer or float dtype), not dtype {a.dtype}"
        )
    return a.astype(_np.float64, copy=False)


def curve(
    theta: Any,
    lam: Any,
    h: Any,
    adhesion_model: str = "jkr",
    attraction: Any = None,
    attraction_range: Any = None,
    hardness_coefficient: Any = _np.inf,
) -> Dict[str, _np.ndarray]:
    """The non-dimensional model (the columns of ``wearopt curve``) at every
    (θ, λ, h) of the broadcast arrays: ``h``, ``load`` (P̄), ``area`` (Ā),
    ``plastic_area``, ``critical_interference`` (Δc), ``dload_dh`` and
    ``noncontact_load``, each an array of the broadcast shape.
    ``adhesion_model="dmt"`` with ``attraction`` ("van_der_waals" or
    "dugdale") and ``attraction_range`` (z0 = Z0/σ or h0/σ) is
    ``wearopt curve --adhesion-model dmt``; ``adhesion_model="lennard_jones"``
    with ``attraction_range`` (z0 = Z0/σ, no ``attraction``) is the
    self-consistent Lennard-Jones sphere (docs/model.md §11). ``theta`` or ``lam`` may be ``inf`` (no
    adhesion, no plasticity); with ``theta = inf`` plasticity comes from
    ``hardness_coefficient`` c_h. Runs in parallel without the GIL.

    >>> import numpy as np
    >>> c = wearopt.curve(10.0, 0.125, np.linspace(-2, 4, 61))
    >>> c["load"].shape
    (61,)
    >>> wearopt.curve([[1.0], [10.0]], 1.0, [0.0, 1.0, 2.0])["area"].shape
    (2, 3)
    """
    if attraction_range is not None:
        attraction_range = float(attraction_range)
    arrays = _np.broadcast_arrays(
        _float_array("theta", theta),
        _float_array("lam", lam),
        _float_array("hardness_coefficient", hardness_coefficient),
        _float_array("h", h),
    )
    shape = arrays[0].shape
    flat = [_np.ascontiguousarray(a, dtype=_np.float64).reshape(-1) for a in arrays]
    out = _wearopt.curve_arrays(*flat, adhesion_model, attraction, attraction_range)
    return {k: v.reshape(shape) for k, v in out.items()}


def sweep(
    problem: Problem,
    samples: int,
    method: str = "sobol",
    seed: int = 0,
    shard: Optional[Tuple[int, int]] = None,
    format: str = "csv",
) -> str:
    """The output of ``wearopt sweep FILE --samples N --method M --seed S
    [--shard I/N] --format F`` as text: the study's scene at ``samples``
    designs of its ``[design]`` box. ``shard=(i, n)`` computes the i-th of n
    equal parts; :func:`merge` joins parts into the unsharded text. The text
    begins with the sweep's fingerprint (CSV: a ``# wearopt sweep …`` comment
    line, read with ``pandas.read_csv(…, comment="#")``; JSON: the keys
    ``fingerprint`` and ``shard``).

    >>> import io, csv
    >>> text = wearopt.sweep("problems/micro-gear-study.toml", 16)
    >>> text.splitlines()[0].split()[:3]    # its fingerprint, which CSV readers skip
    ['#', 'wearopt', 'sweep']
    >>> rows = list(csv.DictReader(l for l in io.StringIO(text) if not l.startswith("#")))
    >>> len(rows), rows[0]["status"]
    (16, 'ok')
    """
    i, n = shard if shard is not None else (0, 1)
    for name, v in (("samples", samples), ("seed", seed), ("shard index", i), ("shard count", n)):
        if not _is_int(v):
            raise TypeError(f"{name} must be an int, not {type(v).__name__}")
        if v < 0:
            raise ValueError(f"{name} {v}: must be >= 0")
    return _wearopt.sweep_text(
        *_source(problem), int(samples), method, int(seed), int(i), int(n), format
    )


def merge(
    parts: Iterable[Union[str, Dict[str, Any]]], samples: Optional[int] = None
) -> Union[str, Dict[str, Any]]:
    """Joins the texts of sweep shards (any order) into the text of the
    unsharded sweep, byte for byte (``wearopt merge``); ``samples`` checks that
    no row is missing.

    Uncertainty parts (the dicts of ``uncertainty(..., shard=(i, n))``, or
    their JSON texts as ``wearopt uncertainty --shard`` writes them) are
    joined into the document of the unsharded run, as :func:`uncertainty`
    returns it; ``samples`` checks the study's N. Parts of another study, and
    samples no part holds or two parts hold, raise ``ValueError`` naming them.

    >>> parts = [wearopt.sweep("problems/micro-gear-study.toml", 8, shard=(i, 3)) for i in range(3)]
    >>> wearopt.merge(parts) == wearopt.sweep("problems/micro-gear-study.toml", 8)
    True
    """
    parts = list(parts)
    for k, p in enumerate(parts):
        if not isinstance(p, (str, dict)):
            raise TypeError(f"part {k} must be a str or a dict, not {type(p).__name__}")
    if any(isinstance(p, dict) for p in parts) or any(
        _wearopt.is_uncertainty_part(p) for p in parts
    ):
        texts = [p if isinstance(p, str) else _json.dumps(p, allow_nan=False) for p in parts]
        return _arrays(_json.loads(_wearopt.merge_uncertainty_json(texts, samples)))
    return _wearopt.merge_text(parts, samples)


def fit_adhesion(
    data: Union[str, "_os.PathLike[str]"],
    radius: Any,
    mu: Optional[float] = None,
    fit_mu: bool = False,
    modulus: Any = None,
    materials: Optional[Iterable[str]] = None,
    quoted_gamma: Any = None,
    quoted_bond_strength: Any = None,
) -> Dict[str, Any]:
    """The work of adhesion γ (and μ with ``fit_mu=True``) from friction
    measurements by the JKR friction law: the JSON of ``wearopt fit-adhesion
    DATA --radius R [--mu μ | --fit-mu] [--modulus E | --materials A,B]
    --format json``. ``data`` is a CSV with the header ``load,friction``;
    quantities are strings with units ("0.3 mm") or SI numbers; ``materials``
    names catalogue materials (one: both bodies; two: ball first).

    >>> c = wearopt.fit_adhesion("problems/ando-friction.csv", "0.3 mm",
    ...                          materials=["steel", "silicon"])
    >>> c["comparison"]["work_of_adhesion"]["quoted"], c["converged"]
    (0.1, True)
    """
    if mu is not None:
        mu = float(mu)
    return _json.loads(
        _wearopt.fit_adhesion_json(
            _os.fspath(data),
            _quantity("radius", radius),
            mu,
            bool(fit_mu),
            _quantity("modulus", modulus),
            None if materials is None else [str(m) for m in materials],
            _quantity("quoted_gamma", quoted_gamma),
            _quantity("quoted_bond_strength", quoted_bond_strength),
        )
    )


def fit_wear(
    path_or_rows: Any,
    temperature: Any = None,
    speed: Any = None,
) -> Dict[str, Any]:
    """The activation energy ΔU and volume ΔV of stress-assisted wear from
    measured wear rates: the JSON of ``wearopt fit-wear DATA [--temperature T]
    [--speed v] --format json``. ``path_or_rows`` is a CSV file (header
    ``stress_Pa``, then ``rate_atoms_per_s``, ``rate_m3_per_s`` or
    ``rate_m3_per_m``, then optionally ``temperature_K``) or its columns as a
    mapping of those names to sequences (a dict, a pandas DataFrame).
    ``temperature`` ("350 K" or kelvin) applies to every row of a file without
    ``temperature_K``; ``speed`` ("1 mm/s" or m/s) turns m³/m into m³/s.

    >>> f = wearopt.fit_wear("problems/wear-rates.csv")
    >>> round(f["activation_energy_ev"]["estimate"], 1)
    0.9
    """
    temperature = _quantity("temperature", temperature, "kelvin")
    speed = _quantity("speed", speed, "m/s")
    if isinstance(path_or_rows, (str, _os.PathLike)):
        return _json.loads(_wearopt.fit_wear_json(_os.fspath(path_or_rows), True, temperature, speed))
    if not hasattr(path_or_rows, "keys"):
        raise TypeError(
            "path_or_rows must be a path or a mapping of column names (stress_Pa, "
            f"rate_…, temperature_K) to sequences, not {type(path_or_rows).__name__}"
        )
    names = [str(k) for k in path_or_rows.keys()]
    columns = [[repr(float(x)) for x in path_or_rows[k]] for k in path_or_rows.keys()]
    if len({len(c) for c in columns}) > 1:
        raise ValueError("<rows>: the columns have different lengths: " + ", ".join(
            f"{n} {len(c)}" for n, c in zip(names, columns)))
    text = ",".join(names) + "\n" + "".join(",".join(row) + "\n" for row in zip(*columns))
    return _json.loads(_wearopt.fit_wear_json(text, False, temperature, speed))


def figures(
    out: Union[str, "_os.PathLike[str]", None] = None,
    points: int = 51,
    load_min: float = 0.05,
    load_max: float = 5.0,
) -> Dict[str, Any]:
    """The paper's figures 1–4 (wear volume against load), the least-squares
    line of every curve and the verdict on each claim of its §4: the JSON of
    ``wearopt figures [--out DIR] --format json``. With ``out``, the files
    ``figure1.csv`` … ``figure4.svg`` and ``slopes.csv`` are written there
    (and listed under ``files``); without it nothing is written.

    >>> f = wearopt.figures(points=5)
    >>> [c["id"] for c in f["claims"]][0], f["files"]
    ('linear', [])
    """
    return _json.loads(
        _wearopt.figures_json(
            int(points),
            float(load_min),
            float(load_max),
            None if out is None else _os.fspath(out),
        )
    )


def accuracy(problem: Optional[Problem] = None) -> Dict[str, Any]:
    """The work–precision of the evaluator against an independent reference
    (the JSON of ``wearopt accuracy [FILE] --format json``): the error and time
    of each quadrature setting and finite-difference rule, over an extreme-range
    grid and the problem's region (the shipped scenes' without one). Takes
    seconds: every setting is timed.
    """
    if problem is None:
        return _json.loads(_wearopt.accuracy_json())
    return _json.loads(_wearopt.accuracy_json(*_source(problem)))



# The typing names served the annotations above (strings, under ``from __future__
# import annotations``) and the ``Problem`` alias; deleted so that ``dir(wearopt)``
# lists the public API only (python/tests/test_wearopt.py::test_dir_is_the_public_api).
del annotations, Any, Dict, Iterable, Optional, Tuple, Union
