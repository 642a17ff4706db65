"""The spinning-rotor drive (seed 002): a high-speed rotor under gyroscopic load."""
