"""Stack the per-rotor quantities of several rotor sets into one set (e.g. lift rotors + pusher)."""

import math

import numpy as np
import openmdao.api as om


class RotorStackComp(om.ExplicitComponent):
    """
    Per-rotor arrays of several rotor sets, one after the other, as arrays of one set.

    For each quantity ``name`` with per-rotor shape ``tail`` and each set ``prefix`` of
    ``count`` rotors, the input ``{prefix}_{name}`` of shape ``(count, *tail)`` fills the rows
    of the output ``name`` of shape ``(sum of the counts, *tail)`` in the order of ``sets``. A
    model that hears the lift rotors and the pusher in one noise evaluation takes its rotor
    inputs from here. Partials: constant ones.

    Options
    -------
    sets : sequence of (str, int)
        Prefix and rotor count of each set, in stacking order.
    quantities : sequence of (str, tuple, str)
        Name, per-rotor shape (``()`` for a scalar) and units of each quantity.
    """

    def initialize(self):
        self.options.declare("sets", types=(list, tuple), desc="(prefix, count) of each set")
        self.options.declare(
            "quantities", types=(list, tuple), desc="(name, per-rotor shape, units) of each"
        )

    def setup(self):
        sets = [(str(prefix), int(count)) for prefix, count in self.options["sets"]]
        for prefix, count in sets:
            if count < 1:
                raise ValueError(
                    f"{self.msginfo}: set {prefix!r} must have >= 1 rotor, got {count}"
                )
        total = sum(count for _, count in sets)
        self._plan = []
        for name, tail, units in self.options["quantities"]:
            tail = tuple(tail)
            per_rotor = math.prod(tail)
            self.add_output(name, np.zeros((total, *tail)), units=units, desc=f"stacked {name}")
            start = 0
            for prefix, count in sets:
                source = f"{prefix}_{name}"
                self.add_input(source, np.zeros((count, *tail)), units=units, desc=f"{name}")
                size = count * per_rotor
                self.declare_partials(
                    name,
                    source,
                    rows=start * per_rotor + np.arange(size),
                    cols=np.arange(size),
                    val=1.0,
                )
                self._plan.append((name, source, slice(start, start + count)))
                start += count

    def compute(self, inputs, outputs):
        for name, source, rows in self._plan:
            outputs[name][rows] = inputs[source]
