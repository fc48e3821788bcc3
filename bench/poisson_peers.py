#!/usr/bin/env python3
"""Peers of `strata bench poisson` (issue 4): PyAMG and a DST-based FFT Poisson solve.

Usage: poisson_peers.py PROBLEM_FILE [--skip-pyamg]

PROBLEM_FILE is written by `src/bench/poisson.rs` (little-endian):
    b"POIS", u32 nx, u32 nz, f64 spacing_m,
    f64[nz*nx] rhs    (row-major; delta * div g at free samples, 0 at fixed ones),
    u8[nz*nx]  fixed  (1 where the height is a Dirichlet constraint; the border is always 1),
    f64[nz*nx] values (the fixed heights, 0 elsewhere).

The equations at free samples are h_W + h_E + h_N + h_S - 4 h = rhs (strata's 5-point operator).
The reduced SPD system over the free samples is (4 I - Adj_ff) h_f = -rhs_f + sum of fixed
neighbours, the same matrix and right-hand side as strata's, and tolerances are relative to its
right-hand side norm, as in strata.

Prints one JSON object on stdout:
  pyamg: smoothed aggregation (pyamg.smoothed_aggregation_solver), solve with CG acceleration
         (PyAMG's recommended use) to tol; setup and solve timed together; the relative residual
         it reached, recomputed here.
  fft:   the same grid with the border as the only Dirichlet samples (no interior constraints),
         solved exactly by a type-I DST (scipy.fft.dstn / idstn, all cores); only the transform
         solve is timed (the right-hand side is assembled beforehand).
"""

import json
import struct
import sys
import time

import numpy as np
import scipy.fft
import scipy.sparse as sp


def read_problem(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:4] != b"POIS":
        raise SystemExit(f"{path}: not a POIS problem file")
    nx, nz = struct.unpack_from("<II", data, 4)
    (spacing,) = struct.unpack_from("<d", data, 12)
    n = nx * nz
    off = 20
    rhs = np.frombuffer(data, dtype="<f8", count=n, offset=off).reshape(nz, nx)
    off += 8 * n
    fixed = np.frombuffer(data, dtype=np.uint8, count=n, offset=off).reshape(nz, nx).astype(bool)
    off += n
    values = np.frombuffer(data, dtype="<f8", count=n, offset=off).reshape(nz, nx)
    return nx, nz, spacing, rhs, fixed, values


def neighbour_sum(a):
    """Sum of the 4 neighbours of every interior sample of a (zero on the border)."""
    s = np.zeros_like(a)
    s[1:-1, 1:-1] = a[1:-1, :-2] + a[1:-1, 2:] + a[:-2, 1:-1] + a[2:, 1:-1]
    return s


def reduced_system(rhs, fixed, values):
    nz, nx = rhs.shape
    free = ~fixed
    idx = -np.ones((nz, nx), dtype=np.int64)
    nfree = int(free.sum())
    idx[free] = np.arange(nfree)
    b = -rhs + neighbour_sum(np.where(fixed, values, 0.0))
    b = b[free]
    rows = [np.arange(nfree)]
    cols = [np.arange(nfree)]
    vals = [np.full(nfree, 4.0)]
    jj, ii = np.nonzero(free)
    for dj, di in ((0, -1), (0, 1), (-1, 0), (1, 0)):
        nb = idx[jj + dj, ii + di]
        keep = nb >= 0
        rows.append(idx[jj, ii][keep])
        cols.append(nb[keep])
        vals.append(np.full(int(keep.sum()), -1.0))
    a = sp.csr_matrix(
        (np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(nfree, nfree)
    )
    return a, b


def run_pyamg(rhs, fixed, values, tol):
    import pyamg

    a, b = reduced_system(rhs, fixed, values)
    t0 = time.perf_counter()
    ml = pyamg.smoothed_aggregation_solver(a)
    t1 = time.perf_counter()
    x = ml.solve(b, tol=tol, accel="cg", maxiter=500)
    t2 = time.perf_counter()
    rel = float(np.linalg.norm(b - a @ x) / np.linalg.norm(b))
    return {
        "ms_pyamg": (t2 - t0) * 1e3,
        "ms_pyamg_setup": (t1 - t0) * 1e3,
        "ms_pyamg_solve": (t2 - t1) * 1e3,
        "pyamg_relative_residual": rel,
        "pyamg_unknowns": int(b.size),
        "pyamg_version": pyamg.__version__,
    }


def run_fft(rhs, values):
    nz, nx = rhs.shape
    border = np.ones((nz, nx), dtype=bool)
    border[1:-1, 1:-1] = False
    b = (-rhs + neighbour_sum(np.where(border, values, 0.0)))[1:-1, 1:-1].copy()
    mz, mx = b.shape
    lam = (
        4.0
        - 2.0 * np.cos(np.pi * np.arange(1, mz + 1) / (mz + 1))[:, None]
        - 2.0 * np.cos(np.pi * np.arange(1, mx + 1) / (mx + 1))[None, :]
    )
    best = None
    for _ in range(3):
        t0 = time.perf_counter()
        u = scipy.fft.idstn(scipy.fft.dstn(b, type=1, workers=-1) / lam, type=1, workers=-1)
        t = time.perf_counter() - t0
        best = t if best is None else min(best, t)
    # Relative residual of the FFT solution of the border-only system (a sanity check).
    pad = np.zeros((nz, nx))
    pad[1:-1, 1:-1] = u
    r = (4.0 * pad - neighbour_sum(pad))[1:-1, 1:-1] - b
    rel = float(np.linalg.norm(r) / np.linalg.norm(b))
    return {"ms_fft": best * 1e3, "fft_relative_residual": rel}


def main():
    if len(sys.argv) < 2:
        raise SystemExit(__doc__)
    path = sys.argv[1]
    skip_pyamg = "--skip-pyamg" in sys.argv[2:]
    nx, nz, spacing, rhs, fixed, values = read_problem(path)
    out = {"nx": nx, "nz": nz, "scipy_version": scipy.__version__, "numpy_version": np.__version__}
    out.update(run_fft(rhs, values))
    if not skip_pyamg:
        out.update(run_pyamg(rhs, fixed, values, 1e-6))
    print(json.dumps(out))


if __name__ == "__main__":
    main()
