"""A number's valid range is declared once, in its constraint: the prose of every requirement
field that states a range is made from it (advisor.core.ranges), so the two cannot disagree."""

import pytest
from pydantic import BaseModel

from advisor.core.ranges import range_prose
from advisor.core.registry import applications, load
from advisor.core.requirements import RANGE, range_in_words

#: Fields whose prose states a range the constraint cannot: 0 or a least value (checked by
#: their requirement_checks), or a limit better read as a formula (2³²−1).
ZERO_OR_FROM = {
    "load_share",
    "force_N",
    "loss_W",
    "load_inertia_kgm2",
    "load_torque_Nm",
    "slew_rate_rad_s",
    "seed",
}


def _fields():
    seen, out = set(), []

    def walk(model):
        if model in seen:
            return
        seen.add(model)
        for name, info in model.model_fields.items():
            out.append((model, name, info))
            ann = info.annotation
            for a in (ann, *getattr(ann, "__args__", ())):
                for b in (a, *getattr(a, "__args__", ())):
                    if isinstance(b, type) and issubclass(b, BaseModel):
                        walk(b)

    for app in applications():
        walk(load(app.requirements))
    return out


FIELDS = _fields()


#: Every field whose description states a numeric range ("… 10⁵ N·m").
STATED = [
    (m, n, i)
    for m, n, i in FIELDS
    if i.description and " … " in i.description and range_in_words(n, i) and n not in ZERO_OR_FROM
]


@pytest.mark.parametrize(
    ("model", "name", "info"), STATED, ids=[f"{m.__name__}.{n}" for m, n, _ in STATED]
)
def test_a_range_in_prose_is_the_constraints(model, name, info):
    assert range_in_words(name, info) in info.description, (model.__name__, info.description)


def test_no_placeholder_is_left():
    assert not [f"{m.__name__}.{n}" for m, n, i in FIELDS if RANGE in (i.description or "")]


def test_the_wizard_shows_the_ranges_it_did():
    """The two ranges the wizard's snapshots show read as they did before they were derived."""
    assert range_prose("N", ge=1, le=5e6) == "1 N … 5 MN"
    assert range_prose("m", ge=1e-3, le=20) == "1 mm … 20 m"
