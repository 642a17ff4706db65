"""A fine brute force of the wave-gear design space, written with the eq. (13)–(16)
functions of ``advisor.calc.wavegear`` only (independent of the sweep's own code)."""

import numpy as np

from advisor.calc import reducer, wavegear

LO, HI, OUT_HI = reducer.STAGE_RATIO_MIN, reducer.STAGE_RATIO_MAX, reducer.OUTPUT_RATIO_MAX


def _span(rest, after, top, k):
    """k evenly spaced (in log) ratios over the interval that leaves ``after`` stages a
    realisable remainder, both ends included; NaN where the interval is empty."""
    a = np.maximum(LO, rest / HI**after)
    b = np.minimum(top, rest / LO**after)
    t = np.linspace(0.0, 1.0, k)
    out = a[..., None] * (b / a)[..., None] ** t
    return np.where((a <= b * (1 + 1e-12))[..., None], out, np.nan)


def lightest(q, p: reducer.ReducerParams, k=(2000, 300, 60), max_d=None, max_l=None):
    """The least mass over stage counts 1…4, with k ratios per stage and every row count."""
    rows = np.arange(2, 13, dtype=float)
    best = np.inf
    chains = []
    if LO <= q <= HI:
        chains.append([np.array([q])])
    qo = _span(np.array(q), 1, OUT_HI, k[0]).ravel()
    chains.append([qo, q / qo])
    qo = _span(np.array(q), 2, OUT_HI, k[1]).ravel()
    q2 = _span(q / qo, 1, HI, k[1]).ravel()
    qo = np.repeat(qo, k[1])
    chains.append([qo, q2, q / (qo * q2)])
    qo = _span(np.array(q), 3, OUT_HI, k[2]).ravel()
    q2 = _span(q / qo, 2, HI, k[2]).ravel()
    qo = np.repeat(qo, k[2])
    q3 = _span(q / (qo * q2), 1, HI, k[2]).ravel()
    qo, q2 = np.repeat(qo, k[2]), np.repeat(q2, k[2])
    chains.append([qo, q2, q3, q / (qo * q2 * q3)])
    for chain in chains:
        good = np.all([np.isfinite(c) for c in chain], axis=0)
        chain = [c[good][:, None] for c in chain]
        d_rb = wavegear.rolling_body_diameter(p.torque_Nm, chain[0], rows[None, :], p.k_rb)
        D = wavegear.outer_diameter(chain[0], d_rb)
        d = wavegear.inner_diameter(chain[0], d_rb)
        L_out = wavegear.stage_length(rows[None, :], d_rb)
        length = L_out
        ok = np.ones(D.shape, bool)
        down = 1.0
        for j, qj in enumerate(chain[1:], start=1):
            down = down * chain[j - 1]
            length = length + wavegear.equal_diameter_length(L_out, down)
            torque = p.torque_Nm / (down * p.stage_efficiency**j)
            own = wavegear.outer_diameter(qj, wavegear.rolling_body_diameter(torque, qj, 2, p.k_rb))
            ok &= own <= D * (1 + 1e-12)
        if max_d is not None:
            ok &= D <= max_d
        if max_l is not None:
            ok &= length <= max_l
        mass = wavegear.mass_kg(
            wavegear.hollow_cylinder_volume(D, d, length), p.density_kg_m3, p.fill_factor
        )
        if ok.any():
            best = min(best, float(mass[ok].min()))
    return best
