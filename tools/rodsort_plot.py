#!/usr/bin/env python3
"""Plots of rodsort runs and sweeps, as PNG and SVG (matplotlib).

`rodsort plot` runs this script; it can also be run by hand:

    rodsort_plot.py RUN_DIR [RUN_DIR ...]  [--what eta,population,dtheta] [-o DIR]
    rodsort_plot.py SWEEP_DIR              [--what eta-theta,thetac-eps,measures] [-o DIR]
    rodsort_plot.py STUDY_DIR [STUDY_DIR ...] [--what axial-velocity,msd]  [-o DIR]

From a run directory (metrics.csv, rods.csv):
  eta         eta(t), with eta in the trap and one line per species for mixtures
  population  rods inside the trap per species over time (dashed: the stationary ones; dotted:
              the held ones, docs/metrics.md)
  dtheta      P(dtheta), the distribution of orientation changes over tau (the paper's Fig. 2e-f),
              one line per species, or per run when several runs are given
From a sweep directory (sweep.csv):
  eta-theta   time-averaged eta against the trap angle, one line per noise level, theta_c marked
  thetac-eps  theta_c against the collision-kick noise eps
  measures    eta, eta in the trap and, for mixtures, the sorting index, the first species'
              purity and its purity among the rods the trap holds, against the first swept key
              other than the seed (a sweep over noise or composition; seeds averaged, standard
              errors as bars)
From a single-particle study directory (`rodsort single -o`: summary.csv, lags.csv):
  axial-velocity  P(V_x), the axial velocity over the window, with the experiments' range of v0
  msd             mean squared displacement and heading correlation against the lag
theta_c follows metrics/critical_angle.cpp: the first downward crossing of half the mean eta of the
three smallest angles, interpolated linearly; it is also written to theta_c.csv, each seed's own to
theta_c_seeds.csv, and the differences between curves seed by seed to theta_c_paired.csv.

Several run directories draw on the same axes (one line per run), for comparisons such as the
paper's system sizes. Output goes to RUN_DIR/plots (SWEEP_DIR/plots), or to -o DIR.
Species keep the colours of `rodsort render` (Okabe-Ito, colour-blind safe).
"""

import argparse
import csv
import math
import os
import re
import sys

RUN_KINDS = ("eta", "population", "dtheta")
SWEEP_KINDS = ("eta-theta", "thetac-eps", "measures")
STUDY_KINDS = ("axial-velocity", "msd")

# The Okabe-Ito palette in render/palette.cpp's order.
SPECIES_COLOURS = ("#0072B2", "#E69F00", "#009E73", "#D55E00", "#CC79A7", "#56B4E9", "#F0E442")
PLATEAU_POINTS = 3  # as metrics::critical_angle's default
MIN_PLATEAU_ETA = 0.1  # metrics::kMinPlateauEta


class PlotError(Exception):
    """A problem the user can act on: a missing file or column, a sweep that cannot give a plot."""


class UsageError(PlotError):
    """Arguments that cannot work, whatever the files hold (exit status 2, as rodsort's)."""


def colour(index):
    return SPECIES_COLOURS[index % len(SPECIES_COLOURS)]


def run_line_style(index):
    """Solid for the first runs of a plot, then dashed, then dotted: the colours repeat after
    len(SPECIES_COLOURS) runs, and the style tells those runs apart."""
    return ("-", "--", ":")[min(index // len(SPECIES_COLOURS), 2)]


# ---------------------------------------------------------------------------------------------
# Reading


class Table:
    """A CSV file read whole: its header and its columns as lists of strings."""

    def __init__(self, path):
        self.path = path
        if not os.path.isfile(path):
            raise PlotError(f"{path}: no such file")
        with open(path, newline="") as stream:
            reader = csv.reader(stream)
            try:
                self.header = next(reader)
            except StopIteration:
                raise PlotError(f"{path}: the file is empty (no header line)") from None
            rows = [row for row in reader if row]
        # A run stopped while writing may leave a short last line: drop it.
        if rows and len(rows[-1]) != len(self.header):
            rows.pop()
        for number, row in enumerate(rows, start=2):
            if len(row) != len(self.header):
                raise PlotError(
                    f"{path}:{number}: {len(row)} fields, the header has {len(self.header)}")
        self.rows = rows

    def has(self, column):
        return column in self.header

    def require(self, column, why):
        if column not in self.header:
            raise PlotError(f"{self.path}: no column '{column}' ({why}); "
                            f"the columns are: {', '.join(self.header)}")

    def text(self, column):
        index = self.header.index(column)
        return [row[index] for row in self.rows]

    def numbers(self, column, why="needed for this plot"):
        self.require(column, why)
        values = []
        for number, value in enumerate(self.text(column), start=2):
            try:
                values.append(float(value))
            except ValueError:
                raise PlotError(f"{self.path}:{number}: column '{column}': "
                                f"expected a number, got '{value}'") from None
        return values


def metrics_species(table):
    """Species names of metrics.csv, from its per-species purity_<name> columns (not the held
    count's purity_held_<name>)."""
    return [column[len("purity_"):] for column in table.header
            if column.startswith("purity_") and not column.startswith("purity_held_")]


def run_label(path, runs=()):
    """The run directory's name; with its parent's when another of `runs` has the same name
    (points of two sweeps, fig2e/angle-80_seed-1 and fig2f/angle-80_seed-1)."""
    def name(p):
        return os.path.basename(os.path.normpath(p))
    if sum(1 for other in runs if name(other) == name(path)) > 1:
        parent = os.path.basename(os.path.dirname(os.path.normpath(path)))
        return f"{parent}/{name(path)}"
    return name(path)


def species_names(directory):
    """The species of a run (its scenario.resolved.yaml) or of a sweep (the first of its
    scenarios/*.yaml), in index order; [] when there is none. The resolved scenario lists them
    as `species:` items that begin with `- name: ...`."""
    path = os.path.join(directory, "scenario.resolved.yaml")
    if not os.path.exists(path):
        folder = os.path.join(directory, "scenarios")
        files = sorted(f for f in os.listdir(folder) if f.endswith(".yaml")) \
            if os.path.isdir(folder) else []
        if not files:
            return []
        path = os.path.join(folder, files[0])
    names, inside = [], False
    with open(path, encoding="utf-8") as stream:
        for line in stream:
            if not line.startswith(" "):
                inside = line.startswith("species:")
                continue
            match = re.match(r"^  - name: *(\S+)", line)
            if inside and match:
                names.append(match.group(1).strip("'\""))
    return names


def scenario_name(run_dir):
    """The `name:` of a run's resolved scenario, or the directory's name."""
    path = os.path.join(run_dir, "scenario.resolved.yaml")
    if os.path.exists(path):
        with open(path, encoding="utf-8") as stream:
            for line in stream:
                match = re.match(r"^name: *(.+)$", line)
                if match:
                    return match.group(1).strip().strip("'\"")
    return run_label(run_dir)


# What the swept keys mean, for axes and legends: (name, unit); {s} is the species.
PHYSICS_NAMES = {
    "trap.angle": ("trap opening angle θ", "degrees"),
    "trap.arm_length": ("trap arm length L", "mm"),
    "box.size": ("cell size", "mm"),
    "drive.gamma": ("Γ", ""),
    "drive.frequency": ("drive frequency f", "Hz"),
    "drive.gap": ("gap between the plates", "mm"),
    "run.dt": ("time step dt", "s"),
    "run.duration": ("duration", "s"),
    "noise.kick_eps": ("collision-kick noise ε{s}", "mm⁻¹"),
    "noise.white_Dr": ("rotational noise D_r{s}", "rad²/s"),
    "fraction": ("fraction{s}", ""),
    "count": ("number of rods N{s}", ""),
}


def physics_name(column, species=(), with_unit=True):
    """A swept key as a physicist writes it: "species[1].noise.white_Dr" -> "rotational noise D_r
    of RnT [rad²/s]"; a key not known here is left as it is."""
    match = re.match(r"^species\[(\d+)\]\.(.+)$", column)
    key, owner = column, ""
    if match:
        index, key = int(match.group(1)), match.group(2)
        owner = f" of {species[index]}" if index < len(species) else f" of species {index + 1}"
    if key not in PHYSICS_NAMES:
        return column
    name, unit = PHYSICS_NAMES[key]
    name = name.replace("{s}", owner)
    return f"{name} [{unit}]" if with_unit and unit else name


def physics_value(column, value, species=()):
    """"ε of A = 0.01 mm⁻¹" for a legend."""
    match = re.match(r"^species\[\d+\]\.(.+)$", column)
    key = match.group(1) if match else column
    unit = PHYSICS_NAMES.get(key, ("", ""))[1]
    return f"{physics_name(column, species, with_unit=False)} = {value}" + \
        (f" {unit}" if unit and unit != "degrees" else "°" if unit == "degrees" else "")


def wrap_angle(angle):
    """Into (-pi, pi], as metrics::wrap_angle."""
    wrapped = math.remainder(angle, 2.0 * math.pi)
    return math.pi if wrapped == -math.pi else wrapped


def headings_from_csv(path):
    """Frame times, each rod's in-plane heading in every frame, and each rod's species, from
    rods.csv."""
    if not os.path.isfile(path):
        raise PlotError(f"{path}: no such file (P(dtheta) needs the rods' frames)")
    headings = {}  # rod -> list of headings, one per frame
    species_of = {}
    times = []
    with open(path, newline="") as stream:
        reader = csv.reader(stream)
        header = next(reader, None)
        if header is None:
            raise PlotError(f"{path}: the file is empty (no header line)")
        for column in ("t", "rod", "species", "ux", "uy"):
            if column not in header:
                raise PlotError(f"{path}: no column '{column}' (needed for P(dtheta)); "
                                f"the columns are: {', '.join(header)}")
        t, rod, species, ux, uy = (header.index(c) for c in ("t", "rod", "species", "ux", "uy"))
        for number, row in enumerate(reader, start=2):
            if len(row) != len(header):
                break  # an incomplete last line of a stopped run
            try:
                time = float(row[t])
                heading = math.atan2(float(row[uy]), float(row[ux]))
            except ValueError:
                raise PlotError(f"{path}:{number}: expected numbers in t, ux, uy") from None
            if not times or time != times[-1]:
                times.append(time)
            headings.setdefault(row[rod], []).append(heading)
            species_of.setdefault(row[rod], row[species])
    return times, headings, species_of


def headings_from_h5md(path):
    """The same from rods.h5 (H5MD, docs/cli.md)."""
    try:
        import h5py
    except ImportError:
        raise PlotError(f"{path}: reading rods.h5 needs h5py (Debian's python3-h5py)") from None
    try:
        with h5py.File(path, "r") as f:
            rods = f["particles/rods"]
            axes = rods["orientation/value"][:]
            times = [float(t) for t in rods["orientation/time"][:]]
            steps = rods["orientation/step"][:]
            names = [n.decode() if isinstance(n, bytes) else n
                     for n in f["parameters/species_names"][:]]
            species = [names[s] for s in rods["species"][:]]
    except (OSError, KeyError) as error:
        raise PlotError(f"{path}: cannot read it as rods.h5 ({error})") from None
    frames = min(len(times), len(axes))
    while frames > 0 and (steps[frames - 1] < 0 or math.isnan(times[frames - 1])):
        frames -= 1  # frames a stopped run did not finish writing
    import numpy
    angles = numpy.arctan2(axes[:frames, :, 1].astype(float), axes[:frames, :, 0].astype(float))
    headings = {str(rod): angles[:, rod].tolist() for rod in range(axes.shape[1])}
    species_of = {str(rod): species[rod] for rod in range(axes.shape[1])}
    return times[:frames], headings, species_of


def rods_file(run_dir):
    """The file of a run's frames: rods.csv, or else rods.h5 where only that is there."""
    path = os.path.join(run_dir, "rods.csv")
    h5 = os.path.join(run_dir, "rods.h5")
    return h5 if not os.path.isfile(path) and os.path.isfile(h5) else path


def run_headings(run_dir):
    """Frame times, each rod's heading in every frame, and each rod's species, of a run."""
    path = rods_file(run_dir)
    return headings_from_h5md(path) if path.endswith(".h5") else headings_from_csv(path)


def regular_pairs(times, lag):
    """The frames k whose pair (k, k + lag) spans lag whole intervals. Frames are regular but for
    the last of a run whose duration is not a whole number of intervals (docs/cli.md): pairs that
    reach it span less and are left out."""
    span = lag * (times[1] - times[0])
    return [k for k in range(len(times) - lag)
            if abs(times[k + lag] - times[k] - span) <= 1e-6 * span]


def orientation_changes(run_dir, tau):
    """Per species: the changes of in-plane orientation [degrees] of every rod over tau, and the
    lag in frames and the real time it spans."""
    path = rods_file(run_dir)
    times, headings, species_of = run_headings(run_dir)
    if len(times) < 2:
        raise PlotError(f"{path}: P(dtheta) needs at least two frames, found {len(times)}")
    interval = times[1] - times[0]
    lag = max(1, round(tau / interval))
    if lag >= len(times):
        raise PlotError(f"{path}: the run holds {len(times)} frames, {interval:.3g} s apart: "
                        f"too few for tau = {tau} s")
    span = lag * interval
    pairs = regular_pairs(times, lag)
    changes = {}
    for rod, series in headings.items():
        per_species = changes.setdefault(species_of[rod], [])
        per_species.extend(math.degrees(wrap_angle(series[k + lag] - series[k]))
                           for k in pairs if k + lag < len(series))
    return changes, lag, span


def critical_angle(points):
    """theta_c of (angle, eta[, levelled_at, duration]) points, as metrics::critical_angle: a
    dict (with a "caution", empty when nothing is known against it), or None with a reason."""
    points = sorted((tuple(p) + (math.nan, math.nan))[:4] for p in points)
    needed = PLATEAU_POINTS + 2
    if len(points) < needed:
        return None, (f"a critical angle needs at least {needed} angles ({PLATEAU_POINTS} for the "
                      f"low-angle plateau and two to bracket the drop), got {len(points)}")
    plateau = sum(p[1] for p in points[:PLATEAU_POINTS]) / PLATEAU_POINTS
    half = 0.5 * plateau
    if not plateau >= MIN_PLATEAU_ETA:
        return None, (f"eta at the smallest angles is {plateau:.3g}, below {MIN_PLATEAU_ETA}: "
                      "their traps have not filled (are the runs long enough?)")
    caution = ""
    for angle, _, levelled_at, duration in points[:PLATEAU_POINTS]:
        if math.isnan(duration):
            continue
        if math.isnan(levelled_at) or levelled_at > 0.5 * duration:
            if math.isnan(levelled_at):
                caution = (f"at {angle:g}, eta never reached 90% of its final level in the runs "
                           f"({duration:g} s): the plateau, and theta_c with it, may be too "
                           "low; run longer")
            else:
                caution = (f"at {angle:g}, eta was still rising in the second half of the runs "
                           f"(it reached 90% of its final level at {levelled_at:.3g} s of "
                           f"{duration:g} s): the plateau, and theta_c with it, may be too "
                           "low; run longer")
            break
    for i, ((a_angle, a_eta, _, _), (b_angle, b_eta, _, _)) in enumerate(zip(points, points[1:])):
        if a_eta >= half and b_eta < half:
            angle = a_angle + (a_eta - half) / (a_eta - b_eta) * (b_angle - a_angle)
            for wider, eta, _, _ in points[i + 2:]:
                if eta >= half:
                    caution += ("; " if caution else "") + (
                        f"at {wider:g}, beyond theta_c, eta is {eta:.3g}, above half the plateau "
                        "again: whether a wider trap fills within the runs depends on when a "
                        "pile nucleates; run longer, or more seeds")
                    break
            return {"angle": angle, "below": a_angle, "above": b_angle, "plateau": plateau,
                    "half": half, "caution": caution}, ""
    return None, f"eta never falls below half its low-angle plateau ({half:.3g})"


def find_column(table, candidates, what):
    for column in candidates:
        if table.has(column):
            return column
    raise PlotError(f"{table.path}: no column for {what} (looked for: {', '.join(candidates)}); "
                    f"the columns are: {', '.join(table.header)}")


def swept_column(table, ending):
    """The column of a swept key ending with `ending` ('trap.angle', 'kick_eps'), or None."""
    for column in table.header:
        if column == ending or column.endswith("." + ending):
            return column
    return None


class Sweep:
    """sweep.csv: time-averaged eta against the angle, one curve per combination of the other
    swept keys (seeds, and repeated points, averaged), as `rodsort summarize` groups them."""

    def __init__(self, sweep_dir):
        self.table = Table(os.path.join(sweep_dir, "sweep.csv"))
        self.species = species_names(sweep_dir)
        table = self.table
        self.angle_column = swept_column(table, "trap.angle")
        if self.angle_column is None:
            raise PlotError(f"{table.path}: the sweep is not over trap.angle (no such column); "
                            f"the columns are: {', '.join(table.header)}")
        self.eps_column = swept_column(table, "kick_eps")
        self.eta_column = find_column(table, ("eta_mean", "eta"), "the time-averaged eta")
        # The swept keys sit between `point` and `status`.
        if table.has("point") and table.has("status"):
            swept = table.header[table.header.index("point") + 1:table.header.index("status")]
        else:
            swept = [c for c in (self.angle_column, self.eps_column) if c]
        self.other_columns = [c for c in swept if c not in (self.angle_column, "seed")]
        if self.eps_column and self.eps_column not in self.other_columns:
            self.other_columns.append(self.eps_column)
        angles = table.numbers(self.angle_column)
        etas = table.numbers(self.eta_column)
        others = list(zip(*(table.text(c) for c in self.other_columns))) or [()] * len(angles)
        status = table.text("status") if table.has("status") else ["complete"] * len(angles)
        nans = [math.nan] * len(angles)
        levelled = table.numbers("eta_time_to_90_s") if table.has("eta_time_to_90_s") else nans
        durations = table.numbers("simulated_s") if table.has("simulated_s") else nans
        seeds = table.text("seed") if table.has("seed") else [None] * len(angles)
        self.skipped = 0
        # key -> angle -> [(eta, time to 90%, run length)] of its complete runs; and the same for
        # each seed's own curve, key -> seed -> angle -> [...]
        self.runs = {}
        self.seed_runs = {}
        self.seed_results = {}  # seed_curves' answers, by key
        for angle, eta, key, state, level, duration, seed in zip(angles, etas, others, status,
                                                                 levelled, durations, seeds):
            if math.isnan(eta) or state != "complete":
                self.skipped += 1
                continue
            run = (eta, level, duration)
            self.runs.setdefault(key, {}).setdefault(angle, []).append(run)
            if seed is not None:
                self.seed_runs.setdefault(key, {}).setdefault(seed, {}).setdefault(
                    angle, []).append(run)
        if not self.runs:
            raise PlotError(f"{table.path}: no complete point with a value of "
                            f"'{self.eta_column}'")
        # key (values of other_columns) -> sorted [(angle, mean eta, standard error, samples)]
        self.curves = {}
        for key, by_angle in self.runs.items():
            curve = []
            for angle in sorted(by_angle):
                values = [eta for eta, _, _ in by_angle[angle]]
                mean, spread = mean_and_standard_error(values)
                curve.append((angle, mean, spread, len(values)))
            self.curves[key] = curve

    def keys(self):
        """The curves' keys, in numeric order of their values where they are numbers."""
        def order(key):
            return [(0, float(v), "") if is_number(v) else (1, 0.0, v) for v in key]
        return sorted(self.curves, key=order)

    def value(self, key, column):
        return key[self.other_columns.index(column)]

    def label(self, key):
        parts = [physics_value(column, value, self.species)
                 for column, value in zip(self.other_columns, key)]
        return ", ".join(parts) or "all points"

    def critical_angles(self):
        """key -> (theta_c dict or None, reason)."""
        return {key: critical_angle(curve_points(self.runs[key])) for key in self.keys()}

    def seed_curves(self, key):
        """seed -> (theta_c dict or None, reason) of each seed's own curve, seeds in numeric
        order where they are numbers; found once per curve, as theta_c.csv, the figure and the
        seeds' files all ask for them."""
        if key not in self.seed_results:
            per_seed = self.seed_runs.get(key, {})
            order = sorted(per_seed,
                           key=lambda s: (0, float(s), "") if is_number(s) else (1, 0.0, s))
            self.seed_results[key] = {seed: critical_angle(curve_points(per_seed[seed]))
                                      for seed in order}
        return self.seed_results[key]

    def seed_critical_angles(self, key):
        """theta_c of each seed's own curve, as metrics::critical_angle_per_seed: (mean, standard
        error, how many seeds have one, how many seeds there are); mean and error are NaN when
        fewer than two seeds have one."""
        curves = self.seed_curves(key)
        found = [result["angle"] for result, _ in curves.values() if result]
        if len(found) < 2:
            return math.nan, math.nan, len(found), len(curves)
        mean, error = mean_and_standard_error(found)
        return mean, error, len(found), len(curves)


def curve_points(by_angle):
    """critical_angle's points from runs grouped by angle (angle -> [(eta, time to 90%, run
    length)]): the angle, the runs' mean eta, and, where the runs' lengths are known, the latest
    time to 90% (NaN once a run never got there) and the shortest run."""
    points = []
    for angle in sorted(by_angle):
        runs = by_angle[angle]
        latest, shortest = 0.0, math.inf
        for _, level, duration in runs:
            latest = math.nan if math.isnan(level) or math.isnan(latest) else max(latest, level)
            shortest = min(shortest, duration)
        mean = sum(eta for eta, _, _ in runs) / len(runs)
        if math.isnan(shortest) or math.isinf(shortest):
            points.append((angle, mean))
        else:
            points.append((angle, mean, latest, shortest))
    return points


def is_number(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


# ---------------------------------------------------------------------------------------------
# Plotting


def title_single_run(axes, runs):
    """A plot of one run is titled with its scenario's name."""
    if len(runs) == 1:
        axes.set_title(scenario_name(runs[0]), fontsize="medium")


def new_figure(plt):
    figure, axes = plt.subplots(figsize=(6.4, 4.0), layout="constrained")
    axes.grid(True, color="0.9", linewidth=0.6)
    return figure, axes


def save(plt, figure, out_dir, name, formats, written):
    for extension in formats:
        path = os.path.join(out_dir, f"{name}.{extension}")
        figure.savefig(path, dpi=120)
        written.append(path)
    plt.close(figure)


def mean_and_standard_error(values):
    """The mean of values and its standard error (sample standard deviation over the square root
    of their number); the error is 0 for a single value."""
    mean = sum(values) / len(values)
    if len(values) < 2:
        return mean, 0.0
    variance = sum((v - mean) ** 2 for v in values) / (len(values) - 1)
    return mean, math.sqrt(variance / len(values))


def run_metrics(run_dir, until):
    """A run's metrics.csv, its rows up to t = until [s] when until is given."""
    table = Table(os.path.join(run_dir, "metrics.csv"))
    if until is not None:
        table.rows = [row for row, t in zip(table.rows, table.numbers("t")) if t <= until]
    return table


def plot_eta(plt, runs, out_dir, formats, written, until):
    figure, axes = new_figure(plt)
    several = len(runs) > 1
    for index, run_dir in enumerate(runs):
        table = run_metrics(run_dir, until)
        t = table.numbers("t")
        eta = table.numbers("eta", "eta(t)")
        label = run_label(run_dir, runs) if several else "all rods"
        line_colour = colour(index) if several else "black"
        axes.plot(t, eta, color=line_colour, linewidth=1.2, linestyle=run_line_style(index),
                  label=label)
        if several:
            continue
        if table.has("eta_trap"):
            axes.plot(t, table.numbers("eta_trap"), color="0.5", linewidth=1.0, linestyle="--",
                      label="inside the trap")
        species = metrics_species(table)
        if len(species) > 1:
            for s, name in enumerate(species):
                column = f"eta_{name}"
                if table.has(column):
                    axes.plot(t, table.numbers(column), color=colour(s), linewidth=1.0,
                              label=name)
    axes.set_xlabel("t [s]")
    axes.set_ylabel("trapping efficiency η")
    axes.set_ylim(bottom=0.0)
    axes.legend(frameon=False, fontsize="small")
    title_single_run(axes, runs)
    save(plt, figure, out_dir, "eta", formats, written)


def plot_population(plt, runs, out_dir, formats, written, until):
    figure, axes = new_figure(plt)
    held_drawn = False
    several = len(runs) > 1
    for index, run_dir in enumerate(runs):
        table = run_metrics(run_dir, until)
        t = table.numbers("t")
        species = metrics_species(table)
        if not species:
            raise PlotError(f"{table.path}: no per-species columns (purity_<species>); "
                            f"the columns are: {', '.join(table.header)}")
        for s, name in enumerate(species):
            line_colour = colour(index if several else s)
            label = f"{run_label(run_dir, runs)}: {name}" if several else name
            axes.plot(t, table.numbers(f"n_trap_{name}", "rods inside the trap"),
                      color=line_colour, linewidth=1.2, label=label)
            if table.has(f"n_stationary_trap_{name}"):
                axes.plot(t, table.numbers(f"n_stationary_trap_{name}"), color=line_colour,
                          linewidth=1.0, linestyle="--")
            if table.has(f"n_held_trap_{name}"):
                axes.plot(t, table.numbers(f"n_held_trap_{name}"), color=line_colour,
                          linewidth=1.0, linestyle=":")
                held_drawn = True
    axes.plot([], [], color="0.4", linestyle="--", label="stationary")
    if held_drawn:
        axes.plot([], [], color="0.4", linestyle=":", label="held")
    axes.set_xlabel("t [s]")
    axes.set_ylabel("rods inside the trap")
    axes.set_ylim(bottom=0.0)
    axes.legend(frameon=False, fontsize="small")
    title_single_run(axes, runs)
    save(plt, figure, out_dir, "population", formats, written)


# Half-widths of the P(dtheta) axis [degrees]: the smallest that holds every change is used, so
# that the narrow distributions of trapped rods are not squeezed into a few bins.
DTHETA_RANGES = (10, 20, 30, 45, 60, 90, 120, 180)
DTHETA_BINS = 120


def plot_dtheta(plt, runs, out_dir, formats, written, tau):
    lines = []  # (label, colour, line style, values)
    spans = set()
    several = len(runs) > 1
    for index, run_dir in enumerate(runs):
        changes, _, span = orientation_changes(run_dir, tau)
        spans.add(round(span, 6))
        # Species in the order of their first rod, which is their index order in rods.csv.
        for s, name in enumerate(changes):
            label = run_label(run_dir, runs) if several else name
            if several and len(changes) > 1:
                label = f"{run_label(run_dir, runs)}: {name}"
            lines.append((label, colour(index if several else s),
                          run_line_style(index) if several else "-", changes[name]))
    largest = max((abs(v) for _, _, _, values in lines for v in values), default=0.0)
    half_width = next((r for r in DTHETA_RANGES if largest <= r), 180)
    edges = [-half_width + 2.0 * half_width * k / DTHETA_BINS for k in range(DTHETA_BINS + 1)]
    figure, axes = new_figure(plt)
    for label, line_colour, style, values in lines:
        axes.hist(values, bins=edges, density=True, histtype="step", linewidth=1.2,
                  color=line_colour, linestyle=style, label=label)
    span_text = ", ".join(f"{span:g}" for span in sorted(spans))
    axes.set_yscale("log")
    axes.set_xlim(-half_width, half_width)
    axes.set_xlabel(f"Δθ over {span_text} s [degrees]")
    axes.set_ylabel("P(Δθ) [1/degree]")
    axes.legend(frameon=False, fontsize="small")
    title_single_run(axes, runs)
    save(plt, figure, out_dir, "dtheta", formats, written)


def plot_eta_theta(plt, sweep, out_dir, formats, written):
    figure, axes = new_figure(plt)
    critical = sweep.critical_angles()
    for index, key in enumerate(sweep.keys()):
        curve = sweep.curves[key]
        line_colour = colour(index)
        result, _ = critical[key]
        label = sweep.label(key)
        if result:
            label += f": θc = {result['angle']:.1f}°"
            if result["caution"]:
                reasons = []
                if "still rising" in result["caution"] or "never reached" in result["caution"]:
                    reasons.append("η still rising")
                if "beyond theta_c" in result["caution"]:
                    reasons.append("a wider trap fills")
                # On a line of its own, so that the legend stays within the axes' width.
                label += f"\n(unreliable: {', '.join(reasons)}; see theta_c.csv)"
            axes.axvline(result["angle"], color=line_colour, linestyle=":", linewidth=1.0)
        axes.errorbar([p[0] for p in curve], [p[1] for p in curve], yerr=[p[2] for p in curve],
                      color=line_colour, marker="o", markersize=4, linewidth=1.2, capsize=2,
                      label=label)
    axes.set_xlabel("trap opening angle θ [degrees]")
    axes.set_ylabel("η, mean over the last half of each run")
    axes.set_ylim(bottom=0.0)
    axes.legend(frameon=False, fontsize="small")
    save(plt, figure, out_dir, "eta-theta", formats, written)


def plot_thetac_eps(plt, sweep, out_dir, formats, written):
    eps_values = {sweep.value(key, sweep.eps_column) for key in sweep.curves} \
        if sweep.eps_column else set()
    if len(eps_values) < 2:
        raise PlotError(f"{sweep.table.path}: theta_c against eps needs a sweep over "
                        "species[...].noise.kick_eps with at least two values")
    # One line per combination of the swept keys other than eps. A noise level where two seeds
    # or more have a theta_c of their own shows their mean and its standard error (the error bar
    # rodsort summarize gives); one without shows the seeds' mean curve's theta_c, its bar
    # spanning the two angles that bracket the drop.
    families = {}
    for key, (result, _) in sweep.critical_angles().items():
        if not result:
            continue
        family = tuple(v for c, v in zip(sweep.other_columns, key) if c != sweep.eps_column)
        mean, error, found, _ = sweep.seed_critical_angles(key)
        if found >= 2:
            point = (mean, error, error, True)
        else:
            point = (result["angle"], result["angle"] - result["below"],
                     result["above"] - result["angle"], False)
        families.setdefault(family, []).append((float(sweep.value(key, sweep.eps_column)),)
                                               + point)
    if not families:
        raise PlotError(f"{sweep.table.path}: no noise level has a critical angle "
                        "(see theta_c.csv for why)")
    family_columns = [c for c in sweep.other_columns if c != sweep.eps_column]
    figure, axes = new_figure(plt)
    kinds_drawn = set()
    for index, (family, points) in enumerate(sorted(families.items())):
        points.sort(key=lambda point: point[0])
        line_colour = "black" if len(families) == 1 else colour(index)
        label = ", ".join(physics_value(c, v, sweep.species)
                          for c, v in zip(family_columns, family)) or None
        axes.plot([p[0] for p in points], [p[1] for p in points], color=line_colour,
                  linewidth=1.2, label=label)
        for over_seeds in (True, False):
            chosen = [p for p in points if p[4] == over_seeds]
            if not chosen:
                continue
            kinds_drawn.add(over_seeds)
            axes.errorbar([p[0] for p in chosen], [p[1] for p in chosen],
                          yerr=[[p[2] for p in chosen], [p[3] for p in chosen]],
                          color=line_colour, linestyle="none", marker="o" if over_seeds else "s",
                          markerfacecolor=line_colour if over_seeds else "white",
                          markersize=5, capsize=3)
    # What the markers and bars are, as legend entries of their own.
    for over_seeds in sorted(kinds_drawn, reverse=True):
        axes.errorbar([], [], yerr=[], color="0.3", linestyle="none",
                      marker="o" if over_seeds else "s",
                      markerfacecolor="0.3" if over_seeds else "white", markersize=5, capsize=3,
                      label="θc of each seed: mean ± standard error" if over_seeds else
                      "θc of the seeds' mean η; bar: the angles that bracket the drop")
    axes.set_xlabel(physics_name(sweep.eps_column, sweep.species))
    axes.set_ylabel("critical angle θc [degrees]")
    axes.legend(frameon=False, fontsize="small")
    save(plt, figure, out_dir, "thetac-eps", formats, written)


def plot_measures(plt, sweep_dir, out_dir, formats, written):
    """The plateau means of sweep.csv against the first swept key (other than the seed) whose
    values are numbers; one set of lines per combination of the other swept keys."""
    table = Table(os.path.join(sweep_dir, "sweep.csv"))
    species = species_names(sweep_dir)
    if not (table.has("point") and table.has("status")):
        raise PlotError(f"{table.path}: no point and status columns; is it rodsort's sweep.csv?")
    swept = table.header[table.header.index("point") + 1:table.header.index("status")]
    keys = [c for c in swept if c != "seed"]
    numeric = [c for c in keys if all(is_number(v) for v in table.text(c))]
    if not numeric:
        raise PlotError(f"{table.path}: no swept key with numeric values to plot against "
                        f"(swept: {', '.join(swept)})")
    x_column = numeric[0]
    others = [c for c in keys if c != x_column]
    purities = [c for c in table.header if c.startswith("purity_") and c.endswith("_mean")
                and not c.startswith("purity_held_")]
    held = [c for c in table.header if c.startswith("purity_held_") and c.endswith("_mean")]
    measures = [c for c in ("eta_mean", "eta_trap_mean", "sorting_index_mean") if table.has(c)]
    if len(purities) > 1:
        measures += purities[:1]
    if len(held) > 1:
        measures += held[:1]
    names = {"eta_mean": "η", "eta_trap_mean": "η in the trap",
             "sorting_index_mean": "sorting index S"}
    names.update({c: f"purity of {c[len('purity_held_'):-len('_mean')]} among the held rods"
                  for c in held})
    status = table.text("status")
    x_values = table.numbers(x_column)
    groups = list(zip(*(table.text(c) for c in others))) or [()] * len(x_values)
    figure, axes = new_figure(plt)
    line = 0
    for group in sorted(set(groups)):
        for measure in measures:
            values = table.numbers(measure)
            by_x = {}
            for x, value, key, state in zip(x_values, values, groups, status):
                if key == group and state == "complete" and not math.isnan(value):
                    by_x.setdefault(x, []).append(value)
            if not by_x:
                continue
            xs = sorted(by_x)
            means, errors = zip(*(mean_and_standard_error(by_x[x]) for x in xs))
            label = names.get(measure, measure[:-len("_mean")].replace("purity_", "purity of "))
            if group:
                label += " (" + ", ".join(physics_value(c, v, species)
                                          for c, v in zip(others, group)) + ")"
            axes.errorbar(xs, means, yerr=errors, color=colour(line), marker="o", markersize=4,
                          linewidth=1.2, capsize=2, label=label)
            line += 1
    if line == 0:
        raise PlotError(f"{table.path}: no complete point to plot")
    axes.set_xlabel(physics_name(x_column, species))
    axes.set_ylabel("mean over the last half of each run")
    axes.axhline(0.0, color="0.6", linewidth=0.8)
    axes.legend(frameon=False, fontsize="small")
    save(plt, figure, out_dir, "measures", formats, written)


def write_critical_angles(sweep, out_dir, written):
    """theta_c.csv: one row per curve, its swept values, then theta_c and the bracketing angles
    [degrees], the plateau eta, and why theta_c was not found when it was not; then the mean and
    standard error of the seeds' own theta_c and how many seeds have one (as critical_angle.csv)."""
    path = os.path.join(out_dir, "theta_c.csv")
    with open(path, "w", newline="") as stream:
        writer = csv.writer(stream, lineterminator="\n")
        writer.writerow(sweep.other_columns + ["theta_c", "below", "above", "plateau", "reason",
                                               "theta_c_seed_mean", "theta_c_seed_stderr",
                                               "seeds_found"])
        for key, (result, reason) in sweep.critical_angles().items():
            if result:
                note = f"caution: {result['caution']}" if result["caution"] else ""
                row = list(key) + [f"{result[k]:.9g}" for k in
                                   ("angle", "below", "above", "plateau")] + [note]
            else:
                row = list(key) + ["nan", "nan", "nan", "nan", reason]
            mean, error, found, seeds = sweep.seed_critical_angles(key)
            row += [f"{mean:.9g}", f"{error:.9g}", f"{found} of {seeds}" if seeds >= 2 else ""]
            writer.writerow(row)
    written.append(path)
    # Files of an earlier plot into the same directory would otherwise outlive their data.
    for stale in ("theta_c_seeds.csv", "theta_c_paired.csv"):
        stale_path = os.path.join(out_dir, stale)
        if os.path.isfile(stale_path):
            os.remove(stale_path)
    if not any(len(sweep.seed_curves(key)) >= 2 for key in sweep.keys()):
        return
    # Each seed's own theta_c, and the differences between curves seed by seed.
    path = os.path.join(out_dir, "theta_c_seeds.csv")
    with open(path, "w", newline="") as stream:
        writer = csv.writer(stream, lineterminator="\n")
        writer.writerow(sweep.other_columns + ["seed", "theta_c", "reason"])
        for key in sweep.keys():
            for seed, (result, reason) in sweep.seed_curves(key).items():
                if result:
                    note = f"caution: {result['caution']}" if result["caution"] else ""
                    writer.writerow(list(key) + [seed, f"{result['angle']:.9g}", note])
                else:
                    writer.writerow(list(key) + [seed, "nan", reason])
    written.append(path)
    write_paired_differences(sweep, out_dir, written)


def write_paired_differences(sweep, out_dir, written):
    """theta_c_paired.csv: for every two curves with two seeds or more that both have a theta_c
    of their own, the mean and standard error of theta_c(curve) - theta_c(reference) over those
    seeds; the reference is the curve that comes first in the curves' order (the lower noise).
    Where a seed starts from the same state in both curves (its rods are placed alike at every
    noise), the difference seed by seed compares like with like."""
    found = {}
    for key in sweep.keys():
        found[key] = {seed: result["angle"] for seed, (result, _) in
                      sweep.seed_curves(key).items() if result}
    rows = []
    keys = sweep.keys()
    for i, reference in enumerate(keys):
        for key in keys[i + 1:]:
            shared = [seed for seed in found[key] if seed in found[reference]]
            if len(shared) < 2:
                continue
            differences = [found[key][seed] - found[reference][seed] for seed in shared]
            mean, error = mean_and_standard_error(differences)
            rows.append(list(key) + list(reference) +
                        [f"{mean:.9g}", f"{error:.9g}", len(shared), " ".join(shared)])
    if not rows:
        return
    path = os.path.join(out_dir, "theta_c_paired.csv")
    with open(path, "w", newline="") as stream:
        writer = csv.writer(stream, lineterminator="\n")
        writer.writerow(sweep.other_columns + [f"reference_{c}" for c in sweep.other_columns] +
                        ["difference_mean", "difference_stderr", "seeds_paired", "seeds"])
        writer.writerows(rows)
    written.append(path)


def study_label(study_dir):
    summary = Table(os.path.join(study_dir, "summary.csv"))
    return f"{run_label(study_dir)} ({summary.text('species')[0]})"


def plot_axial_velocity(plt, studies, out_dir, formats, written):
    figure, axes = new_figure(plt)
    for index, study_dir in enumerate(studies):
        table = Table(os.path.join(study_dir, "axial_velocity.csv"))
        summary = Table(os.path.join(study_dir, "summary.csv"))
        v0 = summary.numbers("v0_mm_s")[0]
        axes.step(table.numbers("vx_mm_s"), table.numbers("density_s_mm"), where="mid",
                  color=colour(index), linewidth=1.2,
                  label=f"{study_label(study_dir)}: v0 = {v0:.2f} mm/s")
    axes.axvspan(3.6 - 2.5, 3.6 + 2.5, color="0.85", zorder=0,
                 label="experiments, rod A: 3.6 ± 2.5 mm/s")
    axes.set_xlabel("axial velocity V_x over the window [mm/s] (+: toward the thin end)")
    axes.set_ylabel("P(V_x) [s/mm]")
    axes.set_ylim(bottom=0.0)
    axes.legend(frameon=False, fontsize="small")
    save(plt, figure, out_dir, "axial_velocity", formats, written)


def plot_msd(plt, studies, out_dir, formats, written):
    figure, (left, right) = plt.subplots(1, 2, figsize=(9.6, 4.0), layout="constrained")
    for axes in (left, right):
        axes.grid(True, color="0.9", linewidth=0.6)
    for index, study_dir in enumerate(studies):
        table = Table(os.path.join(study_dir, "lags.csv"))
        lag = table.numbers("lag_s")
        left.loglog(lag, table.numbers("position_msd_mm2"), color=colour(index), linewidth=1.2,
                    label=study_label(study_dir))
        right.plot(lag, table.numbers("orientation_correlation"), color=colour(index),
                   linewidth=1.2, label=study_label(study_dir))
    left.set_xlabel("lag [s]")
    left.set_ylabel("mean squared displacement [mm²]")
    right.set_xlabel("lag [s]")
    right.set_ylabel("heading correlation ⟨cos Δφ⟩")
    left.legend(frameon=False, fontsize="small")
    save(plt, figure, out_dir, "msd", formats, written)


# ---------------------------------------------------------------------------------------------


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        prog="rodsort plot", description=__doc__.split("\n\n")[0],
        epilog="Kinds: " + ", ".join(RUN_KINDS) + " (run directories); " +
        ", ".join(SWEEP_KINDS) + " (a sweep directory); " + ", ".join(STUDY_KINDS) +
        " (single-particle study directories).")
    parser.add_argument("paths", nargs="+", metavar="RUN_DIR|SWEEP_DIR",
                        help="run directories (metrics.csv, rods.csv) or one sweep directory "
                        "(sweep.csv)")
    parser.add_argument("--what", default="",
                        help="comma-separated kinds to draw (default: every kind the input has)")
    parser.add_argument("-o", "--output", default="",
                        help="directory for the plots (default: PATH/plots, or ./plots for "
                        "several runs)")
    parser.add_argument("--format", default="png,svg", help="comma-separated: png, svg, pdf")
    parser.add_argument("--tau", type=float, default=0.07,
                        help="window of P(dtheta) in seconds (default 0.07, the paper's)")
    parser.add_argument("--until", type=float, default=None,
                        help="eta and population of runs: draw up to this time [s] (runs of "
                        "different lengths on one time axis)")
    return parser.parse_args(argv)


def main(argv):
    arguments = parse_arguments(argv)
    paths = arguments.paths
    for path in paths:
        if not os.path.isdir(path):
            raise UsageError(f"{path}: not a directory")
    is_study = [os.path.isfile(os.path.join(p, "lags.csv")) for p in paths]
    study_mode = any(is_study)
    if study_mode and not all(is_study):
        raise UsageError("give single-particle study directories (lags.csv) alone")
    is_sweep = [os.path.isfile(os.path.join(p, "sweep.csv")) for p in paths]
    if any(is_sweep) and len(paths) > 1:
        raise UsageError("give one sweep directory, or one or more run directories")
    sweep_mode = is_sweep[0]
    if not sweep_mode and not study_mode:
        for path in paths:
            if not os.path.isfile(os.path.join(path, "metrics.csv")):
                raise UsageError(f"{path}: neither a run directory (metrics.csv) nor a sweep "
                                "directory (sweep.csv)")
    allowed = STUDY_KINDS if study_mode else SWEEP_KINDS if sweep_mode else RUN_KINDS
    kinds = [k.strip() for k in arguments.what.split(",") if k.strip()]
    kinds_of = {"run": RUN_KINDS, "sweep": SWEEP_KINDS, "single-particle study": STUDY_KINDS}
    mode = "single-particle study" if study_mode else "sweep" if sweep_mode else "run"
    for kind in kinds:
        if kind not in allowed:
            owner = next((name for name, owned in kinds_of.items() if kind in owned), None)
            hint = f" ('{kind}' is drawn from a {owner} directory)" if owner else ""
            raise UsageError(f"--what: unknown kind '{kind}' for a {mode} directory{hint}; "
                             f"expected some of: {', '.join(allowed)}")
    explicit = bool(kinds)
    kinds = kinds or list(allowed)
    formats = [f.strip() for f in arguments.format.split(",") if f.strip()]
    for extension in formats:
        if extension not in ("png", "svg", "pdf"):
            raise UsageError(f"--format: unknown format '{extension}'; expected png, svg or pdf")
    if not arguments.tau > 0.0:
        raise UsageError(f"--tau: must be positive, got {arguments.tau}")
    if arguments.until is not None and not arguments.until > 0.0:
        raise UsageError(f"--until: must be positive, got {arguments.until}")

    out_dir = arguments.output or (os.path.join(paths[0], "plots") if len(paths) == 1
                                   else "plots")
    os.makedirs(out_dir, exist_ok=True)

    try:
        import matplotlib
    except ImportError:
        raise PlotError(f"matplotlib is not installed for {sys.executable}: install Debian's "
                        "python3-matplotlib (scripts/install-deps does), or point RODSORT_PYTHON "
                        "at a python that has it") from None
    matplotlib.use("Agg")
    matplotlib.rcParams["svg.hashsalt"] = "rodsort"  # identical SVGs for identical data
    matplotlib.rcParams["svg.fonttype"] = "none"  # text stays text, editable in a paper's figure
    import matplotlib.pyplot as plt

    written = []
    if sweep_mode:
        over_angle = swept_column(Table(os.path.join(paths[0], "sweep.csv")), "trap.angle")
        sweep = None
        if over_angle and any(kind != "measures" for kind in kinds):
            sweep = Sweep(paths[0])
            if sweep.skipped:
                print(f"note: {sweep.skipped} point(s) of {sweep.table.path} not complete or "
                      "without eta were left out", file=sys.stderr)
            write_critical_angles(sweep, out_dir, written)
        for kind in kinds:
            try:
                if kind == "measures":
                    # Beside eta-theta, a sweep over the angle alone needs no second figure.
                    if over_angle and not explicit:
                        continue
                    plot_measures(plt, paths[0], out_dir, formats, written)
                elif sweep is None:
                    if not explicit:
                        continue
                    raise PlotError(f"{os.path.join(paths[0], 'sweep.csv')}: the sweep is not "
                                    "over trap.angle; `--what measures` plots it against its "
                                    "swept key")
                elif kind == "eta-theta":
                    plot_eta_theta(plt, sweep, out_dir, formats, written)
                else:
                    plot_thetac_eps(plt, sweep, out_dir, formats, written)
            except PlotError as error:
                if explicit:
                    raise
                print(f"note: no {kind} plot: {error}", file=sys.stderr)
    else:
        for kind in kinds:
            try:
                if kind == "axial-velocity":
                    plot_axial_velocity(plt, paths, out_dir, formats, written)
                elif kind == "msd":
                    plot_msd(plt, paths, out_dir, formats, written)
                elif kind == "eta":
                    plot_eta(plt, paths, out_dir, formats, written, arguments.until)
                elif kind == "population":
                    plot_population(plt, paths, out_dir, formats, written, arguments.until)
                else:
                    plot_dtheta(plt, paths, out_dir, formats, written, arguments.tau)
            except PlotError as error:
                if explicit:
                    raise
                print(f"note: no {kind} plot: {error}", file=sys.stderr)
    for path in written:
        print(f"wrote {path}")
    if not written:
        raise PlotError("nothing to plot")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except PlotError as error:
        print(f"rodsort plot: error: {error}", file=sys.stderr)
        sys.exit(2 if isinstance(error, UsageError) else 1)
