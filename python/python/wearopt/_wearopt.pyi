"""The compiled half of `wearopt` (private: use the functions of `wearopt`)."""

from typing import Dict, List, Optional

import numpy as np

def evaluate_json(source: str, is_path: bool) -> str: ...
def optimize_json(source: str, is_path: bool) -> str: ...
def pareto_json(source: str, is_path: bool, points: Optional[int] = None) -> str: ...
def curve_arrays(
    theta: np.ndarray, lam: np.ndarray, hardness_coefficient: np.ndarray, h: np.ndarray
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
) -> str: ...
