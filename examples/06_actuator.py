"""Control of a hysteretic MSMA actuator: open loop, inverse (IGPI) feedforward, PID, and PID with
the feedforward, compared on steps, sines and a triangle with internal loops.

The parameter set is the [ASSUMED] synthetic MSMA set of the reference (not measured values); the
figures are simulated. Run: PYTHONPATH=build/python python3 examples/06_actuator.py
"""

from pathlib import Path

import numpy as np

import hyst

config = hyst.load_actuator_config(Path(__file__).parent / "config" / "msma_assumed.json")
print(config.name, "-", config.description)

plant = config.linearised_plant()
print(f"linearised plant: DC gain {plant.dc_gain:.4g} m/V, poles {plant.poles()}")

# One run: a 5 Hz sine between 0.2 and 0.8 mm under PID + inverse feedforward.
t = np.arange(0.0, 0.4, config.sample_time)
reference = 5e-4 + 3e-4 * np.sin(2 * np.pi * 5.0 * t)
run = config.simulate(reference, "pid_feedforward")
# Scored after the first 0.1 s: the run starts at rest at 0 A, far from the reference.
error = (reference - run["measured"])[t >= 0.1]
print(f"5 Hz sine, PID + feedforward: RMS error after 0.1 s {1e6 * np.sqrt(np.mean(error**2)):.2f} um")

# The comparison of the four strategies on the configuration's scenarios.
rows, table = config.compare()
print(table)
