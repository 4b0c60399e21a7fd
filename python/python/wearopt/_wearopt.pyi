"""The compiled half of `wearopt` (private: use the functions of `wearopt`)."""

from typing import Dict, List, Optional, Tuple

import numpy as np

def evaluate_json(source: str, is_path: bool) -> str: ...
def optimize_json(source: str, is_path: bool) -> str: ...
def pareto_json(
    source: str,
    is_path: bool,
    points: Optional[int] = None,
    adhesion: Optional[str] = None,
    direction: Optional[str] = None,
) -> str: ...
def uncertainty_json(source: str, is_path: bool, method: str, samples: Optional[int], seed: Optional[int]) -> str: ...
def humidity_json(source: str, is_path: bool, from_: str, to: str, points: int) -> str: ...
def curve_arrays(
    theta: np.ndarray,
    lam: np.ndarray,
    hardness_coefficient: np.ndarray,
    h: np.ndarray,
    adhesion_model: str = "jkr",
    attraction: Optional[str] = None,
    attraction_range: Optional[float] = None,
) -> Dict[str, np.ndarray]: ...
def sweep_text(
    source: str,
    is_path: bool,
    samples: int,
    method: str,
    seed: int,
    shard_index: int,
    shard_count: int,
    format: str,
) -> str: ...
def merge_text(parts: List[str], samples: Optional[int] = None) -> str: ...
def roughness_json(
    path: str,
    cutoff: Optional[str] = None,
    level: str = "plane",
    pixel_size: Optional[str] = None,
    height_unit: Optional[str] = None,
    decimal_comma: bool = False,
) -> str: ...
def roughness_array_json(
    heights: np.ndarray,
    pixel_size: str,
    cutoff: Optional[str] = None,
    level: str = "plane",
    height_unit: Optional[str] = None,
) -> str: ...
def contact_json(
    path: str,
    modulus: str,
    pressures: List[str],
    hardness: Optional[str] = None,
    level: str = "plane",
    pixel_size: Optional[str] = None,
    height_unit: Optional[str] = None,
    tolerance: float = 1e-10,
    fields: bool = False,
    work_of_adhesion: Optional[str] = None,
    adhesion_range: Optional[str] = None,
    coarse_grain: bool = False,
    decimal_comma: bool = False,
) -> Tuple[str, List[np.ndarray], List[np.ndarray], List[np.ndarray], List[np.ndarray]]: ...
def contact_array(
    heights: np.ndarray,
    pixel_size: str,
    modulus: str,
    pressures: List[str],
    hardness: Optional[str] = None,
    level: str = "plane",
    height_unit: Optional[str] = None,
    tolerance: float = 1e-10,
    fields: bool = False,
    work_of_adhesion: Optional[str] = None,
    adhesion_range: Optional[str] = None,
    coarse_grain: bool = False,
) -> Tuple[str, List[np.ndarray], List[np.ndarray], List[np.ndarray], List[np.ndarray]]: ...
def fit_adhesion_json(
    path: str,
    radius: str,
    mu: Optional[float] = None,
    fit_mu: bool = False,
    modulus: Optional[str] = None,
    materials: Optional[List[str]] = None,
    quoted_gamma: Optional[str] = None,
    quoted_bond_strength: Optional[str] = None,
) -> str: ...
def fit_wear_json(
    source: str,
    is_path: bool,
    temperature: Optional[str] = None,
    speed: Optional[str] = None,
) -> str: ...
def figures_json(points: int, load_min: float, load_max: float, out: Optional[str] = None) -> str: ...
def accuracy_json(source: Optional[str] = None, is_path: bool = True) -> str: ...
