"""Particle snapshots of a run for the bench/*.py analyses (imported; Debian's python3-numpy).

A LIGGGHTS run still going has its raw dumps particles/dump.<step>.txt (9 header lines, space separated); a
finished run (any engine) has particles/particles_<step>.csv (one header line, comma separated). Both have the
columns id x y z radius vx vy vz first, so the same column numbers select from either.
The run's case and meta.json are read through the case library (brash-case get: $BRASH_BIN, default build/bin)
and a JSON reader."""
import glob
import json
import os
import subprocess

import numpy as np


def case_value(run, key):
    """A dotted key of RUN_DIR/case.yaml as text, as the case loader resolves it (brash-case get)."""
    here = os.path.dirname(os.path.abspath(__file__))
    exe = os.path.join(os.environ.get('BRASH_BIN') or os.path.join(here, '..', 'build', 'bin'), 'brash-case')
    got = subprocess.run([exe, 'get', os.path.join(run, 'case.yaml'), key], capture_output=True, text=True)
    if got.returncode != 0:
        raise SystemExit(got.stderr.strip() or '%s: brash-case get %s failed' % (run, key))
    return got.stdout.strip()


def meta(run):
    """RUN_DIR/meta.json as a dict."""
    with open(os.path.join(run, 'meta.json')) as f:
        return json.load(f)


def snapshots(run, dt):
    """[(t [s], path)] in step order; exits with a message when the run has none."""
    raw = sorted(glob.glob(os.path.join(run, 'particles', 'dump.*.txt')))
    if raw:
        return [(int(f.split('.')[-2]) * dt, f) for f in raw]
    done = sorted(glob.glob(os.path.join(run, 'particles', 'particles_*.csv')))
    if done:
        return [(int(os.path.basename(f)[len('particles_'):-len('.csv')]) * dt, f) for f in done]
    raise SystemExit('%s: no particle dumps (particles/dump.*.txt or particles/particles_*.csv)' % run)


def load(path, columns):
    """The given columns (0 id, 1-3 x y z, 4 radius, 5-7 vx vy vz) of one snapshot as an array."""
    if path.endswith('.csv'):
        return np.loadtxt(path, delimiter=',', skiprows=1, usecols=columns)
    return np.loadtxt(path, skiprows=9, usecols=columns)


def every_nth(items, every):
    """Every n-th item and always the last."""
    return items[::every] + ([items[-1]] if (len(items) - 1) % every else [])
