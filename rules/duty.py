"""Rules of a duty cycle: the motor and ratio for the cycle, the thermal verdict,
the inertia ratio against its guideline, the starts an induction motor allows."""

from advisor.calc.duty import S2_POWER_FACTOR, S3_POWER_FACTOR
from advisor.core.cite import cite, note
from advisor.core.rulebook import Finding, rule

IEC_60034_1 = cite("iec-60034-1", "duty types S1–S10")
KLYUCHEV = cite("klyuchev", "method of equivalent torque")
INERTIA_GUIDE = (cite("keb-servo") + cite("autoengcalc")).with_note(
    "servo sizing practice: load/motor inertia ≤ 10 for a standard axis, ≤ 5 for high precision"
)
#: The duty cycle's own basis, not a published source: the advisor's method, written out in
#: docs/reference/duty.md, which the reports cite.
DUTY_METHOD = note("the advisor's duty-cycle method, docs/reference/duty.md")
SEED_003 = cite("seed-003")
#: SEW-EURODRIVE's table of the power increasing factor K for S2 and S3 (p. 95).
SEW_K = cite("sew-gearmotors", "§7.5, p. 95, power increasing factor K")
#: The guideline of servo practice for the reflected load over the motor's inertia.
INERTIA_RATIO_GUIDELINE = 10.0


@rule("DU-01", "Motor and ratio for the cycle", SEED_003.at("the move") + DUTY_METHOD)
def motor_for_cycle(rows: dict[str, tuple[float, float, bool, str]]) -> Finding[str]:
    """rows: name -> (move time, ratio, passes the cycle, why not)."""
    ok = {n: r for n, r in rows.items() if r[2]}
    best = min(ok, key=lambda n: ok[n][0])
    ranked = sorted(rows.items(), key=lambda kv: kv[1][0])
    shown = ranked[:5] + [kv for kv in ranked[5:] if not kv[1][2]][:3]
    table = "; ".join(
        f"{n}: {r[0]:.4g} s at i = {r[1]:.4g}" + ("" if r[2] else f" ({r[3]})") for n, r in shown
    )
    if len(ranked) > len(shown):
        table += f"; and {len(ranked) - len(shown)} more motors"
    return Finding(
        best,
        f"Motor {best} at i = {ok[best][1]:.4g}: the fastest move whose motor passes the cycle.",
        "Each motor's move is the fastest of seed 003 at the ratio where its RMS torque over "
        f"the cycle stays within its rated torque and the move fits in the cycle — {table}.",
        {"motor": best, "ratio": ok[best][1], "move_time_s": ok[best][0]},
    )


@rule("DU-08", "Induction motor for the cycle", IEC_60034_1 + DUTY_METHOD)
def motor_for_cycle_linear(
    rows: dict[str, tuple[float, list[str]]], point_motor: str, inertia_basis: str
) -> Finding[str]:
    """rows: model -> (rated power, problems), smallest first from the point's motor."""
    best = next(n for n, (_, problems) in rows.items() if not problems)
    tried = "; ".join(
        f"{n} ({p:g} kW): " + ("passes" if not pr else ", ".join(pr))
        for n, (p, pr) in rows.items()
        if n == best or pr
    )
    return Finding(
        best,
        f"Motor {best} for the cycle"
        + (" (the rated point's motor)." if best == point_motor else f", not {point_motor}."),
        "The smallest motor of the rated point's pole count, from the point's motor up, whose "
        "equivalent torque, starts per hour and starting torque pass the cycle — "
        f"{tried}. Load inertia at the motor: {inertia_basis}.",
        {"motor": best, "rated_power_kW": rows[best][0], "point_motor": point_motor},
    )


@rule("DU-02", "Ratio of least RMS torque", SEED_003.at("phase torques") + DUTY_METHOD)
def least_rms_ratio(
    motor: str, ratio: float, rms_Nm: float, chosen: float, chosen_rms_Nm: float
) -> Finding[float]:
    return Finding(
        ratio,
        f"{motor}: i = {ratio:.4g} gives the least RMS torque, {rms_Nm:.4g} N·m "
        f"(at the chosen i = {chosen:.4g}: {chosen_rms_Nm:.4g} N·m).",
        "RMS² = (M_λ²·(t_acc + t_brake) + (M_p/i)²·t_run)/T: a larger ratio lowers the "
        "running torque M_p/i, and past the inertia match the transients tend to 2·ω0·J0/M_λ, "
        "while the move lengthens; the least RMS often lies where the move fills the whole "
        "cycle. That ratio runs coolest, the chosen one moves fastest.",
        {
            "motor": motor,
            "min_rms_ratio": ratio,
            "min_rms_torque_Nm": rms_Nm,
            "ratio": chosen,
            "rms_torque_Nm": chosen_rms_Nm,
        },
    )


@rule("DU-03", "Inertia ratio", INERTIA_GUIDE)
def inertia_ratio(ratio: float, guideline: float = INERTIA_RATIO_GUIDELINE) -> Finding[bool]:
    within = ratio <= guideline
    return Finding(
        within,
        f"Load/motor inertia at the motor {ratio:.3g} "
        + ("within" if within else "above")
        + f" the guideline of {guideline:g}.",
        "The load's inertia reflected to the motor (J_load/q², through η where the drive has "
        "one) over the motor's: above about 10 a stiff, well-tuned control loop gets hard; it "
        "is a rule of practice, not a limit of physics, so it warns and does not refuse.",
        {"inertia_ratio": ratio, "guideline": guideline},
    )


@rule("DU-04", "Thermal verdict of the cycle", KLYUCHEV + IEC_60034_1)
def thermal(utilisation: float, basis: str) -> Finding[float]:
    return Finding(
        utilisation,
        f"Thermal utilisation {utilisation:.3g} ({'passes' if utilisation <= 1 else 'fails'}).",
        basis,
        {"thermal_utilisation": utilisation},
    )


@rule("DU-05", "Peak torque of the cycle", SEED_003 + DUTY_METHOD)
def peak(
    peak_Nm: float, limit_Nm: float, basis: str, cycle_peak_Nm: float | None = None
) -> Finding[float]:
    """``peak_Nm`` against its limit; ``cycle_peak_Nm``, where the value checked is not the
    cycle's peak (the linear duty checks the largest load torque against the starting
    torque), is named beside it, so that the decision states the design's own numbers."""
    said = f"Peak torque {peak_Nm:.4g} N·m against {limit_Nm:.4g} N·m."
    if cycle_peak_Nm is not None:
        said = (
            f"Largest load torque {peak_Nm:.4g} N·m against the starting torque "
            f"{limit_Nm:.4g} N·m; the cycle's peak torque is {cycle_peak_Nm:.4g} N·m."
        )
    inputs = {"peak_torque_Nm": peak_Nm, "peak_torque_limit_Nm": limit_Nm}
    if cycle_peak_Nm is not None:
        inputs["cycle_peak_torque_Nm"] = cycle_peak_Nm
    return Finding(peak_Nm, said, basis, inputs)


@rule("DU-06", "Starts per hour", cite("iec-60034-1", "S4, S5: inertia factor FI"))
def starts(required: float, allowed: float, basis: str) -> Finding[bool]:
    return Finding(
        required <= allowed,
        f"{required:.4g} starts/h against {allowed:.4g} allowed.",
        basis,
        {"starts_per_hour": required, "allowed_starts_per_hour": allowed},
    )


@rule("DU-07", "The duty as a cycle", IEC_60034_1)
def duty_type(name: str, description: str, how: str) -> Finding[str]:
    return Finding(name, f"Duty {name}: {description}.", how)


@rule("DU-09", "S1 motor in S2 or S3: power increasing factor", SEW_K + IEC_60034_1)
def power_increasing_factor(
    duty_type: str, value: float, k: float, on_time_min: float | None = None
) -> Finding[float]:
    """K of SEW's table (:func:`advisor.calc.duty.s2_power_factor`, ``s3_factor_for_cycle``):
    ``value`` is the S2 period in min or the S3 cyclic duration factor; ``on_time_min`` the
    S3 cycle's time under load (K held to at most the S2 factor of a run that long)."""
    if duty_type == "S2":
        rows = ", ".join(f"{p:g} min → {f:g}" for p, f in S2_POWER_FACTOR)
        what = f"S2 for {value:g} min"
        read = (
            "a period between two rows takes the next longer row's K, one over 60 min is S1 "
            "(K = 1), one under 10 min keeps 1.4 (the table is not extrapolated)"
        )
        extra = (
            " The catalog gives no thermal time constant, so the rise over the run is not computed."
        )
    else:
        rows = ", ".join(f"cdf {100 * c:g} % → {f:g}" for c, f in S3_POWER_FACTOR)
        what = f"S3 at cdf {100 * value:.4g} %"
        read = (
            "a cdf between two rows takes the next larger cdf's K, one over 60 % is S1 "
            "(K = 1), one under 15 % keeps 1.4"
        )
        cap = (
            f" SEW's S3 table is for a cycle of about 10 min: K is held to at most the S2 factor "
            f"of one run as long as the on-time, here {on_time_min:.4g} min."
            if on_time_min is not None
            else ""
        )
        extra = cap + (
            " It is checked beside the equivalent torque (DU-04), which with β0 = 0.5 allows "
            "more: the stricter of the two decides. SEW's rating also counts the losses that "
            "do not fall with the load and the temperature's ripple over the cycle."
        )
    return Finding(
        k,
        f"{what}: the motor may carry K = {k:g} times its rated load.",
        f"SEW's power increasing factor for an S1 motor in {duty_type} ({rows}); {read}. At "
        "an induction motor's near-constant speed a factor on the power is a factor on the "
        f"torque.{extra}",
        {"value": value, "k": k}
        | ({"on_time_min": on_time_min} if on_time_min is not None else {}),
    )
