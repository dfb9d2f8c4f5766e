"""Gather per-condition values of the same items into one matrix (for KS across conditions)."""

import numpy as np
import openmdao.api as om


class GatherComp(om.ExplicitComponent):
    """
    Stack values of the same items (e.g. the nine motors) from several conditions as columns.

    Each source k has ``sizes[k]`` entries, entry j belonging to item ``items[k][j]``; the
    output has one row per item and one column per source:

        out[items[k][j], k] = source_k[j]

    An item absent from a source (the failed rotor of an OEI case) takes that column from the
    first source that has the item, so a KS aggregate over the row ignores the absence instead
    of seeing a zero; an item that no source has takes ``absent_value`` (a model built with a
    single OEI case: the failed rotor's motor carries no load at all).

    Inputs
    ------
    {source} : (sizes[k], 1), units of ``units``

    Outputs
    -------
    {name} : (num_items, num_sources)

    Options
    -------
    name : str
    sources : list of str
    items : list of sequences of int
        Item index of each entry of each source.
    num_items : int
    units : str or None
    absent_value : float or None
        Value of items that no source has (None: such an item is an error).
    """

    def initialize(self):
        self.options.declare("name", types=str, desc="output name")
        self.options.declare("sources", types=(list, tuple), desc="input names")
        self.options.declare("items", types=(list, tuple), desc="item index of each entry")
        self.options.declare("num_items", types=int, lower=1, desc="number of items")
        self.options.declare(
            "units",
            default=None,
            types=str,
            allow_none=True,
            desc="units of the inputs and the output",
        )
        self.options.declare(
            "absent_value",
            default=None,
            types=float,
            allow_none=True,
            desc="value of items that no source has",
        )

    def setup(self):
        opts = self.options
        sources, ni = list(opts["sources"]), opts["num_items"]
        items = [np.asarray(i, dtype=int) for i in opts["items"]]
        if len(items) != len(sources) or any(i.min() < 0 or i.max() >= ni for i in items):
            raise ValueError(
                f"{self.msginfo}: items = {[i.tolist() for i in items]} must give "
                f"one index array per source ({len(sources)}) with values in "
                f"0..{ni - 1}."
            )
        ns = len(sources)
        owner = {}
        for name, idx in zip(sources, items, strict=True):
            for j, item in enumerate(idx):
                owner.setdefault(int(item), (name, j))
        missing = sorted(set(range(ni)) - set(owner))
        if missing and opts["absent_value"] is None:
            raise ValueError(
                f"{self.msginfo}: items {missing} are in no source; give absent_value to fill them."
            )
        self._constant = np.zeros((ni, ns))
        for item in missing:
            self._constant[item, :] = opts["absent_value"]
        self._plan = []
        for k, (name, idx) in enumerate(zip(sources, items, strict=True)):
            self.add_input(
                name, np.zeros((idx.size, 1)), units=opts["units"], desc=f"values from {name}"
            )
            self._plan.append((name, idx, k))
        self.add_output(
            opts["name"],
            np.zeros((ni, ns)),
            units=opts["units"],
            desc="values per item (rows) and source (columns)",
        )
        # Build the (row, col) -> (source, entry) map including filled gaps.
        self._maps = {name: ([], []) for name in sources}
        for name, idx, k in self._plan:
            present = np.zeros(ni, dtype=bool)
            present[idx] = True
            for j, item in enumerate(idx):
                self._maps[name][0].append(item * ns + k)
                self._maps[name][1].append(j)
            for item in np.flatnonzero(~present):
                if int(item) in owner:
                    fill_name, j = owner[int(item)]
                    self._maps[fill_name][0].append(item * ns + k)
                    self._maps[fill_name][1].append(j)
        for name, (rows, cols) in self._maps.items():
            self.declare_partials(opts["name"], name, rows=rows, cols=cols, val=1.0)

    def compute(self, inputs, outputs):
        outputs[self.options["name"]] = self._constant
        out = outputs[self.options["name"]].reshape(-1)
        for name, (rows, cols) in self._maps.items():
            out[rows] = inputs[name].reshape(-1)[cols]
