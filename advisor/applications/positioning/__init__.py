"""The positioning drive (seed 003): the ratio for the fastest move."""
