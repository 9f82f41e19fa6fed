"""The V trap's inside, as the metrics layer decides it (trap/v_trap.cpp, VTrap::contains), for
the Python scripts beside this file: `from vtrap import inside_trap`."""
import math

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
