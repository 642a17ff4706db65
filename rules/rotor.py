"""Rules of the spinning-rotor drive (seed 002)."""

from advisor.core.cite import cite
from advisor.core.rulebook import Finding, rule

SEED_002 = cite("seed-002")


@rule("RO-01", "Design load on the bearings", SEED_002)
def design_loads(
    moment_Nm: float, axial_N: float, radial_N: float, preload_N: float, weight_share_N: float
) -> Finding[float]:
    return Finding(
        moment_Nm,
        f"Gyroscopic moment {moment_Nm:.4g} N·m: {radial_N:.4g} N radial and {axial_N:.4g} N "
        f"axial on each bearing; preload {preload_N:.4g} N.",
        "Seed 002: the reaction is taken at ωt = 0 of eq. (3), where the ball lies in the plane "
        "normal to the moment and the force is largest; it does not depend on the number of "
        "balls. The preload F_H ≈ 1.58·F_r·tan β is set with every radial component "
        f"(weight {weight_share_N:.4g} N per bearing plus the reaction), not with the weight "
        "alone (conclusion 2 of the seed).",
        {
            "gyroscopic_moment_Nm": moment_Nm,
            "reaction_radial_N": radial_N,
            "reaction_axial_N": axial_N,
            "preload_N": preload_N,
        },
    )


@rule("RO-02", "Drive torque", SEED_002)
def drive_torque(
    run_up_Nm: float, steady_with_reaction_Nm: float, run_up_time_s: float
) -> Finding[float]:
    # within rounding the two are the same torque (no slew): keep the run-up's, whose time
    # is known
    run_up_decides = run_up_Nm >= steady_with_reaction_Nm * (1.0 - 1e-9)
    chosen = run_up_Nm if run_up_decides else steady_with_reaction_Nm
    why = (
        f"the run-up in {run_up_time_s:g} s needs {run_up_Nm:.4g} N·m, at least the "
        f"{steady_with_reaction_Nm:.4g} N·m that holds speed under the gyroscopic load"
        if run_up_decides
        else f"holding speed under the gyroscopic load needs {steady_with_reaction_Nm:.4g} N·m, "
        f"more than the {run_up_Nm:.4g} N·m of the run-up in {run_up_time_s:g} s"
    )
    return Finding(
        chosen,
        f"{chosen:.4g} N·m: {why}.",
        "Seed 002, conclusion 4: for an idling rotor the readiness time, not the steady power, "
        "sizes the drive; the required torque comes from solving the motion equation (5) for "
        "the time. The drive runs at that torque only while starting, so a higher current "
        "density is acceptable in its windings.",
        {
            "required_torque_Nm": chosen,
            "run_up_torque_Nm": run_up_Nm,
            "steady_with_reaction_Nm": steady_with_reaction_Nm,
        },
    )


@rule("RO-03", "Bearing friction model", SEED_002)
def friction_model(lambda_mm: float) -> Finding[float]:
    return Finding(
        lambda_mm,
        f"Eq. (4) with rolling friction λ = {lambda_mm:g} mm; the SKF model beside it.",
        "Seed 002 sums radial, axial and centrifugal terms with a rolling-friction length λ. "
        "The paper does not print λ; its radial and axial rows agree with λ ≈ 0.028 mm, the "
        "default. The SKF catalogue model (rolling + sliding, inlet shear heating) is reported "
        "as a second opinion with the lubricant viscosity given.",
        {"rolling_friction_mm": lambda_mm},
    )
