#!/usr/bin/python3
"""SciPy reference for bench_frf, on the reduced matrices it exports.

usage: scipy_frf.py DIR REPEAT
For untracked.mat and tracked.mat in DIR: the acceleration FRF of eq. 18,
(K - w^2 M + j w C) x = (K_u + j w C_u) tau, a = -w^2 H x, with tau_q = exp(-j w (x_max - x_q) / v),
solved by scipy.linalg.solve at each of the file's frequencies, as a SciPy user writes it.
Prints 'scipy_frf VARIANT SECONDS MAX_DIFFERENCE' (median time of REPEAT runs, and
max |SciPy - ours| / max |SciPy| against the file's ours_re + j ours_im)."""
import sys
import time

import numpy as np
import scipy.io
import scipy.linalg as la


def frf(f):
    m, k, c = f["M"], f["K"], f["C"]
    k_u, c_u, h = f["K_u"], f["C_u"], f["H"]
    stations = f["stations"].ravel()
    speed = float(f["speed"].ravel()[0])
    lags = (stations.max() - stations) / speed
    out = np.empty((f["hz"].size, h.shape[0]), dtype=complex)
    for i, hz in enumerate(f["hz"].ravel()):
        w = 2.0 * np.pi * hz
        tau = np.exp(-1j * w * lags)
        z = k - w * w * m + 1j * w * c
        x = la.solve(z, (k_u + 1j * w * c_u) @ tau, check_finite=False)
        out[i] = -w * w * (h @ x)
    return out


def main():
    folder, repeat = sys.argv[1], int(sys.argv[2])
    for variant in ("untracked", "tracked"):
        f = scipy.io.loadmat(f"{folder}/{variant}.mat")
        times = []
        for _ in range(repeat):
            t0 = time.perf_counter()
            result = frf(f)
            times.append(time.perf_counter() - t0)
        ours = f["ours_re"] + 1j * f["ours_im"]
        diff = np.abs(result - ours).max() / np.abs(result).max()
        print(f"scipy_frf {variant} {np.median(times):.4f} {diff:.3g}", flush=True)


if __name__ == "__main__":
    main()
