"""Product-family studies: ``advisor family FAMILY.toml --out DIR``.

A family is a base requirement plus axes (dotted requirement keys, each with a list of
values or a range); its variants are the product of the axes. The variants are advised in
chunks, by worker processes on this machine or on a ``dask.distributed`` cluster
(``--scheduler``), and gathered into ``designs.csv``, ``summary.toml`` and ``family.html``.

Modules, from the inside out:

- :mod:`advisor.family.adapter`: the ONE call into the engine (``advise_one``);
- :mod:`advisor.family.outputs`: the key outputs of each application, from its report;
- :mod:`advisor.family.spec`: reading the family file, the axes and the variants;
- :mod:`advisor.family.cells`: the columns of ``designs.csv`` and its cells;
- :mod:`advisor.family.summary`: ``summary.toml``, from the parts each chunk's worker
  tallies, merged as the chunks arrive;
- :mod:`advisor.family.chunks`: what one task does (advise a block of variants, tally it);
- :mod:`advisor.family.local`: the chunks run on this machine (in-process or forked workers);
- :mod:`advisor.family.study`: the run (locally or on Dask), resume and progress;
- :mod:`advisor.family.html` and :mod:`advisor.family.svg`: ``family.html``, from the
  summary alone.

Dask is imported only with ``--scheduler``, never on the batch path.
"""

from advisor.core import pydantic_plugins

# as on the batch path: pydantic need not scan every installed package for plugins (the
# workers import this package before any model)
pydantic_plugins.disable()
