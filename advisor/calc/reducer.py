"""A reducer of wave gear stages in the equal-diameter layout, and its design space.

The output stage sets the diameters (eqs. (13), (14) with d_тк from (16) at the output
torque); the other stages share them and differ only in length, L_k = L_out·∛(1/Πq) between
stage k and the output (seed 000, after eq. (19)). Stage torques fall through the chain:
the stage before a stage of ratio q and efficiency η carries M/(q·η).

:func:`sweep` evaluates every stage count, split, output ratio and output row count at once
with numpy broadcasting; :func:`evaluate` evaluates one configuration with the same code, so
the rule-based design and the optimum are computed alike.
"""

from typing import NamedTuple

import numpy as np

from advisor.calc import wavegear as wg

#: Ratio limits of one stage: a positive bore needs q > 6.45 (eq. (14)); seed 000's fig. 2
#: spans intermediate ratios 6…60 and its two-stage case uses up to 63.
STAGE_RATIO_MIN = 6.5
STAGE_RATIO_MAX = 64.0
#: Output-stage ratios swept (the issue's design space) and row counts (seed 000 fig. 1).
OUTPUT_RATIO_GRID = np.arange(7.0, 40.0 + 1e-9, 0.5)
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


def evaluate(ratios_out_to_in: list[float], rows_out_to_in: list[int], p: ReducerParams) -> Reducer:
    """One reducer; ratios and rows listed from the output stage towards the motor."""
    n = len(ratios_out_to_in)
    torque = p.torque_Nm
    q0 = ratios_out_to_in[0]
    d_out = float(wg.rolling_body_diameter(torque, q0, rows_out_to_in[0], p.k_rb))
    D = float(wg.outer_diameter(q0, d_out))
    d = float(wg.inner_diameter(q0, d_out))
    L_out = float(wg.stage_length(rows_out_to_in[0], d_out))
    stages = []
    downstream = 1.0  # product of the ratios between this stage and the output
    for i, (q, rows) in enumerate(zip(ratios_out_to_in, rows_out_to_in, strict=True)):
        d_rb = float(wg.rolling_body_diameter(torque, q, rows, p.k_rb))
        length = float(wg.equal_diameter_length(L_out, downstream))
        vol = float(wg.hollow_cylinder_volume(D, d, length))
        position = "output" if i == 0 else ("input" if i == n - 1 else "intermediate")
        stages.append(
            Stage(
                position,
                q,
                rows,
                torque,
                d_rb,
                float(wg.outer_diameter(q, d_rb)),
                float(wg.inner_diameter(q, d_rb)),
                D,
                d,
                length,
                float(wg.mass_kg(vol, p.density_kg_m3, p.fill_factor)),
            )
        )
        downstream *= q
        torque = torque / (q * p.stage_efficiency)
    length = sum(s.length_mm for s in stages)
    volume = float(wg.hollow_cylinder_volume(D, d, length))
    return Reducer(
        stages=tuple(reversed(stages)),
        total_ratio=downstream,
        efficiency=p.stage_efficiency**n,
        outer_diameter_mm=D,
        inner_diameter_mm=d,
        length_mm=length,
        volume_mm3=volume,
        mass_kg=float(wg.mass_kg(volume, p.density_kg_m3, p.fill_factor)),
    )


class SweepResult(NamedTuple):
    """Flat arrays, one entry per feasible configuration."""

    stages: np.ndarray
    q_out: np.ndarray
    q_mid: np.ndarray  # the ratios between output and input stage, (N, 2), NaN where absent
    q_in: np.ndarray  # NaN for a single stage
    rows_out: np.ndarray
    outer_diameter_mm: np.ndarray
    length_mm: np.ndarray
    mass_kg: np.ndarray
    evaluated: int  # configurations examined, feasible or not

    def ratios_out_to_in(self, i: int) -> list[float]:
        out = [float(self.q_out[i])]
        out += [float(x) for x in self.q_mid[i] if not np.isnan(x)]
        if not np.isnan(self.q_in[i]):
            out.append(float(self.q_in[i]))
        return out


def sweep(total_ratio: float, p: ReducerParams, max_stages: int = 4) -> SweepResult:
    """Every stage count (1…max_stages), split, output ratio (7…40) and output row count
    (2…12) that realises ``total_ratio`` with every stage ratio within limits."""
    parts = []
    evaluated = 0
    for n in range(1, max_stages + 1):
        if n == 1:
            q_out = OUTPUT_RATIO_GRID[np.isclose(OUTPUT_RATIO_GRID, total_ratio)]
            if q_out.size == 0 and 7.0 <= total_ratio <= 40.0:
                q_out = np.array([total_ratio])
            grids = np.meshgrid(q_out, ROW_GRID, indexing="ij")
            qo, rows = (g.ravel() for g in grids)
            mids = np.full((qo.size, 2), np.nan)
            q_in = np.full(qo.size, np.nan)
            ok = np.ones(qo.size, bool)
        else:
            n_mid = n - 2
            axes = [OUTPUT_RATIO_GRID] + [INTERMEDIATE_RATIO_GRID] * n_mid + [ROW_GRID]
            grids = np.meshgrid(*axes, indexing="ij")
            flat = [g.ravel() for g in grids]
            qo, rows = flat[0], flat[-1]
            mids = np.full((qo.size, 2), np.nan)
            prod = qo.copy()
            for j in range(n_mid):
                mids[:, j] = flat[1 + j]
                prod = prod * flat[1 + j]
            q_in = total_ratio / prod
            ok = (q_in >= STAGE_RATIO_MIN) & (q_in <= STAGE_RATIO_MAX)
        evaluated += qo.size
        if not ok.any():
            continue
        qo, rows, mids, q_in = qo[ok], rows[ok], mids[ok], q_in[ok]
        d_rb = wg.rolling_body_diameter(p.torque_Nm, qo, rows, p.k_rb)
        D = wg.outer_diameter(qo, d_rb)
        d = wg.inner_diameter(qo, d_rb)
        L_out = wg.stage_length(rows, d_rb)
        length = L_out.copy()
        downstream = qo.copy()
        for j in range(n - 1):
            length = length + wg.equal_diameter_length(L_out, downstream)
            nxt = mids[:, j] if j < n - 2 else q_in
            downstream = downstream * nxt
        mass = wg.mass_kg(wg.hollow_cylinder_volume(D, d, length), p.density_kg_m3, p.fill_factor)
        parts.append(
            (np.full(qo.size, n), qo, mids, np.where(n == 1, np.nan, q_in), rows, D, length, mass)
        )
    if not parts:
        empty = np.array([])
        return SweepResult(
            empty, empty, np.empty((0, 2)), empty, empty, empty, empty, empty, evaluated
        )
    cols = list(zip(*parts, strict=True))
    return SweepResult(
        stages=np.concatenate(cols[0]),
        q_out=np.concatenate(cols[1]),
        q_mid=np.concatenate(cols[2]),
        q_in=np.concatenate(cols[3]),
        rows_out=np.concatenate(cols[4]),
        outer_diameter_mm=np.concatenate(cols[5]),
        length_mm=np.concatenate(cols[6]),
        mass_kg=np.concatenate(cols[7]),
        evaluated=evaluated,
    )


def best(
    result: SweepResult,
    objective: str,
    max_outer_diameter_mm: float | None = None,
    max_length_mm: float | None = None,
) -> int | None:
    """Index of the lightest (``"mass"``) or slimmest (``"diameter"``) configuration within
    the envelope; ``None`` if none fits."""
    ok = np.ones(result.mass_kg.size, bool)
    if max_outer_diameter_mm is not None:
        ok &= result.outer_diameter_mm <= max_outer_diameter_mm
    if max_length_mm is not None:
        ok &= result.length_mm <= max_length_mm
    if not ok.any():
        return None
    key = result.mass_kg if objective == "mass" else result.outer_diameter_mm
    masked = np.where(ok, key, np.inf)
    return int(np.argmin(masked))
