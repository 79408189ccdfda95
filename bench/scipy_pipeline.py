#!/usr/bin/python3
"""SciPy reference for bench_pipeline, on the matrices it exports.

usage: scipy_pipeline.py DIR REDUCED_MAT REPEAT
prints 'scipy_pipeline MODES_S CONSTRAINT_S FIXED_S PROJECTION_S',
'scipy_simulation SECONDS PEAK_HEAVE' (the whole state space, cont2discrete + dlsim),
'scipy_modal_simulation SETUP_S SECONDS PEAK_HEAVE' (the work ours does: the modes up to the
Nyquist frequency integrated one by one, the others quasi-static) and
'scipy_memory PIPELINE_MB TOTAL_MB' (peak resident set after the pipeline part and in all). The Craig-Bampton work is what a SciPy user writes: the
constraint modes by one splu of K_ss, the fixed-interface modes by eigsh, then T_CMS and the
projections M_R = T^T M T, K_R = T^T K T (ours computes the same and more: C_R, K_u, C_u, the
gravity load and the recovery rows)."""
import resource
import sys
import time

import numpy as np
import scipy.io
import scipy.linalg as la
import scipy.signal as signal
import scipy.sparse.linalg as sla


def median_time(fn, repeat):
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        result = fn()
        times.append(time.perf_counter() - t0)
    return float(np.median(times)), result


def main():
    folder, reduced_mat, repeat = sys.argv[1], sys.argv[2], int(sys.argv[3])
    k = scipy.io.mmread(f"{folder}/K.mtx").tocsc()
    m = scipy.io.mmread(f"{folder}/M.mtx").tocsc()
    info = scipy.io.loadmat(f"{folder}/masters.mat")
    masters = info["masters"].ravel().astype(int)
    n_fixed = int(info["fixed_interface_modes"].ravel()[0])
    slaves = np.setdiff1d(np.arange(k.shape[0]), masters)
    sigma = -1.0  # below the lowest eigenvalue (no rigid-body mode: ground springs)

    t_modes, _ = median_time(lambda: sla.eigsh(k, k=40, M=m, sigma=sigma, which="LM", tol=1e-10), repeat)
    k_ss = k[slaves][:, slaves].tocsc()
    m_ss = m[slaves][:, slaves].tocsc()
    k_sm = k[slaves][:, masters].toarray()
    t_constraint, _ = median_time(lambda: sla.splu(k_ss).solve(-k_sm), repeat)
    t_fixed, (_, phi_s) = median_time(
        lambda: sla.eigsh(k_ss, k=n_fixed, M=m_ss, sigma=sigma, which="LM", tol=1e-10), repeat)
    phi_c = sla.splu(k_ss).solve(-k_sm)

    def project():
        n_m = len(masters)
        t = np.zeros((k.shape[0], n_m + n_fixed))
        t[masters, np.arange(n_m)] = 1.0
        t[slaves, :n_m] = phi_c
        t[slaves, n_m:] = phi_s
        return t.T @ (m @ t), t.T @ (k @ t)

    t_projection, _ = median_time(project, repeat)
    print(f"SciPy: eigsh 40 modes {t_modes:.3f} s, splu constraint modes ({len(masters)} columns) "
          f"{t_constraint:.3f} s, eigsh {n_fixed} fixed-interface modes {t_fixed:.3f} s, "
          f"T_CMS and T^T M T, T^T K T {t_projection:.3f} s")
    print(f"scipy_pipeline {t_modes:.6f} {t_constraint:.6f} {t_fixed:.6f} {t_projection:.6f}")
    pipeline_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0

    r = scipy.io.loadmat(reduced_mat)
    mr, kr, cr, ku, cu, h = (r[x] for x in ("M_R", "K_R", "C_R", "K_u", "C_u", "H"))
    g = r["gravity_load"].ravel()
    n, n_u = kr.shape[0], ku.shape[1]
    minv = la.inv(mr)
    a = np.block([[np.zeros((n, n)), np.eye(n)], [-minv @ kr, -minv @ cr]])
    # Inputs [u; u'; 1]: the constant gravity load rides on a unit input.
    b = np.block([[np.zeros((n, 2 * n_u + 1))], [minv @ ku, minv @ cu, (minv @ g)[:, None]]])
    c = np.hstack([h, np.zeros_like(h)])
    d = np.zeros((h.shape[0], 2 * n_u + 1))
    inputs = scipy.io.loadmat(f"{folder}/inputs.mat")
    w, dt = inputs["W"], float(inputs["dt"].ravel()[0])
    u = np.hstack([w, np.ones((w.shape[0], 1))])

    def run():
        ad, bd, cd, dd, _ = signal.cont2discrete((a, b, c, d), dt, method="foh")
        # Start at rest under the first input: the discrete fixed point x = Ad x + Bd u0 (the
        # static equilibrium, in whatever state coordinates the FOH realisation uses).
        x0 = la.solve(np.eye(2 * n) - ad, bd @ u[0])
        _, y, _ = signal.dlsim((ad, bd, cd, dd, dt), u, x0=x0)
        return y

    t_sim, y = median_time(run, max(1, min(repeat, 2)))
    heave = y[:, 2] - y[0, 2]
    print(f"SciPy: cont2discrete(FOH) + dlsim {t_sim:.3f} s for {w.shape[0]} samples")
    print(f"scipy_simulation {t_sim:.6f} {np.abs(heave).max():.6f}")

    # The same work as ours (dynamics::Simulator, ModalDecoupled): the modes of (K_R, M_R) up to
    # the Nyquist frequency 1/(2 dt) integrated exactly, each as its own FOH-discretised second
    # order filter, the others quasi-static (q = Phi Omega^-2 Phi^T f). Damping ratios from the
    # diagonal of Phi^T C_R Phi (the description's modal damping makes it diagonal).
    nyquist = 0.5 / dt

    def modal_setup():
        lam, phi = la.eigh(kr, mr)
        omega = np.sqrt(np.maximum(lam, 0.0))
        zeta = np.diag(phi.T @ cr @ phi) / (2.0 * omega)
        dynamic = omega / (2.0 * np.pi) <= nyquist
        g_map = phi.T @ np.hstack([ku, cu])
        filters = []
        for wj, zj in zip(omega[dynamic], zeta[dynamic]):
            a_j = np.array([[0.0, 1.0], [-wj * wj, -2.0 * zj * wj]])
            ad, bd, cd, dd, _ = signal.cont2discrete(
                (a_j, np.array([[0.0], [1.0]]), np.array([[1.0, 0.0]]), np.zeros((1, 1))), dt,
                method="foh")
            num, den = signal.ss2tf(ad, bd, cd, dd)
            filters.append((num.ravel(), den))
        quasi = ~dynamic
        h_quasi = (h @ phi[:, quasi]) / lam[quasi]
        return (phi, g_map, dynamic, filters, h @ phi[:, dynamic], h_quasi @ g_map[quasi],
                h_quasi @ (phi[:, quasi].T @ g))

    def modal_run(setup):
        phi, g_map, dynamic, filters, h_dynamic, d_quasi, y_quasi_g = setup
        forces = w @ g_map[dynamic].T + phi[:, dynamic].T @ g
        eta = np.empty_like(forces)
        for j, (num, den) in enumerate(filters):
            # At rest under the first sample: the filter's steady state for that input.
            zi = signal.lfilter_zi(num, den) * forces[0, j]
            eta[:, j], _ = signal.lfilter(num, den, forces[:, j], zi=zi)
        return eta @ h_dynamic.T + w @ d_quasi.T + y_quasi_g

    t_modal_setup, setup = median_time(modal_setup, repeat)
    t_modal, y_modal = median_time(lambda: modal_run(setup), repeat)
    modal_heave = y_modal[:, 2] - y_modal[0, 2]
    print(f"SciPy, same modal work: set-up {t_modal_setup:.3f} s (eigh, {int(setup[2].sum())} "
          f"modes <= {nyquist:g} Hz discretised), simulation {t_modal:.3f} s")
    print(f"scipy_modal_simulation {t_modal_setup:.6f} {t_modal:.6f} "
          f"{np.abs(modal_heave).max():.6f}")
    total_mb = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    print(f"scipy_memory {pipeline_mb:.1f} {total_mb:.1f}")


if __name__ == "__main__":
    main()
