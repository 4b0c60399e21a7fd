"""Type stubs of the `wearopt` package (see the docstrings in __init__.py)."""

import os
from typing import Any, Dict, Iterable, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
from numpy.typing import ArrayLike

__version__: str

Problem = Union[str, os.PathLike[str], Dict[str, Any]]

def evaluate(problem: Problem) -> Dict[str, Any]:
    """The JSON of `wearopt eval FILE --format json` as a dict.

    >>> wearopt.evaluate("problems/micro-gear.toml")["status"]
    'ok'
    """

def optimize(problem: Problem) -> Dict[str, Any]:
    """The JSON of `wearopt optimize FILE --format json` as a dict.

    >>> wearopt.optimize("problems/micro-gear-study.toml")["status"]
    'optimal'
    """

def asperity(
    tabor: Optional[float],
    from_: float,
    to: float,
    points: int,
    adhesion_model: str = "lennard_jones",
    *,
    radius: Union[float, str, None] = None,
    work_of_adhesion: Union[float, str, None] = None,
    modulus: Union[float, str, None] = None,
    interatomic_distance: Union[float, str, None] = None,
    fast: Optional[bool] = None,
) -> Dict[str, Any]:
    """The JSON of `wearopt asperity --tabor MU --from D0 --to D1 --points N --format json` as a dict
    (or the sphere in SI instead of μ; `fast`: `--fast`)."""
    ...

def uncertainty(
    problem: Problem, method: str = "sobol", samples: Optional[int] = None, seed: Optional[int] = None
) -> Dict[str, Any]:
    """The JSON of `wearopt uncertainty FILE --method M --format json` as a dict (intervals and the CDF as numpy arrays)."""
    ...

def humidity(problem: Problem, from_: Union[float, str], to: Union[float, str], points: int) -> Dict[str, Any]:
    """The JSON of `wearopt humidity FILE --from RH0 --to RH1 --points N --format json` as a dict."""
    ...

def pareto(
    problem: Problem,
    points: Optional[int] = None,
    adhesion: Optional[str] = None,
    direction: Optional[str] = None,
) -> Dict[str, Any]:
    """The JSON of `wearopt pareto FILE [--points N] [--adhesion M] [--direction D]
    --format json` as a dict (without a `[pareto]` section: pull_off_force, 15
    points, low, unless given).

    >>> len(wearopt.pareto("problems/micro-gear.toml", points=5)["points"])
    5
    """

def contact(
    heights: Union[str, os.PathLike[str], ArrayLike],
    pixel_size: Union[str, float, None] = None,
    modulus: Union[str, float, None] = None,
    pressures: Union[str, float, Sequence[Union[str, float]], None] = None,
    hardness: Union[str, float, None] = None,
    level: str = "plane",
    height_unit: Union[str, float, None] = None,
    tolerance: float = 1e-10,
    fields: bool = False,
    work_of_adhesion: Union[str, float, None] = None,
    adhesion_range: Union[str, float, None] = None,
    coarse_grain: bool = False,
    decimal_comma: bool = False,
) -> Dict[str, Any]:
    """The JSON of `wearopt contact SCAN … --format json` as a dict (fields as
    arrays with `fields=True`; with `work_of_adhesion` and `adhesion_range`,
    the adhesive contact and the map's pull-off too).

    >>> wearopt.contact("problems/scans/self-affine.gsf", modulus="150 GPa",
    ...                 pressures="100 MPa")["points"][0]["status"]
    'converged'
    """

def roughness(
    path: Union[str, os.PathLike[str], ArrayLike],
    cutoff: Union[str, float, None] = None,
    level: str = "plane",
    pixel_size: Union[str, float, None] = None,
    height_unit: Union[str, float, None] = None,
    decimal_comma: bool = False,
) -> Dict[str, Any]:
    """The JSON of `wearopt roughness FILE … --format json` as a dict.

    >>> wearopt.roughness("problems/scans/self-affine.gsf")["summit_sigma"] > 0
    True
    """

def curve(
    theta: ArrayLike,
    lam: ArrayLike,
    h: ArrayLike,
    adhesion_model: str = "jkr",
    attraction: Optional[ArrayLike] = None,
    attraction_range: Optional[ArrayLike] = None,
    hardness_coefficient: ArrayLike = ...,
) -> Dict[str, np.ndarray]:
    """The columns of `wearopt curve` (h, load, area, plastic_area,
    critical_interference, dload_dh) at the broadcast (θ, λ, h).

    >>> wearopt.curve([[1.0], [10.0]], 1.0, [0.0, 1.0, 2.0])["load"].shape
    (2, 3)
    """

def sweep(
    problem: Problem,
    samples: int,
    method: str = "sobol",
    seed: int = 0,
    shard: Optional[Tuple[int, int]] = None,
    format: str = "csv",
) -> str:
    """The text of `wearopt sweep FILE --samples N …` (CSV or JSON).

    >>> wearopt.sweep("problems/micro-gear-study.toml", 4).count("\\n")
    5
    """

def merge(parts: Iterable[str], samples: Optional[int] = None) -> str:
    """The text of `wearopt merge PARTS…`: the shards joined into the unsharded sweep.

    >>> parts = [wearopt.sweep("problems/micro-gear-study.toml", 8, shard=(i, 2)) for i in range(2)]
    >>> wearopt.merge(parts) == wearopt.sweep("problems/micro-gear-study.toml", 8)
    True
    """

def fit_adhesion(
    data: Union[str, os.PathLike[str]],
    radius: Union[str, float],
    mu: Optional[float] = None,
    fit_mu: bool = False,
    modulus: Union[str, float, None] = None,
    materials: Optional[Iterable[str]] = None,
    quoted_gamma: Union[str, float, None] = None,
    quoted_bond_strength: Union[str, float, None] = None,
) -> Dict[str, Any]:
    """The JSON of `wearopt fit-adhesion DATA --radius R … --format json` as a dict."""

def fit_wear(
    path_or_rows: Union[str, os.PathLike[str], Mapping[str, Sequence[float]]],
    temperature: Union[str, float, None] = None,
    speed: Union[str, float, None] = None,
) -> Dict[str, Any]:
    """The JSON of `wearopt fit-wear DATA [--temperature T] [--speed v] --format json` as a dict."""

def figures(
    out: Union[str, os.PathLike[str], None] = None,
    points: int = 51,
    load_min: float = 0.05,
    load_max: float = 5.0,
) -> Dict[str, Any]:
    """The JSON of `wearopt figures [--out DIR] --format json` as a dict (files written only with `out`)."""

def accuracy(problem: Optional[Problem] = None) -> Dict[str, Any]:
    """The JSON of `wearopt accuracy [FILE] --format json` as a dict."""
