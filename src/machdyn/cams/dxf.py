"""The cam profile as a DXF drawing for the workshop: closed polylines of the cam surface, the pitch curve and
the cutter's path, in millimetres (AutoCAD R12 DXF, group codes as in the AutoCAD DXF Reference: HEADER with
$INSUNITS = 4 (mm), ENTITIES with POLYLINE/VERTEX/SEQEND, one layer per curve)."""

from __future__ import annotations

import numpy as np


def _polyline(layer: str, xy: np.ndarray) -> list[str]:
    out = ["0", "POLYLINE", "8", layer, "66", "1", "70", "1", "10", "0.0", "20", "0.0", "30", "0.0"]
    for x, y in zip(xy[0] * 1e3, xy[1] * 1e3, strict=True):
        out += ["0", "VERTEX", "8", layer, "10", f"{x:.6f}", "20", f"{y:.6f}", "30", "0.0"]
    return [*out, "0", "SEQEND", "8", layer]


def profile_dxf(curves: dict[str, np.ndarray]) -> str:
    """A DXF text with one closed polyline per curve: layer name -> (2, K) points [m], written in mm."""
    lines = ["0", "SECTION", "2", "HEADER", "9", "$ACADVER", "1", "AC1009", "9", "$INSUNITS", "70", "4",
             "0", "ENDSEC", "0", "SECTION", "2", "ENTITIES"]
    for layer, xy in curves.items():
        lines += _polyline(layer, np.asarray(xy, dtype=float))
    lines += ["0", "ENDSEC", "0", "EOF"]
    return "\n".join(lines) + "\n"


def read_polylines(text: str) -> dict[str, np.ndarray]:
    """The polylines of a DXF written by :func:`profile_dxf` (layer -> (2, K) points [mm]), to check it."""
    codes = text.split("\n")
    pairs = list(zip(codes[0::2], codes[1::2], strict=False))
    out: dict[str, list[tuple[float, float]]] = {}
    layer = None
    x = None
    for k, (code, value) in enumerate(pairs):
        if code == "0" and value == "VERTEX":
            layer = pairs[k + 1][1]
            out.setdefault(layer, [])
        elif code == "10" and layer is not None:
            x = float(value)
        elif code == "20" and layer is not None and x is not None:
            out[layer].append((x, float(value)))
            x = None
        elif code == "0" and value == "SEQEND":
            layer = None
    return {name: np.array(points).T for name, points in out.items()}
