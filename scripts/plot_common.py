"""Shared by the figure scripts (plot_mac.py, plot_frf.py, plot_simulation.py): reading the CSV
files `tvd` writes, one-line errors for bad input (exit status 2), LABEL=FILE arguments and
writing the PNG."""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def fail(message):
    """One error line on stderr, exit status 2 (bad input)."""
    sys.stderr.write(f"{os.path.basename(sys.argv[0])}: error: {message}\n")
    sys.exit(2)


def read_csv(path):
    """Header and data rows of a CSV file; fails on a missing, unreadable or empty file."""
    try:
        with open(path, newline="") as stream:
            rows = [row for row in csv.reader(stream) if row]
    except (OSError, UnicodeDecodeError, csv.Error) as error:
        fail(f"{path}: cannot read CSV ({getattr(error, 'strerror', None) or error})")
    if len(rows) < 2:
        fail(f"{path}: no data rows")
    return [name.strip() for name in rows[0]], rows[1:]


def column(path, header, rows, name):
    """The column called `name` as a float array; fails if it is missing or not finite numbers."""
    if name not in header:
        fail(f"{path}: missing column '{name}'")
    j = header.index(name)
    values = []
    for line, row in enumerate(rows, start=2):
        text = row[j].strip() if j < len(row) else ""
        try:
            value = float(text)
        except ValueError:
            value = math.nan
        if not math.isfinite(value):
            fail(f"{path}: line {line}, column '{name}': '{text}' is not a finite number")
        values.append(value)
    return np.array(values)


def labelled(text):
    """'LABEL=FILE' -> (LABEL, FILE); a bare FILE is labelled by its base name."""
    label, sep, path = text.partition("=")
    return (label, path) if sep else (os.path.splitext(os.path.basename(text))[0], text)


def save(fig, out):
    """Writes the figure as PNG (150 dpi), closes it and prints the path; fails with one line if
    it cannot."""
    fig.tight_layout()
    try:
        fig.savefig(out, dpi=150, format="png")
    except OSError as error:
        fail(f"{out}: cannot write PNG ({error.strerror or error})")
    plt.close(fig)
    print(out)
