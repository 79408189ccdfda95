"""Shared by the figure scripts (plot_mac.py, plot_frf.py, plot_simulation.py): reading the CSV and
MAT files `tvd` writes, one-line errors for bad input (exit status 2), option types, LABEL=FILE
arguments, checking the outputs before anything is plotted and writing the figures."""
import argparse
import csv
import io
import json
import logging
import math
import os
import struct
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import scipy.io  # noqa: E402
from matplotlib.backends.backend_agg import FigureCanvasAgg  # noqa: E402

# Figure types --out may name by its extension (any case); raw/rgba are headerless pixel dumps and
# pgf needs a LaTeX installation.
FIGURE_TYPES = sorted(set(FigureCanvasAgg.get_supported_filetypes()) - {"raw", "rgba", "pgf"})
# .eps/.ps: the grid's transparency is drawn opaque, which is fine; no warning on stderr.
logging.getLogger("matplotlib.backends.backend_ps").setLevel(logging.ERROR)
OUT_HELP = ("the figure type follows the extension: .png, .pdf, .svg (also "
            + ", ".join("." + t for t in FIGURE_TYPES if t not in ("png", "pdf", "svg")) + ")")
LABELLED_HELP = ("one line per file, named LABEL in the legend. FILE is a CSV file or a .mat file "
                 "written by tvd (one n x 1 variable per column, named like the CSV header). "
                 "Without 'LABEL=' the legend shows the file's base name. An argument that names "
                 "an existing file is always a bare FILE, even if it contains '='; otherwise the "
                 "text before the first '=' is the LABEL (so 'LABEL=dir/a=b.csv' also works)")


def fail(message):
    """One error line on stderr, exit status 2 (bad input)."""
    sys.stderr.write(f"{os.path.basename(sys.argv[0])}: error: {message}\n")
    sys.exit(2)


class ArgumentParser(argparse.ArgumentParser):
    """Usage errors are one line too (`--help` shows the usage), exit status 2."""

    def error(self, message):
        fail(message)


def to_float(text):
    """float(text), or NaN when it is not a number (callers reject what is not finite)."""
    try:
        return float(text)
    except ValueError:
        return math.nan


def positive_float(text):
    """argparse type: a finite number > 0."""
    value = to_float(text)
    if not (math.isfinite(value) and value > 0):
        raise argparse.ArgumentTypeError(f"'{text}' is not a finite number > 0")
    return value


def vehicle_view(ax, axis, horizontal=0):
    """Axes of a view of the vehicle: x forward (horizontal 0) or y (1, a front view seen from
    ahead: the vehicle's left, +y, on the right) against y (axis 1, top view) or z (axis 2),
    equal scales (REP-103 frame)."""
    ax.set_xlabel("x [m] (forward)" if horizontal == 0 else "y [m] (left)")
    ax.set_ylabel("z [m] (up)" if axis == 2 else "y [m] (left)")
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, alpha=0.3)


def reason(error):
    """The human part of an exception, for '(...)' in an error line."""
    text = getattr(error, "strerror", None) or str(error) or type(error).__name__
    return text.strip().splitlines()[0] if text.strip() else type(error).__name__


# --- JSON documents (`tvd ... --json`) ----------------------------------------------------------

def read_json(path):
    """The JSON document in `path`; one error line when it cannot be read or is not JSON."""
    try:
        with open(path, encoding="utf-8-sig") as stream:
            return json.load(stream)
    except OSError as error:
        fail(f"{path}: cannot read ({reason(error)})")
    except ValueError as error:
        fail(f"{path}: not JSON ({reason(error)})")


def json_number(path, what, value):
    """`value` as a float; one error line naming `what` when it is not a finite number."""
    if not isinstance(value, (int, float)) or isinstance(value, bool) or not math.isfinite(value):
        fail(f"{path}: {what} is not a finite number ({value!r})")
    return float(value)


# --- MAT files ---------------------------------------------------------------------------------

def mat_truncation(path):
    """A description of how a MAT v5 file is cut short, or None if its elements fit in the file
    (or it is not a v5 file). Walks the top-level data element tags after the 128-byte header."""
    try:
        with open(path, "rb") as stream:
            data = stream.read()
    except OSError:
        return None
    if len(data) < 128:
        return f"the file has {len(data)} bytes, less than the 128-byte MAT header"
    endian = {b"IM": "<", b"MI": ">"}.get(data[126:128])
    if endian is None:
        return None
    offset, index = 128, 1
    while offset < len(data):
        if offset + 8 > len(data):
            return f"the file ends inside the tag of data element {index}"
        kind, size = struct.unpack(endian + "II", data[offset:offset + 8])
        if kind >> 16:  # small data element: type and size packed in 4 bytes, data in the next 4
            offset += 8
        else:
            end = offset + 8 + size
            if end > len(data):
                return f"the file has {len(data)} bytes, its data element {index} needs {end}"
            offset = end if kind == 15 else end + (-size % 8)  # miCOMPRESSED is not padded
        index += 1
    return None


def load_mat(path, variable_names=None):
    """The variables of a MAT file (all, or the named ones); any read failure is one line naming
    the file: 'cannot read MAT file (...)', 'truncated' when the file is cut short."""
    if os.path.isdir(path):
        fail(f"{path}: cannot read MAT file (it is a directory)")
    try:
        try:
            # tvd writes text as UTF-16 code units, as MATLAB does; SciPy's default codec keeps
            # one byte of each. A character beyond U+FFFF (a surrogate pair) defeats that codec.
            data = scipy.io.loadmat(path, variable_names=variable_names,
                                    uint16_codec="utf-16-le")
        except Exception:  # noqa: BLE001 - then as SciPy reads it by default (or fails)
            data = scipy.io.loadmat(path, variable_names=variable_names)
    except Exception as error:  # noqa: BLE001 - corrupt files raise zlib.error, struct.error, ...
        if isinstance(error, OSError) and not os.path.isfile(path):
            fail(f"{path}: cannot read MAT file ({reason(error)})")
        truncated = mat_truncation(path)
        if truncated:
            fail(f"{path}: cannot read MAT file (truncated: {truncated})")
        what = "" if isinstance(error, OSError) else "corrupt or not a MAT file: "
        fail(f"{path}: cannot read MAT file ({what}{reason(error)})")
    missing = [n for n in variable_names or () if n not in data]
    if missing:
        truncated = mat_truncation(path)
        if truncated:
            fail(f"{path}: cannot read MAT file (truncated: {truncated})")
    return data


def is_mat(path):
    """True for a .mat name (any case) or a file that starts with a MAT v5/v7.3 header."""
    if path.lower().endswith(".mat"):
        return True
    try:
        with open(path, "rb") as stream:
            return stream.read(7) == b"MATLAB "
    except OSError:
        return False


# --- tables: CSV or MAT ------------------------------------------------------------------------

class Table:
    """Named numeric columns of one CSV or MAT file; `header` lists the column names."""

    def __init__(self, path):
        self.path = path
        if is_mat(path):
            self._read_mat()
        else:
            self._read_csv()

    def _read_csv(self):
        path = self.path
        if os.path.isdir(path):
            fail(f"{path}: cannot read CSV (it is a directory)")
        try:
            with open(path, newline="", encoding="utf-8-sig") as stream:
                reader = csv.reader(stream)
                rows = [(reader.line_num, row) for row in reader if row]
        except (OSError, UnicodeDecodeError, csv.Error) as error:
            fail(f"{path}: cannot read CSV ({reason(error)})")
        if len(rows) < 2:
            fail(f"{path}: no data rows")
        self.header = [name.strip() for name in rows[0][1]]
        check_unique(path, self.header)
        for line, row in rows[1:]:
            if len(row) != len(self.header):
                fail(f"{path}: line {line} has {len(row)} fields, the header has "
                     f"{len(self.header)}")
        self._rows = rows[1:]
        self._columns = None

    def _read_mat(self):
        data = load_mat(self.path)
        vectors, self._other = {}, set()
        for name, value in data.items():
            if name.startswith("__"):
                continue
            if (isinstance(value, np.ndarray) and value.dtype.kind in "iuf"
                    and (value.ndim == 1 or (value.ndim == 2 and 1 in value.shape))):
                vectors[name] = value.ravel().astype(float)
            elif not (isinstance(value, np.ndarray) and value.dtype.kind in "US"):
                self._other.add(name)  # not char metadata: named if a column of it is asked for
        rows = max((v.size for v in vectors.values()), default=0)
        if rows == 0:
            fail(f"{self.path}: no data rows (no numeric n x 1 variable)")
        self._columns = {}
        for name, values in vectors.items():
            if values.size == rows:
                self._columns[name] = values
            elif values.size != 1:  # numeric scalars are metadata
                fail(f"{self.path}: variable '{name}' has {values.size} entries, the others "
                     f"{rows}: not a table of equal columns (the .mat of a tvd simulate, frf or "
                     f"statics --out)")
        self.header = list(self._columns)

    def column(self, name):
        """The column called `name` as a float array; fails if it is missing or not finite."""
        path = self.path
        if self._columns is not None:
            if name in self._other:
                fail(f"{path}: variable '{name}' is not a numeric n x 1 vector")
            if name not in self._columns:
                fail(f"{path}: missing variable '{name}'")
            values = self._columns[name]
            bad = np.flatnonzero(~np.isfinite(values))
            if bad.size:
                fail(f"{path}: variable '{name}', row {bad[0] + 1}: {values[bad[0]]} is not a "
                     f"finite number")
            return values
        if name not in self.header:
            fail(f"{path}: missing column '{name}'")
        j = self.header.index(name)
        values = []
        for line, row in self._rows:
            text = row[j].strip()
            value = to_float(text)
            if not math.isfinite(value):
                fail(f"{path}: line {line}, column '{name}': '{text}' is not a finite number")
            values.append(value)
        return np.array(values)

    def text(self, name):
        """The column called `name` as strings (CSV files; e.g. the mode types of modes.csv)."""
        if self._columns is not None or name not in self.header:
            fail(f"{self.path}: missing text column '{name}'")
        j = self.header.index(name)
        return [row[j].strip() for _, row in self._rows]

    def where(self, line_or_row):
        """'line L' (CSV) or 'row R' (MAT) of the k-th data row (0-based)."""
        if self._columns is not None:
            return f"row {line_or_row + 1}"
        return f"line {self._rows[line_or_row][0]}"


def check_unique(path, header):
    seen = {}
    for k, name in enumerate(header, start=1):
        if name in seen:
            fail(f"{path}: column '{name}' appears twice (columns {seen[name]} and {k})")
        seen[name] = k


# --- LABEL=FILE ----------------------------------------------------------------------------------

def labelled(text):
    """'LABEL=FILE' -> (LABEL, FILE); a bare FILE is labelled by its base name. An argument that
    names an existing file is a bare FILE even if it contains '='."""
    label, sep, path = text.partition("=")
    if not sep or os.path.isfile(text):
        label, path = "", text
    elif not os.path.exists(path):
        fail(f"{path}: no such file (from '{text}', read as LABEL=FILE: a path containing '=' "
             f"needs a LABEL= in front or must exist)")
    return (label or os.path.splitext(os.path.basename(path))[0], path)


def check_unique_labels(files):
    """files: (label, path) pairs from labelled(). Fails with one line when two share a label (a
    legend would name only one of their curves): two LABEL= alike, or two bare files of the same
    base name in different directories."""
    seen = {}
    for label, path in files:
        if label in seen:
            fail(f"label '{label}' is given to both {seen[label]} and {path}: give each file its "
                 f"own LABEL=FILE")
        seen[label] = path


# --- outputs -------------------------------------------------------------------------------------

def check_outputs(*options):
    """options: (option name, path or None). Fails with one line, before anything is plotted, if
    an output has no known figure extension, is a directory, is not in a writable directory, or
    two outputs are the same file."""
    seen = {}
    for option, out in options:
        if out is None:
            continue
        extension = os.path.splitext(out)[1][1:].lower()
        if extension not in FIGURE_TYPES:
            known = ", ".join("." + t for t in FIGURE_TYPES)
            fail(f"{option} {out}: unknown figure type '.{extension}' (known: {known})"
                 if extension else f"{option} {out}: no extension to give the figure type "
                 f"(e.g. .png, .pdf, .svg)")
        directory = os.path.dirname(out) or "."
        if os.path.isdir(out):
            fail(f"{out}: cannot write {extension.upper()} (it is a directory)")
        if not os.path.isdir(directory):
            fail(f"{out}: cannot write {extension.upper()} (directory {directory} does not exist)")
        if not os.access(directory, os.W_OK | os.X_OK) or (os.path.exists(out)
                                                            and not os.access(out, os.W_OK)):
            fail(f"{out}: cannot write {extension.upper()} (permission denied)")
        key = os.path.realpath(out)
        if key in seen:
            fail(f"{seen[key]} and {option} name the same file {out}")
        seen[key] = option


def save(*figures):
    """figures: (figure, path) pairs. Renders every figure first (the type from the extension,
    150 dpi), then writes the files and prints their paths; if a write fails, the files written
    so far are removed and the error is one line."""
    rendered = []
    for fig, out in figures:
        # A figure may keep room at its top for a suptitle of several lines (`tvd_rect`).
        fig.tight_layout(rect=getattr(fig, "tvd_rect", (0, 0, 1, 1)))
        buffer = io.BytesIO()
        try:
            fig.savefig(buffer, dpi=150, format=os.path.splitext(out)[1][1:].lower())
        except Exception as error:  # noqa: BLE001 - e.g. a missing image library
            fail(f"{out}: cannot render the figure ({reason(error)})")
        plt.close(fig)
        rendered.append((out, buffer.getvalue()))
    written = []
    for out, data in rendered:
        try:
            with open(out, "wb") as stream:
                written.append(out)
                stream.write(data)
        except OSError as error:
            for path in written:
                try:
                    os.remove(path)
                except OSError:
                    pass
            fail(f"{out}: cannot write {os.path.splitext(out)[1][1:].upper()} ({reason(error)})")
    for out, _ in rendered:
        print(out)
