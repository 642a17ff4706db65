"""The candidate motors of a positioning drive (seed 003): the listed motors, or the induction
motors of the catalog at their rated speed with their starting torque; each with the size that
ranks them where a move time is required (MO-05)."""

import math
from dataclasses import dataclass, replace

from advisor.calc.motion import RATIO_MAX, Drive, RatioSolution, move_time, solve_ratio
from advisor.core.errors import InfeasibleError
from advisor.core.reading import Requirements
from catalogs import Catalogs
from rules.motion import INERTIA_BAND


@dataclass(frozen=True, slots=True)
class Candidate:
    """One candidate motor driving the load."""

    name: str
    drive: Drive
    power_W: float  # the size that ranks it (MO-05)
    inertia_estimated: bool  # its rotor inertia is an estimate (MO-05 counts it higher)


@dataclass(frozen=True, slots=True)
class CandidateSet:
    """The candidates, what their size is, and what the report must say about them."""

    candidates: tuple[Candidate, ...]
    power_basis: str
    warnings: tuple[str, ...]


@dataclass(frozen=True, slots=True)
class Solved:
    """A candidate at its own fastest ratio."""

    candidate: Candidate
    solution: RatioSolution

    @property
    def name(self) -> str:
        return self.candidate.name

    @property
    def drive(self) -> Drive:
        return self.candidate.drive


def inertia_is_estimate(motor) -> bool:
    """Whether a catalog motor's rotor inertia is an estimated value (its row's ``estimated``)."""
    return "inertia_kgm2" in motor.estimated


def decisive_inertia(inertia_kgm2: float, estimated: bool) -> float:
    """The rotor inertia a decision holds a motor to (MO-05): an estimated one at the top of
    its band, J0·(1 + INERTIA_BAND), so that the estimate never makes a motor look fast enough
    or its starts look few enough; a given one as it is.

    >>> round(decisive_inertia(0.00079, True), 9), decisive_inertia(0.00079, False)  # 0.00079·1.3
    (0.001027, 0.00079)
    """
    return inertia_kgm2 * (1.0 + INERTIA_BAND) if estimated else inertia_kgm2


def held_to(s: Solved, path_rad: float, profile: str) -> Solved:
    """The candidate as the decisions hold it: with an estimated inertia, its drive at the
    decisive inertia (:func:`decisive_inertia`) and its fastest ratio there (seed 003); a given
    inertia, itself. Its ``inertia_estimated`` stays set, so apply it once."""
    c = s.candidate
    if not c.inertia_estimated:
        return s
    d = c.drive._replace(inertia_kgm2=decisive_inertia(c.drive.inertia_kgm2, True))
    return Solved(replace(c, drive=d), solve_ratio(d, path_rad, profile))


def held_as_built(s: Solved, path_rad: float) -> Solved:
    """The candidate as built, at its fastest ratio with the catalog's inertia (seed 003), and
    judged as the decisions judge a single move: an estimated inertia at the top of its band
    (:func:`decisive_inertia`), the move that then happens at that same ratio. A given inertia:
    itself. The ratio the raised inertia would make fastest is not the one built: for a
    triangular move the built drive is the slower (4A132M4: 0.16854 s at i = 7.07 against
    0.16782 s at i = 6.20), and a required time between the two must be refused."""
    c = s.candidate
    if not c.inertia_estimated:
        return s
    d = c.drive._replace(inertia_kgm2=decisive_inertia(c.drive.inertia_kgm2, True))
    t, law = move_time(d, path_rad, s.solution.ratio)
    return Solved(replace(c, drive=d), replace(s.solution, move_time_s=t, profile=law))


def listed_candidates(req: Requirements) -> CandidateSet:
    """The motors of [[positioning.motors]], sized by their rated power M_n·ω0, or, without a
    rated torque for every motor, by the power M_λ·ω0 at their starting torque."""
    pos = req.positioning
    rated = all(m.rated_torque_Nm is not None for m in pos.motors)
    return CandidateSet(
        tuple(
            Candidate(
                m.name,
                Drive(
                    m.speed_rad_s,
                    m.inertia_kgm2,
                    m.accel_torque_Nm,
                    pos.load_inertia_kgm2,
                    pos.load_torque_Nm,
                ),
                (m.rated_torque_Nm if rated else m.accel_torque_Nm) * m.speed_rad_s,
                False,
            )
            for m in pos.motors
        ),
        "rated power M_n·ω0"
        if rated
        else "power at the starting torque M_λ·ω0 (no rated torque listed for every motor)",
        (),
    )


def catalog_candidates(req: Requirements, cat: Catalogs) -> CandidateSet:
    """The induction motors of the catalog at their rated speed with their starting torque,
    sized by their rated power; a note says so, and how many inertias are estimates."""
    pos = req.positioning
    found = tuple(
        Candidate(
            m.model,
            Drive(
                m.rated_speed_rpm * math.pi / 30.0,
                m.inertia_kgm2,
                m.starting_torque_ratio * m.rated_torque_Nm,
                pos.load_inertia_kgm2,
                pos.load_torque_Nm,
            ),
            m.rated_power_kW * 1e3,
            inertia_is_estimate(m),
        )
        for m in cat.motors
    )
    estimated = len({c.name for c in found if c.inertia_estimated})
    note = (
        "no [[positioning.motors]] given: candidates are the induction motors of the catalog "
        "at their rated speed with their starting torque"
    )
    if estimated:
        note += (
            f"; the rotor inertias of {estimated} of them are estimated values, counted "
            f"{INERTIA_BAND * 100:.0f} % higher where they decide (MO-05)"
        )
    return CandidateSet(found, "rated power of the catalog", (note,))


def candidates(req: Requirements, cat: Catalogs) -> CandidateSet:
    """The listed motors, or without them the catalog's."""
    if req.positioning.motors:
        return listed_candidates(req)
    return catalog_candidates(req, cat)


def usable(cands: CandidateSet) -> tuple[tuple[Candidate, ...], list[str]]:
    """The candidates that can be given a ratio that moves the load with some margin, and a
    warning naming how many were left out; none: no feasible design.

    A motor whose torque only balances the load near the top of the ratios searched cannot be
    given a ratio that moves the load with any margin."""
    kept = tuple(c for c in cands.candidates if c.drive.torque_ratio < RATIO_MAX / 2.0)
    if not kept:
        m_min = min(c.drive.torque_ratio for c in cands.candidates)
        raise InfeasibleError(
            f"no feasible design: no motor can move the load through a ratio up to {RATIO_MAX:g}",
            [
                f"the least ratio at which a motor balances the load, m = M_p/M_λ, is "
                f"{m_min:.4g} (needs a ratio below {RATIO_MAX / 2:g}); give a stronger motor "
                "or check the load torque"
            ],
        )
    dropped = len(cands.candidates) - len(kept)
    warnings = []
    if dropped:
        warnings.append(
            f"{dropped} motor(s) left out: each needs a ratio above {RATIO_MAX / 2:g} only to "
            "balance the load torque"
        )
    return kept, warnings
