"""Shipped catalog data and their validated loaders.

Every catalog is a TOML file in this folder, validated on load by a pydantic model; a broken
or inconsistent entry raises :class:`advisor.core.errors.CatalogError` naming the file, the row and
the field. Every row carries its source.

A user catalog directory (``--catalog-dir``) may hold files with the same names; their rows
are added to (motors, threads) or override (materials) the shipped ones.
"""

from catalogs.loader import Catalogs, load_catalogs

__all__ = ["Catalogs", "load_catalogs"]
