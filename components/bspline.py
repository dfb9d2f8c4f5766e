"""Clamped B-spline curves from control points to evaluation stations (blade chord and twist)."""

import numpy as np
import openmdao.api as om
from scipy.interpolate import BSpline

from lpc_mdo.core.checks import check_integer, check_range, check_shape


def clamped_knots(num_cp, order):
    """
    Return the clamped (open uniform) knot vector on [0, 1].

    Parameters
    ----------
    num_cp : int
        Number of control points (>= order).
    order : int
        Spline order (degree + 1).

    Returns
    -------
    ndarray, (num_cp + order,)
        ``order`` zeros, the uniform interior knots, ``order`` ones.
    """
    degree = order - 1
    return np.concatenate(
        [np.zeros(degree), np.linspace(0.0, 1.0, num_cp - degree + 1), np.ones(degree)]
    )


def bspline_basis(x, num_cp, order):
    """
    Return the basis matrix B (len(x), num_cp) of the clamped B-spline: curve(x) = B @ cp.

    Parameters
    ----------
    x : array_like
        Parameter values in [0, 1].
    num_cp : int
        Number of control points (>= order).
    order : int
        Spline order (degree + 1).

    Returns
    -------
    scipy.sparse.csr_array
        Basis matrix with explicit zeros removed.
    """
    basis = BSpline.design_matrix(
        np.asarray(x, dtype=float), clamped_knots(num_cp, order), order - 1
    )
    basis = basis.tocsr()
    basis.eliminate_zeros()
    return basis


class BsplineComp(om.ExplicitComponent):
    """
    Clamped B-spline: control points to curve values at normalized stations x in [0, 1].

    Implements BladeAD ``BsplineParameterization`` (docs theory/rotors 'Blade parameterization'):
    curve(x) = sum_j N_j,order(x) cp_j with a clamped (open uniform) knot vector, so curve(0) = cp_0
    and curve(1) = cp_last. With the default num_cp = 4, order = 4 the knots are
    [0,0,0,0,1,1,1,1] and the curve is the cubic Bezier sum_i C(3,i) x^i (1-x)^(3-i) cp_i;
    control points linear in their Greville abscissae (equally spaced when num_cp = order) give an
    exactly linear curve. Evaluated by default at x = linspace(0, 1, num_points), uniform in x;
    value i goes to station i (docs theory/rotors 'Blade parameterization', the as-coded BladeAD
    mapping).

    The map is linear, output = B @ cp for each curve, so the Jacobian is the constant basis
    matrix B, block-diagonal over vec_size, declared once in setup with rows/cols/val.

    Inputs
    ------
    <in_name> : float, (vec_size, num_cp), units of option ``units``
        Control points, one row per curve (e.g. one per rotor).

    Outputs
    -------
    <out_name> : float, (vec_size, num_points), units of option ``units``
        Curve values at the stations x_interp, one row per curve.

    Options
    -------
    num_cp : int
        Number of control points per curve (>= order). Default 4.
    num_points : int
        Number of evaluation stations (>= 1). Default 10.
    order : int
        B-spline order = degree + 1 (>= 1). Default 4 (cubic).
    vec_size : int
        Number of independent curves sharing the basis (e.g. rotors). Default 1.
    x_interp : array_like or None
        Normalized parameter values (num_points,) in [0, 1] where the curve is evaluated, e.g.
        the normalized radius. Default None: linspace(0, 1, num_points).
    in_name : str
        Name of the control-point input. Default 'control_points'.
    out_name : str
        Name of the curve output. Default 'curve'.
    units : str or None
        Units of the control points and of the curve. Default None (dimensionless).
    """

    def initialize(self):
        self.options.declare(
            "num_cp",
            default=4,
            types=int,
            lower=1,
            desc="Number of control points per curve (>= order)",
        )
        self.options.declare(
            "num_points", default=10, types=int, lower=1, desc="Number of evaluation stations"
        )
        self.options.declare(
            "order", default=4, types=int, lower=1, desc="B-spline order = degree + 1 (4 = cubic)"
        )
        self.options.declare(
            "vec_size",
            default=1,
            types=int,
            lower=1,
            desc="Number of independent curves sharing the basis",
        )
        self.options.declare(
            "x_interp",
            default=None,
            types=(list, tuple, np.ndarray),
            allow_none=True,
            desc="Normalized stations in [0, 1] (num_points,); None: linspace(0, 1, num_points)",
        )
        self.options.declare(
            "in_name", default="control_points", types=str, desc="Name of the control-point input"
        )
        self.options.declare(
            "out_name", default="curve", types=str, desc="Name of the curve output"
        )
        self.options.declare(
            "units",
            default=None,
            types=str,
            allow_none=True,
            desc="Units of the control points and the curve (None: dimensionless)",
        )

    def _stations(self):
        num_points = self.options["num_points"]
        x = self.options["x_interp"]
        if x is None:
            return np.linspace(0.0, 1.0, num_points)
        x = check_shape(
            "x_interp",
            np.asarray(x, dtype=float),
            (num_points,),
            where=f"{self.msginfo} (option 'num_points' = {num_points})",
        )
        check_range("x_interp", x, lower=0.0, upper=1.0, where=self.msginfo)
        return x

    def setup(self):
        opts = self.options
        num_cp, order = opts["num_cp"], opts["order"]
        num_points, vec_size = opts["num_points"], opts["vec_size"]
        check_integer(
            "num_cp",
            num_cp,
            lower=order,
            allowed=f">= option 'order' = {order}",
            where=self.msginfo,
        )
        in_name, out_name = opts["in_name"], opts["out_name"]
        if in_name == out_name:
            raise ValueError(
                f"{self.msginfo}: options 'in_name' and 'out_name' are both "
                f"'{in_name}'; they must differ."
            )

        self.x_interp = self._stations()
        self.basis = bspline_basis(self.x_interp, num_cp, order)

        self.add_input(
            in_name,
            val=np.zeros((vec_size, num_cp)),
            units=opts["units"],
            desc="B-spline control points, one row per curve",
        )
        self.add_output(
            out_name,
            val=np.zeros((vec_size, num_points)),
            units=opts["units"],
            desc="B-spline curve values at the stations x_interp, one row per curve",
        )

        # Block-diagonal constant Jacobian: block c maps cp[c, :] to curve[c, :].
        coo = self.basis.tocoo()
        offsets = np.arange(vec_size)[:, np.newaxis]
        rows = (offsets * num_points + coo.row).ravel()
        cols = (offsets * num_cp + coo.col).ravel()
        vals = np.tile(coo.data, vec_size)
        self.declare_partials(out_name, in_name, rows=rows, cols=cols, val=vals)

    def compute(self, inputs, outputs):
        cp = inputs[self.options["in_name"]]
        outputs[self.options["out_name"]] = (self.basis @ cp.T).T
