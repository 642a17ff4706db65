"""Pure calculations: SI in, SI out, no I/O, no decisions."""
