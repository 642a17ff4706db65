"""The one-way (holding) device (seed 004), shared by the linear and rotary actuators."""
