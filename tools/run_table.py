"""Reading the points (noise, angle, seed) of runs listed in a `rodsort summarize --csv` table,
for the scripts that gather runs kept only as such tables in docs/data."""
import re
import sys
from pathlib import Path


RUN_NAME = re.compile(r"eps([0-9.]+)-(\d+)-seed(\d+)$")
ANGLE_NAME = re.compile(r"(?:^|_)angle-(\d+(?:\.\d+)?)(?:_|$)")


class NoiseMismatch(ValueError):
    """A run's directory is named for another noise than the one its table was given."""


def run_point(run, seed, eps=None):
    """(eps, angle, seed) as strings for one row's run directory and seed column, or None where
    the name tells no point. Without eps, the point is read from a name eps<EPS>-<ANGLE>-seed<SEED>;
    with it (a table given as EPS=TABLE.csv), the angle is read from angle-<ANGLE>, as
    `rodsort sweep` names its points, or from such a name of that eps, and the seed from the seed
    column. Raises NoiseMismatch where a name is of another eps than the one given."""
    name = Path(run.rstrip("/")).name
    named, by_angle = RUN_NAME.search(name), ANGLE_NAME.search(name)
    if named and eps is not None and float(named[1]) != float(eps):
        raise NoiseMismatch(f"run {run} is named for eps {named[1]}, but the table was given as "
                            f"eps {eps}")
    if named:
        return (named[1] if eps is None else eps, named[2], named[3])
    if eps is not None and by_angle:
        return (eps, f"{float(by_angle[1]):g}", seed)
    return None


def split_argument(table):
    """(eps or None, path) of a TABLE or EPS=TABLE argument; ValueError where EPS is no number."""
    eps, _, path = table.rpartition("=")
    if not eps:
        return None, path
    try:
        float(eps)
    except ValueError:
        raise ValueError(f"{table}: the noise before '=' must be a number (EPS=TABLE.csv), "
                         f"not {eps!r}") from None
    return eps, path


def require_columns(path, reader, wanted, expected=None):
    """Exits, naming the table, where the header of a csv.DictReader lacks one of the wanted
    columns; expected says what table was wanted (by default, one with those columns)."""
    missing = [name for name in wanted if name not in (reader.fieldnames or [])]
    if missing:
        sys.exit(f"{path}: line 1: no column {', '.join(missing)} (expected "
                 f"{expected or 'a table with the columns ' + ', '.join(wanted)})")


def report_unnamed(path, unnamed):
    """Says on stderr how many rows of a table were left out for want of a point in their name."""
    if unnamed:
        print(f"{path}: {unnamed} row(s) with no eps<EPS>-<ANGLE>-seed<SEED> name (or, given as "
              f"EPS=, no angle-<ANGLE>), left out", file=sys.stderr)
