"""The linear actuator (seed 001): induction motor + sliding screw–nut."""
