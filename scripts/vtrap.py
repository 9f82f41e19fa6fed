"""The V trap's inside, as the metrics layer decides it (trap/v_trap.cpp, VTrap::contains), the
blocks of a run's scenario.resolved.yaml that say where it is, the held rods, the rods' frames in
the plane from rods.h5 (planar_frames) or from a run's rods.csv or rods.h5 (read_frames), and the
spheres of trajectory.dump's last frame, for the Python scripts beside this file:
`from vtrap import inside_trap, resolved_block`."""
import json
import math
import sys
import re

import numpy as np


def cross(a, b):
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def inside_trap(points, trap):
    """VTrap::contains for an array of points [..., 2]; `trap` is the resolved scenario's block."""
    apex = np.array(trap["apex"])
    half = math.radians(trap["angle"]) / 2
    bisector = math.radians(trap["direction"])
    length = trap["arm_length"]
    left = length * np.array([math.cos(bisector + half), math.sin(bisector + half)])
    right = length * np.array([math.cos(bisector - half), math.sin(bisector - half)])
    relative = points - apex
    return ((cross(left, relative) <= 0) & (cross(right, relative) >= 0)
            & (cross(right - left, relative - left) <= 0))


def held_rods(inside, unwrapped, lag, distance):
    """The metrics layer's held rods (docs/metrics.md, "Held rods") over frames [frames, rods]:
    inside the trap and moved less than `distance` over the last `lag` frames; none in the first
    `lag` frames. `unwrapped` is [frames, rods, 2]."""
    held = np.zeros(inside.shape, dtype=bool)
    if lag < len(inside):
        moved = np.linalg.norm(unwrapped[lag:] - unwrapped[:-lag], axis=-1)
        held[lag:] = inside[lag:] & (moved < distance)
    return held


def planar_frames(rods, frames, box):
    """Wrapped and unwrapped centres and in-plane axes, each [frames, rods, 2], of the frames
    `frames` (an index array or a slice) of rods.h5's particles/rods group; `box` is the cell's
    [x, y] side."""
    position = rods["position/value"][frames, :, :2].astype(float)
    unwrapped = position + rods["image/value"][frames, :, :2] * box
    axis = rods["orientation/value"][frames, :, :2].astype(float)
    return position, unwrapped, axis


def resolved_block(text, name):
    """The `key: value` lines of a top-level block of scenario.resolved.yaml, values as JSON (the
    resolved file writes numbers and flow lists, which JSON reads)."""
    block = re.search(rf"^{name}:\n((?:  .*\n)+)", text, re.MULTILINE)
    values = {}
    for line in block.group(1).splitlines() if block else []:
        match = re.match(r"^  (\w+): (.+)$", line)
        if match:
            try:
                values[match.group(1)] = json.loads(match.group(2))
            except ValueError:
                values[match.group(1)] = match.group(2)
    return values


def species_names(text):
    """The species' names of scenario.resolved.yaml, in order (their index in rods.h5)."""
    block = re.search(r"^species:\n((?:[ -].*\n)+)", text, re.MULTILINE)
    return re.findall(r"^  - name: (\S+)$", block.group(1), re.MULTILINE) if block else []


def last_dump_frame(path):
    """{rod: [(x, y, z, radius), ...]} of trajectory.dump's last frame, spheres in the order
    written; exits with a message where the run wrote no dump."""
    try:
        lines = path.read_text().splitlines()
    except OSError as error:
        sys.exit(f"{path}: {error.strerror}; run with output.trajectory_interval > 0")
    starts = [i for i, line in enumerate(lines) if line.startswith("ITEM: ATOMS")]
    if not starts:
        sys.exit(f"{path}: no ITEM: ATOMS block")
    columns = lines[starts[-1]].split()[2:]
    spheres = {}
    for line in lines[starts[-1] + 1:]:
        if line.startswith("ITEM:"):
            break
        row = dict(zip(columns, line.split()))
        spheres.setdefault(int(row["mol"]) - 1, []).append(
            tuple(float(row[k]) for k in ("x", "y", "z", "radius")))
    return spheres


def read_csv(path):
    """Times, species names [rods], centres, unwrapped centres and in-plane axes [frames, rods, 2]
    of rods.csv."""
    try:
        with open(path) as stream:
            header = stream.readline().strip().split(",")
    except OSError as error:
        sys.exit(f"{path}: {error.strerror}")
    wanted = ["t", "species", "x", "y", "xu", "yu", "ux", "uy"]
    missing = [c for c in wanted if c not in header]
    if missing:
        sys.exit(f"{path}: no column {', '.join(missing)}")
    columns = [header.index(c) for c in wanted]
    data = np.genfromtxt(path, delimiter=",", skip_header=1, usecols=columns, dtype=None,
                         encoding=None, names=wanted)
    data = np.atleast_1d(data)
    times = np.unique(data["t"])
    if len(times) < 2 or len(data) % len(times):
        sys.exit(f"{path}: needs at least two whole frames")
    frames = data.reshape(len(times), len(data) // len(times))
    pair = lambda a, b: np.stack([frames[a], frames[b]], -1).astype(float)
    return (times, frames["species"][0], pair("x", "y"), pair("xu", "yu"),
            pair("ux", "uy"))


def read_h5(path, names):
    """As read_csv, from rods.h5 (H5MD); `names` are the species' names by index."""
    try:
        import h5py
    except ImportError as error:
        sys.exit(f"{path}: reading it needs h5py (Debian's python3-h5py): {error}")
    rods = h5py.File(path, "r")["particles/rods"]
    times = rods["position/time"][:]
    if len(times) < 2:
        sys.exit(f"{path}: needs at least two whole frames")
    edges = rods["box/edges/value"][0]
    box = np.array([edges[0, 0], edges[1, 1]])
    position, unwrapped, axis = planar_frames(rods, slice(None), box)
    species = np.array([names[k] for k in rods["species"][:]])
    return times, species, position, unwrapped, axis


def read_frames(run, text):
    """As read_csv, from the run's rods.csv, or from its rods.h5 where it wrote no rods.csv; `text`
    is its scenario.resolved.yaml."""
    if (run / "rods.csv").exists() or not (run / "rods.h5").exists():
        return read_csv(run / "rods.csv")
    return read_h5(run / "rods.h5", species_names(text))
