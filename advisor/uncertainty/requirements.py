"""The optional ``[uncertainty]`` table: which inputs are known only as a
distribution, how many samples, the seed, and the probability of passing a robust choice
must reach. Imported by the applications' requirement models (no numpy here)."""

from typing import Annotated, Literal

from pydantic import Field

from advisor.core.requirements import StrictModel, after_check, ask, number_field
from advisor.uncertainty import checks

#: The inputs a distribution may be given for: requirement fields and model parameters.
InputName = Literal[
    "linear.force_N",
    "linear.support_span_m",
    "screw.friction_coefficient",
    "screw.thrust.friction_coefficient",
]


class InputDistribution(StrictModel):
    """One uncertain input: a uniform range, a normal law with its standard deviation, or a
    triangular law; the normal's mean and the triangle's mode default to the nominal value."""

    name: Annotated[
        InputName,
        Field(
            description="the input: linear.force_N, linear.support_span_m, "
            "screw.friction_coefficient or screw.thrust.friction_coefficient"
        ),
    ]
    distribution: Annotated[
        Literal["uniform", "normal", "triangular"],
        Field(description="uniform (low, high), normal (sd, mean), triangular (low, mode, high)"),
    ]
    low: Annotated[
        float | None, number_field(desc="lower end, in the input's unit", label="Low")
    ] = None
    high: Annotated[
        float | None, number_field(desc="upper end, in the input's unit", label="High")
    ] = None
    sd: Annotated[
        float | None,
        number_field(gt=0, desc="standard deviation of a normal law, {range}", label="Std. dev."),
    ] = None
    mean: Annotated[
        float | None,
        number_field(desc="mean of a normal law; left out: the nominal value", label="Mean"),
    ] = None
    mode: Annotated[
        float | None,
        number_field(desc="mode of a triangular law; left out: the nominal value", label="Mode"),
    ] = None

    _complete = after_check(checks.distribution_complete)


class UncertaintyReq(StrictModel):
    """The ``[uncertainty]`` table: the chosen design held fixed and every check evaluated
    over samples of the uncertain inputs; ``target`` makes the choice robust."""

    samples: Annotated[
        int, ask("Latin hypercube samples, {range}", label="Samples", ge=100, le=1_000_000)
    ] = 10_000
    seed: Annotated[
        int, ask("random seed (same seed, same numbers), 0 … 2³²−1", ge=0, le=2**32 - 1)
    ] = 1
    target: Annotated[
        float | None,
        ask(
            gt=0,
            lt=1,
            allow_inf_nan=False,
            desc="required probability of passing every check, {range}: the lightest candidate "
            "that reaches it is chosen; left out: the nominal choice, with its probability",
            label="Target P(pass)",
        ),
    ] = None
    inputs: Annotated[
        list[InputDistribution],
        ask(
            "uncertain inputs; screw.friction_coefficient defaults to the material pair's "
            "friction range (uniform)",
            max_length=20,
            extra={"row-label": "Input"},
        ),
    ] = []  # noqa: RUF012 - pydantic copies field defaults

    _unique = after_check(checks.unique_inputs)


#: The optional ``[uncertainty]`` table an application's requirement model declares.
UncertaintyField = Annotated[
    UncertaintyReq | None,
    Field(description="the [uncertainty] table: samples, seed, target, inputs"),
]
