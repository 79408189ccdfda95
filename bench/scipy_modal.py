#!/usr/bin/python3
"""SciPy reference for bench_modal: eigsh shift-invert on the exported K, M (Matrix Market).

usage: scipy_modal.py DIR MODES SIGMA REPEAT   -> prints 'scipy_median_seconds S f1 F fn F'"""
import sys
import time

import numpy as np
import scipy.io
import scipy.sparse.linalg as sla


def main():
    folder, modes, sigma, repeat = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4])
    k = scipy.io.mmread(f"{folder}/K.mtx").tocsc()
    m = scipy.io.mmread(f"{folder}/M.mtx").tocsc()
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        vals, _ = sla.eigsh(k, k=modes, M=m, sigma=sigma, which="LM", tol=1e-10)
        times.append(time.perf_counter() - t0)
    f = np.sqrt(np.maximum(np.sort(vals), 0.0)) / (2 * np.pi)
    print(f"scipy_median_seconds {np.median(times):.6f} f1 {f[0]:.9g} fn {f[-1]:.9g}")


if __name__ == "__main__":
    main()
