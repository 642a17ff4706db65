"""The rotary actuator (seed 000): PM brushless motor + wave-gear reducer."""
