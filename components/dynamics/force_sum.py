"""Sum of the forces and moments that act on the vehicle."""

import numpy as np
import openmdao.api as om


class ForceSumComp(om.ExplicitComponent):
    """
    Resultant force and moment (about the body origin) of several sources.

    F = sum_k F_k,  M = sum_k M_k, with each source giving its force (num_nodes, 3) in N and,
    unless listed in ``forces_only``, its moment about the body origin (num_nodes, 3) in N*m.
    A source in ``forces_only`` acts through the body origin (used for the parasite drag, whose
    line of action passes within centimetres of the cg, so its pitching moment is negligible).

    Inputs
    ------
    {source}_force : (num_nodes, 3), N
    {source}_moment : (num_nodes, 3), N*m

    Outputs
    -------
    force : (num_nodes, 3), N
    moment : (num_nodes, 3), N*m

    Options
    -------
    sources : list of str
    forces_only : list of str
        Sources without a moment input.
    num_nodes : int
    """

    def initialize(self):
        self.options.declare("sources", types=(list, tuple), desc="names of the load sources")
        self.options.declare(
            "forces_only",
            default=(),
            types=(list, tuple),
            desc="sources that act through the body origin",
        )
        self.options.declare(
            "num_nodes", default=1, types=int, lower=1, desc="number of flight conditions"
        )

    def setup(self):
        nn = self.options["num_nodes"]
        sources = list(self.options["sources"])
        unknown = set(self.options["forces_only"]) - set(sources)
        if not sources or unknown:
            raise ValueError(
                f"{self.msginfo}: sources = {sources}, forces_only = "
                f"{list(self.options['forces_only'])}; forces_only must be a subset "
                "of a non-empty sources list."
            )
        self.add_output("force", np.zeros((nn, 3)), units="N", desc="resultant force, body axes")
        self.add_output(
            "moment", np.zeros((nn, 3)), units="N*m", desc="resultant moment about the body origin"
        )
        for name in sources:
            self.add_input(
                f"{name}_force", np.zeros((nn, 3)), units="N", desc=f"force of {name}, body axes"
            )
            self.declare_partials("force", f"{name}_force", diagonal=True, val=1.0)
            if name not in self.options["forces_only"]:
                self.add_input(
                    f"{name}_moment",
                    np.zeros((nn, 3)),
                    units="N*m",
                    desc=f"moment of {name} about the body origin",
                )
                self.declare_partials("moment", f"{name}_moment", diagonal=True, val=1.0)

    def compute(self, inputs, outputs):
        outputs["force"] = 0.0
        outputs["moment"] = 0.0
        for name in self.options["sources"]:
            outputs["force"] += inputs[f"{name}_force"]
            if name not in self.options["forces_only"]:
                outputs["moment"] += inputs[f"{name}_moment"]


class VectorSumComp(om.ExplicitComponent):
    """
    Sum of several 3-vectors of the same units: ``output_name`` = sum of ``input_names``.

    The aerodynamic force and moment of a condition (lattice loads plus the stability
    corrections). OpenMDAO's AddSubtractComp computes the same, but declares its partials as
    scipy sparse identity matrices, whose products cost about four times those of the diagonal
    (rows, cols) partials declared here; the sum lies on every trim row's adjoint path.

    Inputs
    ------
    {input_names[k]} : (num_nodes, 3), ``units``

    Outputs
    -------
    {output_name} : (num_nodes, 3), ``units``

    Options
    -------
    output_name : str
    input_names : list of str
    units : str or None
    num_nodes : int
    """

    def initialize(self):
        self.options.declare("output_name", types=str, desc="name of the sum")
        self.options.declare("input_names", types=(list, tuple), desc="names of the terms")
        self.options.declare("units", default=None, types=str, allow_none=True, desc="units")
        self.options.declare("num_nodes", default=1, types=int, lower=1, desc="vectors per term")

    def setup(self):
        opts = self.options
        shape = (opts["num_nodes"], 3)
        names = list(opts["input_names"])
        if not names or len(set(names)) != len(names) or opts["output_name"] in names:
            raise ValueError(
                f"{self.msginfo}: input_names = {names}; give distinct names, none equal to "
                f"output_name = {opts['output_name']!r}."
            )
        self.add_output(opts["output_name"], np.zeros(shape), units=opts["units"], desc="sum")
        for name in names:
            self.add_input(name, np.zeros(shape), units=opts["units"], desc="term of the sum")
            self.declare_partials(opts["output_name"], name, diagonal=True, val=1.0)

    def compute(self, inputs, outputs):
        outputs[self.options["output_name"]] = sum(
            inputs[name] for name in self.options["input_names"]
        )
