"""A reducer of wave gear stages in the equal-diameter layout, and its design space.

The output stage sets the diameters (eqs. (13), (14) with d_тк from (16) at the output
torque); the other stages share them and differ only in length, L_k = L_out·∛(1/Πq) between
stage k and the output (seed 000, after eq. (19)). Stage torques fall through the chain:
the stage before a stage of ratio q and efficiency η carries M/(q·η).

:func:`sweep` evaluates every stage count, split, output ratio and output row count at once
with numpy broadcasting; :func:`evaluate` evaluates one configuration with the same code, so
the rule-based design and the optimum are computed alike.
"""

import math
from typing import NamedTuple

import numpy as np

from advisor.calc import wavegear

#: Ratio limits of one stage: a positive bore needs q > 6.45 (eq. (14)); seed 000's fig. 2
#: spans intermediate ratios 6…60 and its two-stage case uses up to 63.
STAGE_RATIO_MIN = 6.5
STAGE_RATIO_MAX = 64.0
#: Output-stage ratios swept (the issue's design space) and row counts (seed 000 fig. 1).
#: A single stage may take any ratio within the stage limits.
OUTPUT_RATIO_MAX = 40.0
OUTPUT_RATIO_GRID = np.arange(STAGE_RATIO_MIN, OUTPUT_RATIO_MAX + 1e-9, 0.5)
ROW_GRID = np.arange(2, 13)
INTERMEDIATE_RATIO_GRID = np.geomspace(STAGE_RATIO_MIN, STAGE_RATIO_MAX, 24)


class ReducerParams(NamedTuple):
    torque_Nm: float  # peak output torque
    k_rb: float  # 1 balls, 2 rollers (eq. (16))
    stage_efficiency: float
    density_kg_m3: float
    fill_factor: float


class Stage(NamedTuple):
    position: str  # "input" | "intermediate" | "output"
    ratio: float
    rows: int
    torque_Nm: float  # at the output of this stage
    rolling_body_diameter_mm: float
    own_outer_diameter_mm: float
    own_inner_diameter_mm: float
    outer_diameter_mm: float
    inner_diameter_mm: float
    length_mm: float
    mass_kg: float


class Reducer(NamedTuple):
    stages: tuple[Stage, ...]  # motor side first
    total_ratio: float
    efficiency: float
    outer_diameter_mm: float
    inner_diameter_mm: float
    length_mm: float
    volume_mm3: float
    mass_kg: float


class _Own(NamedTuple):
    """A stage's own rolling body and diameters at its torque [mm] (eqs. (13), (14), (16))."""

    rolling_body_diameter_mm: float
    outer_diameter_mm: float
    inner_diameter_mm: float


def _own(torque_Nm: float, q: float, rows: int, p: ReducerParams) -> _Own:
    d_rb = float(wavegear.rolling_body_diameter(torque_Nm, q, rows, p.k_rb))
    return _Own(
        d_rb, float(wavegear.outer_diameter(q, d_rb)), float(wavegear.inner_diameter(q, d_rb))
    )


def _stage(
    position: str,
    q: float,
    rows: int,
    torque_Nm: float,
    own: _Own,
    common: tuple[float, float, float],
    p: ReducerParams,
) -> Stage:
    """One stage at its torque: its own diameters (``own``), the common outer and inner
    diameters and its length (``common``), its mass by eqs. (12), (19)."""
    D, d, length = common
    vol = float(wavegear.hollow_cylinder_volume(D, d, length))
    return Stage(
        position,
        q,
        rows,
        torque_Nm,
        *own,
        D,
        d,
        length,
        float(wavegear.mass_kg(vol, p.density_kg_m3, p.fill_factor)),
    )


def evaluate(ratios_out_to_in: list[float], rows_out_to_in: list[int], p: ReducerParams) -> Reducer:
    """One reducer; ratios and rows listed from the output stage towards the motor.

    Parameters
    ----------
    ratios_out_to_in : list of float
        Stage ratios q_k, output first [-]
    rows_out_to_in : list of int
        Rows of rolling bodies n_p of each stage, output first [-]
    p : ReducerParams
        Output torque [N·m], rolling body, stage efficiency, density [kg/m³], fill factor

    Returns
    -------
    Reducer
        Stages (motor side first) with torques [N·m], diameters and lengths [mm], masses
        [kg]; the reducer's total ratio, efficiency η^n, diameters, length [mm], volume
        [mm³] and mass [kg]

    Notes
    -----
    The output stage sets the diameters (eqs. (13), (14), (16)); the others share them and
    differ in length, L_k = L_out·∛(1/Πq) (seed 000, after eq. (19)); the stage before one of
    ratio q and efficiency η carries M/(q·η). Valid for stage ratios above 6.45 (eq. (14)).
    """
    n = len(ratios_out_to_in)
    torque = p.torque_Nm
    out = _own(torque, ratios_out_to_in[0], rows_out_to_in[0], p)  # sets the diameters
    d_out, D, d = out
    L_out = float(wavegear.stage_length(rows_out_to_in[0], d_out))
    stages = []
    downstream = 1.0  # product of the ratios between this stage and the output
    for i, (q, rows) in enumerate(zip(ratios_out_to_in, rows_out_to_in, strict=True)):
        position = "output" if i == 0 else ("input" if i == n - 1 else "intermediate")
        length = float(wavegear.equal_diameter_length(L_out, downstream))
        own = out if i == 0 else _own(torque, q, rows, p)
        stages.append(_stage(position, q, rows, torque, own, (D, d, length), p))
        downstream *= q
        torque = torque / (q * p.stage_efficiency)
    length = sum(s.length_mm for s in stages)
    volume = float(wavegear.hollow_cylinder_volume(D, d, length))
    return Reducer(
        stages=tuple(reversed(stages)),
        total_ratio=downstream,
        efficiency=p.stage_efficiency**n,
        outer_diameter_mm=D,
        inner_diameter_mm=d,
        length_mm=length,
        volume_mm3=volume,
        mass_kg=float(wavegear.mass_kg(volume, p.density_kg_m3, p.fill_factor)),
    )


def fits(r: Reducer, max_outer_diameter_mm: float | None, max_length_mm: float | None) -> bool:
    """Whether reducer ``r`` lies within an envelope (None: no limit).

    Parameters
    ----------
    r : Reducer
        The reducer
    max_outer_diameter_mm, max_length_mm : float or None
        Envelope [mm]; None: no limit

    Returns
    -------
    bool
        Its outer diameter and length within the envelope
    """
    return (max_outer_diameter_mm is None or r.outer_diameter_mm <= max_outer_diameter_mm) and (
        max_length_mm is None or r.length_mm <= max_length_mm
    )


class SweepResult(NamedTuple):
    """Flat arrays, one entry per feasible configuration (every stage ratio within limits and
    every stage's own outer diameter within the common one)."""

    stages: np.ndarray
    q_out: np.ndarray
    q_mid: np.ndarray  # the ratios between output and input stage, (N, 2), NaN where absent
    q_in: np.ndarray  # NaN for a single stage
    rows_out: np.ndarray
    outer_diameter_mm: np.ndarray
    length_mm: np.ndarray
    mass_kg: np.ndarray
    evaluated: int  # configurations built and computed: every one realises the total ratio

    @property
    def feasible(self) -> int:
        return int(self.mass_kg.size)

    def efficiency(self, stage_efficiency: float) -> np.ndarray:
        return stage_efficiency ** self.stages.astype(float)

    def ratios_out_to_in(self, i: int) -> list[float]:
        q_in = float(self.q_in[i])
        out = [float(self.q_out[i]), *(x for x in self.q_mid[i].tolist() if not math.isnan(x))]
        if not math.isnan(q_in):
            out.append(q_in)
        return out


def stage_count_bounds(total_ratio: float, max_stages: int = 4) -> range:
    """The stage counts that can realise ``total_ratio``: n stages make at least
    q_min^n and at most q_out,max·q_max^(n−1) (one stage: q_min…q_max).

    Parameters
    ----------
    total_ratio : float
        Total reduction q_Σ [-]
    max_stages : int, optional
        Most stages considered [-]

    Returns
    -------
    range
        The stage counts that can realise it (empty when none can)
    """
    lo, hi = STAGE_RATIO_MIN, STAGE_RATIO_MAX
    ns = [
        n
        for n in range(1, max_stages + 1)
        if lo**n <= total_ratio * (1 + 1e-12)
        and total_ratio <= (hi if n == 1 else OUTPUT_RATIO_MAX * hi ** (n - 1)) * (1 + 1e-12)
    ]
    return range(ns[0], ns[-1] + 1) if ns else range(0)


def _level(
    rest: np.ndarray, after: int, grid: np.ndarray, top: float
) -> tuple[np.ndarray, np.ndarray]:
    """Every ratio of one stage that leaves the ``after`` stages behind it a realisable
    remainder: q in [max(q_min, rest/q_max^after), min(top, rest/q_min^after)], taken from
    ``grid`` plus both ends of the interval (the constraint boundaries). Returns the parent
    index of each ratio and the ratio; no infeasible combination is built."""
    lo, hi = STAGE_RATIO_MIN, STAGE_RATIO_MAX
    a = np.maximum(lo, rest / hi**after)
    b = np.minimum(top, rest / lo**after)
    keep = a <= b * (1 + 1e-12)
    i0 = np.searchsorted(grid, a, "right")  # grid points strictly inside (a, b)
    i1 = np.searchsorted(grid, b, "left")
    counts = np.where(keep, np.maximum(i1 - i0, 0) + 2, 0)
    parent = np.repeat(np.arange(rest.size), counts)
    starts = np.cumsum(counts) - counts
    pos = np.arange(parent.size) - starts[parent]
    inner = np.minimum(i0[parent] + pos - 2, grid.size - 1)
    q = np.where(pos == 0, a[parent], np.where(pos == 1, b[parent], grid[inner]))
    return parent, q


def _chains(total_ratio: float, n: int, out_grid: np.ndarray, mid_grid: np.ndarray):
    """The ratio chains (output first) of ``n`` stages that realise ``total_ratio``."""
    if n == 1:
        ok = STAGE_RATIO_MIN <= total_ratio <= STAGE_RATIO_MAX
        return [np.array([total_ratio] if ok else [])]
    parent, q_out = _level(np.array([float(total_ratio)]), n - 1, out_grid, OUTPUT_RATIO_MAX)
    cols = [q_out]
    rest = total_ratio / q_out
    for j in range(n - 2):
        parent, q = _level(rest, n - 2 - j, mid_grid, STAGE_RATIO_MAX)
        cols = [c[parent] for c in cols] + [q]
        rest = rest[parent] / q
    cols.append(np.clip(rest, STAGE_RATIO_MIN, STAGE_RATIO_MAX))
    return cols


class _Block(NamedTuple):
    """The configurations of one stage count (chains × output rows) before the feasibility
    mask: every column of :class:`SweepResult` as a (chains, rows) array."""

    outer_diameter_mm: np.ndarray
    length_mm: np.ndarray
    mass_kg: np.ndarray
    fits: np.ndarray


def _stage_count_block(chain: list[np.ndarray], rows: np.ndarray, p: ReducerParams) -> _Block:
    """Eqs. (12)–(16) for every chain (output ratio first) of one stage count and every output
    row count, by the same functions :func:`evaluate` calls, broadcast (chains, rows).

    The output stage sets the diameters; the others share them in the equal-diameter layout,
    L = L_out·(1 + Σ ∛(1/Πq)), and each must fit them with two rows at its own torque."""
    q_out = chain[0]
    d_rb = wavegear.rolling_body_diameter(p.torque_Nm, q_out[:, None], rows[None, :], p.k_rb)
    outer = wavegear.outer_diameter(q_out[:, None], d_rb)
    inner = wavegear.inner_diameter(q_out[:, None], d_rb)
    factor = np.ones(q_out.size)
    own = np.zeros(q_out.size)
    downstream = np.ones(q_out.size)
    for j in range(1, len(chain)):
        downstream = downstream * chain[j - 1]
        factor += wavegear.equal_diameter_length(1.0, downstream)
        torque = p.torque_Nm / (downstream * p.stage_efficiency**j)
        d_rb_j = wavegear.rolling_body_diameter(torque, chain[j], 2.0, p.k_rb)
        own = np.maximum(own, wavegear.outer_diameter(chain[j], d_rb_j))
    length = wavegear.stage_length(rows[None, :], d_rb) * factor[:, None]
    volume = wavegear.hollow_cylinder_volume(outer, inner, length)
    mass = wavegear.mass_kg(volume, p.density_kg_m3, p.fill_factor)
    return _Block(outer, length, mass, own[:, None] <= outer)


def _feasible_columns(chain: list[np.ndarray], rows: np.ndarray, block: _Block) -> tuple:
    """The :class:`SweepResult` columns of one stage count's feasible configurations."""
    n = len(chain)
    ic, ir = np.nonzero(block.fits)
    mids = np.full((ic.size, 2), np.nan)
    for j in range(n - 2):
        mids[:, j] = chain[1 + j][ic]
    return (
        np.full(ic.size, n),
        chain[0][ic],
        mids,
        chain[-1][ic] if n > 1 else np.full(ic.size, np.nan),
        rows[ir].astype(int),
        block.outer_diameter_mm[block.fits],  # as np.nonzero orders them: (ic, ir)
        block.length_mm[block.fits],
        block.mass_kg[block.fits],
    )


def sweep(
    total_ratio: float,
    p: ReducerParams,
    max_stages: int = 4,
    out_grid: np.ndarray | None = None,
    mid_grid: np.ndarray | None = None,
    rows: np.ndarray | None = None,
    stage_counts: range | list[int] | None = None,
) -> SweepResult:
    """Every reducer of the design space that realises q_Σ = Π q_k, in flat arrays.

    Every stage count (1…``max_stages``), split (``mid_grid``), output ratio (``out_grid``)
    and output row count (``rows``) with every stage ratio within 6.5…64 (a bore needs
    q > 6.45, eq. (14)), plus the stage ratios at their limits; only these are built, then
    checked for every stage fitting the common diameter. Eqs. (12)–(19) are computed by
    :mod:`advisor.calc.wavegear`, as :func:`evaluate` computes them.

    Parameters
    ----------
    total_ratio : float
        Total reduction q_Σ [-]
    p : ReducerParams
        Output torque [N·m], rolling body, stage efficiency, density [kg/m³], fill factor
    max_stages : int, optional
        Most stages considered [-]
    out_grid, mid_grid, rows : numpy.ndarray, optional
        Output and intermediate ratios [-] and output row counts [-] swept
    stage_counts : range or list of int, optional
        Stage counts swept instead of all that can realise ``total_ratio``

    Returns
    -------
    SweepResult
        One entry per feasible configuration: lengths [mm], masses [kg]

    References: seed 000, eqs. (12)–(19) and the equal-diameter layout after eq. (19).
    """
    out_grid = OUTPUT_RATIO_GRID if out_grid is None else out_grid
    mid_grid = INTERMEDIATE_RATIO_GRID if mid_grid is None else mid_grid
    rows_f = (ROW_GRID if rows is None else np.asarray(rows)).astype(float)
    counts = stage_count_bounds(total_ratio, max_stages) if stage_counts is None else stage_counts
    parts = []
    evaluated = 0
    for n in counts:
        chain = _chains(total_ratio, n, out_grid, mid_grid)
        if chain[0].size == 0:
            continue
        evaluated += chain[0].size * rows_f.size
        parts.append(_feasible_columns(chain, rows_f, _stage_count_block(chain, rows_f, p)))
    if not parts:
        empty = np.array([])
        return SweepResult(
            empty, empty, np.empty((0, 2)), empty, empty.astype(int), empty, empty, empty, evaluated
        )
    cols = list(zip(*parts, strict=True))
    return SweepResult(*(np.concatenate(c) for c in cols), evaluated)


def best(
    result: SweepResult,
    objective: str,
    max_outer_diameter_mm: float | None = None,
    max_length_mm: float | None = None,
) -> int | None:
    """Index of the lightest (``"mass"``) or slimmest (``"diameter"``) configuration within
    the envelope; ``None`` if none fits. Of equally slim ones (the output stage alone sets
    the outer diameter, so many splits share it) the lightest.

    Parameters
    ----------
    result : SweepResult
        The design space (:func:`sweep`)
    objective : str
        "mass" or "diameter"
    max_outer_diameter_mm, max_length_mm : float, optional
        Envelope [mm]; None: no limit

    Returns
    -------
    int or None
        Index into ``result``; None when nothing fits
    """
    ok = _within(result, max_outer_diameter_mm, max_length_mm)
    if not ok.any():
        return None
    key, tie = _keys(result, objective)
    masked = np.where(ok, key, np.inf)
    ties = np.flatnonzero(masked == masked.min())
    return int(ties[0] if ties.size == 1 else ties[np.argmin(tie[ties])])


def _keys(result: SweepResult, objective: str) -> tuple[np.ndarray, np.ndarray]:
    """The objective and its tie-break: mass (then diameter), or diameter (then mass)."""
    if objective == "mass":
        return result.mass_kg, result.outer_diameter_mm
    return result.outer_diameter_mm, result.mass_kg


#: Ratio of neighbouring intermediate grid ratios (the refinement works within one step).
_MID_STEP = float(INTERMEDIATE_RATIO_GRID[1] / INTERMEDIATE_RATIO_GRID[0])
_OUT_STEP = float(OUTPUT_RATIO_GRID[1] - OUTPUT_RATIO_GRID[0])


class _Point(NamedTuple):
    """A configuration as :func:`refine` ranks it: envelope violation, objective, tie-break."""

    violation: float
    key: float
    tie: float
    ratios: list[float]
    rows: int


def _point(result: SweepResult, i: int, violation, key, tie) -> _Point:
    return _Point(
        float(violation[i]),
        float(key[i]),
        float(tie[i]),
        result.ratios_out_to_in(i),
        int(result.rows_out[i]),
    )


def _polish(
    total_ratio: float,
    p: ReducerParams,
    start: _Point,
    objective: str,
    envelope: tuple[float | None, float | None],
    points: int,
    passes: int,
) -> _Point:
    """``passes`` local sweeps of one stage count around ``start``: ``points`` ratios over a
    grid step on either side and the neighbouring row counts, the span shrinking fivefold
    each pass; the best point found."""
    best_point = start
    span_out, span_mid = _OUT_STEP, _MID_STEP
    for _ in range(passes if len(start.ratios) > 1 else 0):
        ratios, rows = best_point.ratios, best_point.rows
        mids = ratios[1:-1]
        mid_grid = (
            _unique(
                np.concatenate([np.geomspace(m / span_mid, m * span_mid, points) for m in mids])
            )
            if mids
            else INTERMEDIATE_RATIO_GRID[:0]
        )
        local = sweep(
            total_ratio,
            p,
            out_grid=np.linspace(ratios[0] - span_out, ratios[0] + span_out, points),
            mid_grid=mid_grid,
            rows=np.arange(max(2, rows - 1), min(int(ROW_GRID.max()), rows + 1) + 1),
            stage_counts=[len(ratios)],
        )
        if local.mass_kg.size:
            lv = _violation(local, *envelope)
            lk, lt = _keys(local, objective)
            candidate = _point(local, _first(lv, lk, lt), lv, lk, lt)
            if candidate[:3] < best_point[:3]:
                best_point = candidate
        span_out, span_mid = span_out / 5.0, span_mid ** (1.0 / 5.0)
    return best_point


def refine(
    total_ratio: float,
    p: ReducerParams,
    result: SweepResult,
    objective: str,
    max_outer_diameter_mm: float | None = None,
    max_length_mm: float | None = None,
    points: int = 11,
    passes: int = 3,
) -> tuple[list[float], int] | None:
    """The best configuration, polished: for each stage count, its best grid point is swept
    again (:func:`_polish`; the sweep always adds the constraint boundaries). Within an
    envelope the optimum lies between grid points (on the envelope); without one, the mass
    optimum sits on a ratio limit, which the boundary points already hold. A stage count
    with no grid point within the envelope is polished from its least violating point: the
    envelope and the common-diameter check may leave room only between grid points
    (q = 20 758 under 0.8 of the free optimum's diameter: a 3-stage design of 9.01 kg that
    no grid point reaches, where the best 4-stage one is 9.39 kg). Returns the ratios
    (output first) and output rows, or ``None`` if nothing fits.

    Parameters
    ----------
    total_ratio : float
        Total reduction q_Σ [-]
    p : ReducerParams
        Output torque [N·m], rolling body, stage efficiency, density [kg/m³], fill factor
    result : SweepResult
        The design space (:func:`sweep`)
    objective : str
        "mass" or "diameter"
    max_outer_diameter_mm, max_length_mm : float, optional
        Envelope [mm]; None: no limit
    points, passes : int, optional
        Ratios per local sweep and local sweeps per stage count [-]

    Returns
    -------
    tuple of (list of float, int) or None
        Stage ratios (output first) [-] and output rows [-]
    """
    envelope = (max_outer_diameter_mm, max_length_mm)
    viol = _violation(result, *envelope)
    key, tie = _keys(result, objective)
    found: _Point | None = None
    for n in _unique(result.stages):
        start = _point(result, _first(viol, key, tie, result.stages == n), viol, key, tie)
        cand = _polish(total_ratio, p, start, objective, envelope, points, passes)
        # a stage count counts once a polished point fits the envelope
        if cand.violation == 0.0 and (found is None or cand[1:3] < found[1:3]):
            found = cand
    return None if found is None else (found.ratios, found.rows)


def _violation(
    result: SweepResult, max_outer_diameter_mm: float | None, max_length_mm: float | None
) -> np.ndarray:
    """How far each configuration lies outside the envelope: 0 within it, else the larger
    relative excess of its outer diameter and its length over their limits. "Within" is
    exactly :func:`_within`'s comparison: a quotient rounded to 1 must not let a point one
    ulp outside pass for one inside."""
    v = np.zeros(result.mass_kg.size)
    if max_outer_diameter_mm is not None:
        v = np.maximum(v, result.outer_diameter_mm / max_outer_diameter_mm - 1.0)
    if max_length_mm is not None:
        v = np.maximum(v, result.length_mm / max_length_mm - 1.0)
    inside = _within(result, max_outer_diameter_mm, max_length_mm)
    return np.where(inside, 0.0, np.maximum(v, np.finfo(float).tiny))


def _first(
    violation: np.ndarray, key: np.ndarray, tie: np.ndarray, among: np.ndarray | None = None
) -> int:
    """The best index: the least violation of the envelope first (0 for every point within
    it), then the least objective, then the least tie-break."""
    idx = np.arange(key.size) if among is None else np.flatnonzero(among)
    return int(idx[np.lexsort((tie[idx], key[idx], violation[idx]))[0]])


def _within(
    result: SweepResult, max_outer_diameter_mm: float | None, max_length_mm: float | None
) -> np.ndarray:
    ok = np.ones(result.mass_kg.size, bool)
    if max_outer_diameter_mm is not None:
        ok &= result.outer_diameter_mm <= max_outer_diameter_mm
    if max_length_mm is not None:
        ok &= result.length_mm <= max_length_mm
    return ok


#: Points checked at once by :func:`pareto` (fewer: more numpy calls; more: larger arrays).
_BLOCK = 192
#: [i, j]: point i comes before point j within a block.
_BEFORE = np.triu(np.ones((_BLOCK, _BLOCK), bool), 1)


def _shortest_of_groups(result: SweepResult, ok: np.ndarray) -> np.ndarray:
    """Of configurations with the same stage count, output ratio and rows (the same
    diameters and efficiency) only the shortest can be non-dominated: the first of each."""
    # the sweep lists configurations by stage count, then chain (chains of one q_out are
    # contiguous), then rows: a run id per (stage count, q_out) and the rows make the group
    n, qo = result.stages[ok], result.q_out[ok]
    new_run = np.ones(ok.size, bool)
    new_run[1:] = (n[1:] != n[:-1]) | (qo[1:] != qo[:-1])
    group = np.cumsum(new_run) * 64 + result.rows_out[ok]
    order = np.argsort(group, kind="stable")
    g = group[order]
    first = np.concatenate(([True], g[1:] != g[:-1]))  # of its group
    group_no = np.cumsum(first) - 1
    length = result.length_mm[ok][order]
    shortest = np.minimum.reduceat(length, np.flatnonzero(first))
    at_min = np.flatnonzero(length == shortest[group_no])  # every shortest, in order
    of = group_no[at_min]
    first_shortest = at_min[np.concatenate(([True], of[1:] != of[:-1]))]
    return ok[order[first_shortest]]


def _fewest_stages(result: SweepResult, cand: np.ndarray) -> np.ndarray:
    """The same output stage (q_out, rows: the same diameters) with fewer stages is shorter,
    lighter and more efficient: the fewest stages of each, sorted by mass, then diameter,
    length and stages (a point can only be dominated by earlier ones)."""
    by_stage = cand[np.lexsort((result.stages[cand], result.rows_out[cand], result.q_out[cand]))]
    qo, rw = result.q_out[by_stage], result.rows_out[by_stage]
    cand = by_stage[np.r_[True, (qo[1:] != qo[:-1]) | (rw[1:] != rw[:-1])]]
    mass = result.mass_kg[cand]
    order = np.argsort(mass)  # distinct masses: the order of the lexsort below, faster
    ascending = mass[order]
    if (ascending[1:] == ascending[:-1]).any():  # equal masses: the other objectives decide
        order = np.lexsort(
            (result.stages[cand], result.length_mm[cand], result.outer_diameter_mm[cand], mass)
        )
    return cand[order]


def _ranks(x: np.ndarray) -> np.ndarray:
    """Each value's rank among ``x`` (equal values, equal ranks) as small integers: they
    order exactly as the values do, and compare faster in the (block, block) arrays."""
    order = np.argsort(x)
    ascending = x[order]
    ranks = np.empty(x.size, np.int16 if x.size < 2**15 else np.int32)
    ranks[order] = np.cumsum(np.concatenate(([False], ascending[1:] != ascending[:-1])))
    return ranks


def _covered(by: np.ndarray, points: np.ndarray) -> np.ndarray:
    """[i, j]: point i of ``by`` is no worse than point j of ``points`` in every objective
    (rows: objectives; one comparison array per objective, faster than one 3-D array)."""
    covered = by[0][:, None] <= points[0]
    for k in range(1, by.shape[0]):
        covered &= by[k][:, None] <= points[k]
    return covered


def _non_dominated(result: SweepResult, cand: np.ndarray) -> np.ndarray:
    """The non-dominated of ``cand`` (sorted as :func:`_fewest_stages` sorts) by mass,
    diameter, length and stages (fewer: higher efficiency η^n, lower losses).

    In this order whatever dominates a point comes before it, and (dominance being
    transitive) so does a non-dominated point that dominates it: each block is checked
    against the front so far, then what survives against the survivors before it within
    the block (a point dominated by one the front dominates is dominated by the front). A
    point before another is no heavier, so mass needs no comparison. A point equal in every
    objective to an earlier one goes too (duplicates are kept once)."""
    obj = np.stack(
        [
            _ranks(result.outer_diameter_mm[cand]),
            _ranks(result.length_mm[cand]),
            result.stages[cand].astype(np.int16),  # 1…4
        ]
    )  # (objective, point)
    front_obj = obj[:, :0]
    front = []
    for start in range(0, cand.size, _BLOCK):
        blk, idx = obj[:, start : start + _BLOCK], cand[start : start + _BLOCK]
        alive = ~_covered(front_obj, blk).any(axis=0)  # most fall to the front so far
        blk, idx = blk[:, alive], idx[alive]
        b = idx.size
        keep = ~(_covered(blk, blk) & _BEFORE[:b, :b]).any(axis=0)
        front_obj = np.concatenate([front_obj, blk[:, keep]], axis=1)
        front.append(idx[keep])
    return np.concatenate(front) if front else cand[:0]


def pareto(
    result: SweepResult,
    stage_efficiency: float,
    max_outer_diameter_mm: float | None = None,
    max_length_mm: float | None = None,
) -> np.ndarray:
    """Indices of the non-dominated configurations within the envelope, sorted by mass.

    Objectives: least mass, least outer diameter, least length and highest efficiency
    (η^n with ``stage_efficiency`` η; the losses follow it). Of configurations with the
    same stage count, output ratio and rows only the shortest can be non-dominated;
    duplicates are kept once.

    Parameters
    ----------
    result : SweepResult
        The design space (:func:`sweep`)
    stage_efficiency : float
        Efficiency of one stage η [-]
    max_outer_diameter_mm, max_length_mm : float, optional
        Envelope [mm]; None: no limit

    Returns
    -------
    numpy.ndarray
        Indices into ``result``, lightest first

    References: seed 000, eqs. (13)–(19) give the objectives.
    """
    ok = np.nonzero(_within(result, max_outer_diameter_mm, max_length_mm))[0]
    if ok.size == 0:
        return ok
    cand = _fewest_stages(result, _shortest_of_groups(result, ok))
    return _non_dominated(result, cand)


def _unique(a: np.ndarray) -> np.ndarray:
    """The distinct values of ``a``, sorted: ``np.unique`` for finite values, without the
    import of ``numpy.ma`` that ``np.unique`` makes on its first call (10–40 ms of a cold
    run)."""
    s = np.sort(a, axis=None)
    return s[np.concatenate(([True], s[1:] != s[:-1]))] if s.size else s


def thin(front: np.ndarray, at_most: int) -> np.ndarray:
    """At most ``at_most`` of the ``front`` (sorted by mass), evenly spaced along it, the
    lightest and the heaviest always kept.

    Parameters
    ----------
    front : numpy.ndarray
        Indices of the front, sorted by mass
    at_most : int
        Most points kept [-]

    Returns
    -------
    numpy.ndarray
        The indices kept
    """
    if front.size <= at_most:
        return front
    return front[_unique(np.round(np.linspace(0, front.size - 1, at_most)).astype(int))]


def dominator(
    result: SweepResult,
    r: Reducer,
    max_outer_diameter_mm: float | None = None,
    max_length_mm: float | None = None,
    rel: float = 1e-9,
) -> int | None:
    """Index of the configuration that dominates reducer ``r`` (no heavier, wider, longer or
    with more stages, and better in one of them by more than ``rel``), the lightest of them
    (ties by diameter, length), or ``None`` if ``r`` is non-dominated in the design space.

    Parameters
    ----------
    result : SweepResult
        The design space (:func:`sweep`)
    r : Reducer
        The reducer judged
    max_outer_diameter_mm, max_length_mm : float, optional
        Envelope [mm]; None: no limit
    rel : float, optional
        Relative margin by which the dominating one must be better [-]

    Returns
    -------
    int or None
        Index into ``result``; None when ``r`` is non-dominated
    """
    ok = _within(result, max_outer_diameter_mm, max_length_mm)
    n = len(r.stages)
    m, D, L = r.mass_kg * (1 + rel), r.outer_diameter_mm * (1 + rel), r.length_mm * (1 + rel)
    weak = ok & (result.mass_kg <= m) & (result.outer_diameter_mm <= D)
    weak &= (result.length_mm <= L) & (result.stages <= n)
    strict = (result.mass_kg < r.mass_kg * (1 - rel)) | (
        result.outer_diameter_mm < r.outer_diameter_mm * (1 - rel)
    )
    strict |= (result.length_mm < r.length_mm * (1 - rel)) | (result.stages < n)
    idx = np.nonzero(weak & strict)[0]
    if idx.size == 0:
        return None
    order = np.lexsort((result.length_mm[idx], result.outer_diameter_mm[idx], result.mass_kg[idx]))
    return int(idx[order[0]])
