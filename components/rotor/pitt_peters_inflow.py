"""Steady Pitt–Peters inflow: three inflow states per rotor from L^-1 lambda - c = 0 by Newton.

Paper eq. 14-15 and docs theory/rotors 'Pitt-Peters inflow' (with its correction of eq. 14: lambda =
lambda_0 + lambda_c (r/R) cos psi + lambda_s (r/R) sin psi). For each rotor and operating point the
states lambda = (lambda_0, lambda_c, lambda_s) (normalised by Omega R) satisfy the steady
form of eq. 15 (M lambda_dot = 0)::

    R(lambda) = F_A V Lt^-1 lambda - c(lambda) = 0

- c = (C_T, C_c, C_s): C_T = T/(rho pi R^2 (Omega R)^2), C_c = M_c/(rho pi R^2 (Omega R)^2 R),
  C_s = M_s/(...), with M_c = int r cos psi dT and M_s = int r sin psi dT the first-harmonic
  thrust moments of the blade-element loads at the current states (``pitt_peters_loads.py``;
  C_c = -C_My and C_s = C_Mx of docs theory/rotors 'Pitt-Peters inflow', psi measured in the
  direction of rotation from the downstream blade).
- Wake quantities (docs theory/rotors 'Pitt-Peters inflow' with the mean inflow lambda_0 itself; no
  nested momentum solve is needed because row 0 below is the momentum equation): lambda = mu_z +
  lambda_0
  (total normal inflow), mu^2 = mu_x^2 + mu_y^2, V_T = sqrt(mu^2 + lambda^2) (flow parameter),
  V_m = (mu^2 + lambda (lambda + lambda_0))/V_T (mass-flow parameter), wake skew
  chi = atan2(mu, lambda), tan(chi/2) = mu/(V_T + lambda).
- V = diag(V_T, V_m, V_m) (Peters & HaQuang 1988: the uniform state sees V_T, the harmonics V_m).
  In hover V_T = lambda_0 and V_m = 2 lambda_0, as in the as-coded BladeAD scaling (docs
  theory/rotors 'Pitt-Peters inflow'); in edgewise flight the uniform state is the momentum value
  lambda_0 = C_T/(2 F_A V_T)
  (when the coupling below vanishes), where the as-coded 2/V_eff scaling doubles it.
- Lt, the L matrix with the coupling at L10 (docs theory/rotors 'Pitt-Peters inflow' default,
  literature placement), in wind axes (lambda_c along the downstream direction)::

      [ 1/2            -k tan(chi/2)             0             ]
      [ k tan(chi/2)    4 cos chi/(1 + cos chi)   0             ],   k = 15 pi/64
      [ 0               0                        4/(1 + cos chi)]

  so that with zero first-harmonic loading lambda_c/lambda_0 = (15 pi/32) tan(chi/2). With an
  in-plane velocity along e_y as well (sideslip, or the pusher's plane), the same matrix is
  rotated to the downstream direction d = (mu_x, -s mu_y)/mu of the (cos, sin) state plane:
  with g = tan(chi/2) d = (mu_x, -s mu_y)/(V_T + lambda) the entries are L01 = -k g^T,
  L10 = k g, and the 2x2 block (4/(1 + cos chi)) I - 4 g g^T. g is smooth through hover (mu = 0),
  so the model is differentiable at zero edgewise speed.
- F_A = 1 with loss_placement='blade_element' (Prandtl's F multiplies the loads, docs theory/rotors
  'Pitt-Peters inflow'); then in hover lambda_0 = C_T/(2 V_T) exactly, the momentum value. With the
  default loss_placement='momentum', F acts where the BEM puts it, on the momentum side: F_A is
  the Prandtl-loss-weighted disk area over pi R^2, F_A = (2/(N_psi R^2)) sum_i dr_i r_i sum_psi F
  (the BEM's annulus momentum with F integrated over the disk; in hover C_T = 2 F_A lambda_0^2),
  and the loads carry no F. With the tangential induction (``pitt_peters_loads.py``, default on)
  this matches the BEM's hover thrust to 0.02 % on the LPC blade; without the swirl
  (docs theory/rotors 'Pitt-Peters inflow') it is 6.5 % high ('momentum') or 2.4 % high
  ('blade_element'). tests/test_pitt_peters_validation.py quantifies them.

Solver: Newton on each rotor's 3x3 system (vectorized over rotors and operating points) with a
backtracking line search per rotor, from the previous solution and, if that fails, from a cold
start (lambda_0 = 0.05 + max(0, -mu_z)); om.AnalysisError if neither converges. The Jacobian is
exact: the blade-element part is analytic (chain rule of the station equations), the 3x3 algebra
of R (wake quantities, Lt^-1, normalisation) is differentiated by complex step over its 13
per-rotor scalars (cheap: a few hundred flops per rotor). ``solve_linear`` inverts the 3x3 blocks,
so groups need no DirectSolver for this component.
"""

import numpy as np
import openmdao.api as om

from lpc_mdo.components.rotor.pitt_peters_loads import (
    RPM_TO_RAD_S,
    PittPetersBladeElements,
    SparsityPatterns,
    add_pitt_peters_inputs,
    declare_pitt_peters_options,
    input_kind,
    input_size,
    pitt_peters_values,
    rotor_blade_options,
)

#: Pitt–Peters coupling constant 15 pi/64.
L_COUPLING = 15.0 * np.pi / 64.0

_PARAMS = (
    "lam0",
    "lamc",
    "lams",
    "thrust",
    "moment_cos",
    "moment_sin",
    "loss_area",
    "omega",
    "radius",
    "density",
    "axial_velocity",
    "v_x",
    "v_y",
)
_LOADS = ("thrust", "moment_cos", "moment_sin", "loss_area")
_CS_STEP = 1.0e-30
_DET_MIN = 1.0e-10


def pitt_peters_residual(states, loading, mu_x, mu_y, mu_z, area_factor=1.0):
    """
    Nondimensional steady Pitt–Peters residual F_A V Lt^-1 lambda - c (module docstring).

    Vectorized over any leading shape; complex-step safe.

    Parameters
    ----------
    states : array_like, (..., 3)
        (lambda_0, lambda_c, lambda_s).
    loading : array_like, (..., 3)
        (C_T, C_c, C_s): thrust coefficient and first-harmonic thrust-moment coefficients.
    mu_x, mu_y : array_like, (...)
        In-plane advance ratios along e_x and (spin-signed) e_y; mu_y here is s v_y/(Omega R).
    mu_z : array_like, (...)
        Axial advance ratio V_x/(Omega R) (> 0: climb).
    area_factor : array_like, (...)
        F_A, the Prandtl-loss-weighted disk area fraction (1: full disk).

    Returns
    -------
    residual : ndarray, (..., 3)
    valid : ndarray of bool, (...)
        False where the states are outside the model (V_T + lambda <= 0, V_m <= 0 or a singular
        L matrix: axial descent into the vortex ring, wake skew beyond about 110 deg); the
        residual there is meaningless.
    """
    states = np.asarray(states)
    lam0 = states[..., 0]
    lam = mu_z + lam0
    mu2 = mu_x * mu_x + mu_y * mu_y
    v_t = np.sqrt(mu2 + lam * lam)
    den = v_t + lam
    valid = (np.real(den) > 0.0) & (np.real(v_t) > 0.0)
    v_t = np.where(valid, v_t, 1.0)
    den = np.where(valid, den, 1.0)
    v_m = (mu2 + lam * (lam + lam0)) / v_t
    valid &= np.real(v_m) > 0.0
    g_c = mu_x / den
    g_s = -mu_y / den
    l_x = 4.0 * v_t / den
    k = L_COUPLING
    dtype = np.result_type(states, loading, mu_x, mu_y, mu_z, area_factor, float)
    lt = np.zeros(np.shape(lam) + (3, 3), dtype=dtype)
    lt[..., 0, 0] = 0.5
    lt[..., 0, 1] = -k * g_c
    lt[..., 0, 2] = -k * g_s
    lt[..., 1, 0] = k * g_c
    lt[..., 2, 0] = k * g_s
    lt[..., 1, 1] = l_x - 4.0 * g_c * g_c
    lt[..., 2, 2] = l_x - 4.0 * g_s * g_s
    lt[..., 1, 2] = lt[..., 2, 1] = -4.0 * g_c * g_s
    valid &= np.real(np.linalg.det(lt)) > _DET_MIN
    lt = np.where(valid[..., None, None], lt, np.eye(3))
    y = np.linalg.solve(lt, states[..., None].astype(dtype))[..., 0]
    scaled = np.stack([v_t * y[..., 0], v_m * y[..., 1], v_m * y[..., 2]], axis=-1)
    return np.asarray(area_factor)[..., None] * scaled - loading, valid


class PittPetersInflowComp(om.ImplicitComponent):
    """
    Steady Pitt–Peters inflow states of several rotors at several operating points.

    Paper eq. 14-15, docs theory/rotors 'Pitt-Peters inflow'; the residual F_A V Lt^-1 lambda - c =
    0, its L matrix, scaling and solver are in the module docstring, the blade-element loads
    c(lambda) in :mod:`lpc_mdo.components.rotor.pitt_peters_loads`.

    Inputs
    ------
    rpm : float, (num_rotors, num_nodes), rpm
        Rotor speed.
    axial_velocity : float, (num_rotors, num_nodes), m/s
        Hub velocity relative to the air along the thrust axis (> 0: climb for a lift rotor).
    inplane_velocity : float, (num_rotors, num_nodes, 2), m/s
        Hub velocity relative to the air along the disk e_x and e_y (RotorVelocityComp).
    radius, hub_radius : float, (num_rotors,), m
        Tip and hub radius.
    station_radius, station_width : float, (num_rotors, num_radial), m
        Element-centre radii and quadrature widths (BladeStationsComp).
    chord : float, (num_rotors, num_radial), m
        Blade chord at the stations.
    twist : float, (num_rotors, num_radial), rad
        Blade pitch relative to the rotor plane at the stations.
    density, speed_of_sound, dynamic_viscosity : float, (num_nodes,), kg/m**3, m/s, Pa*s
        Atmosphere.

    Outputs
    -------
    inflow_states : float, (num_rotors, num_nodes, 3), -
        (lambda_0, lambda_c, lambda_s): uniform, cosine and sine inflow over Omega R.

    Options
    -------
    num_rotors, num_nodes, num_radial : int
        Array sizes (>= 1). Defaults 1, 1, 25.
    num_azimuth : int
        Azimuthal stations psi_k = 2 pi k/N_psi (>= 3). Default 25.
    num_blades : int or sequence of int
        Blades per rotor. Default 2.
    spin_direction : int or sequence of int
        +1 (right-handed about the thrust axis) or -1 per rotor. Default +1.
    polar : Polar
        Sectional polar. Default LinearQuadraticPolar() (docs theory/aerodynamics 'Linear-quadratic
        polar').
    tip_loss, hub_loss : bool
        Prandtl losses (default True).
    loss_placement : str
        'momentum' (default) or 'blade_element' (docs theory/rotors 'Pitt-Peters inflow'); module
        docstring.
    tangential_induction : bool
        Wake swirl per station (default True; ``pitt_peters_loads.py``).
    max_iterations : int
        Newton iterations per start (default 50).
    tolerance : float
        Convergence: max abs(R) per rotor (load-coefficient units, C_T ~ 1e-2), default 1e-12.

    Raises
    ------
    om.AnalysisError
        Input out of range (names the input, values and range), or no convergence.
    """

    def initialize(self):
        declare_pitt_peters_options(self.options)
        self.options.declare(
            "max_iterations", default=50, types=int, lower=1, desc="Newton iterations per start"
        )
        self.options.declare(
            "tolerance",
            default=1e-12,
            types=float,
            lower=1e-16,
            desc="Newton tolerance on max |residual| per rotor (C_T units)",
        )

    def setup(self):
        opts = self.options
        nr, nn = opts["num_rotors"], opts["num_nodes"]
        nrad, naz = opts["num_radial"], opts["num_azimuth"]
        blades, spin = rotor_blade_options(self)
        self._spin = spin
        self._momentum = opts["loss_placement"] == "momentum"
        self._field = PittPetersBladeElements(
            (nr, nn, nrad, naz),
            blades,
            spin,
            opts["polar"],
            opts["tip_loss"],
            opts["hub_loss"],
            opts["loss_placement"],
            opts["tangential_induction"],
            owner=self.msginfo,
        )
        self._loads = _LOADS if self._momentum else _LOADS[:3]
        add_pitt_peters_inputs(self, nr, nn, nrad)
        self.add_output(
            "inflow_states",
            val=np.tile([0.05, 0.0, 0.0], (nr, nn, 1)),
            units=None,
            desc="Inflow states (lambda_0, lambda_c, lambda_s) over Omega R",
        )

        wrt = [
            "inflow_states",
            "rpm",
            "axial_velocity",
            "inplane_velocity",
            "radius",
            "station_radius",
            "station_width",
            "chord",
            "twist",
            "density",
            "dynamic_viscosity",
            "speed_of_sound",
        ]
        if opts["hub_loss"]:
            wrt.append("hub_radius")
        self._wrt = wrt
        pat = SparsityPatterns(nr, nn, nrad, naz)
        for name in wrt:
            rows, cols = pat.op(3, input_kind(name), input_size(name))
            self.declare_partials("inflow_states", name, rows=rows, cols=cols)
        self._inverse = np.tile(np.eye(3), (nr, nn, 1, 1))
        self.newton_iterations = 0

    # ---------------------------------------------------------------- residual pieces
    def _values(self, inputs):
        return pitt_peters_values(self, inputs)

    def _params(self, x, states, ints):
        nr, nn = self.options["num_rotors"], self.options["num_nodes"]
        shape = (nr, nn)
        p = {
            "lam0": states[..., 0],
            "lamc": states[..., 1],
            "lams": states[..., 2],
            "omega": RPM_TO_RAD_S * x["rpm"],
            "radius": np.broadcast_to(x["radius"][:, None], shape),
            "density": np.broadcast_to(x["density"][None, :], shape),
            "axial_velocity": x["axial_velocity"],
            "v_x": x["inplane_velocity"][..., 0],
            "v_y": self._spin[:, None] * x["inplane_velocity"][..., 1],
        }
        for name in _LOADS:
            p[name] = ints.get(name, np.zeros(shape))
        return p

    def _op_residual(self, p):
        big_r = p["radius"]
        omega_r = p["omega"] * big_r
        norm = p["density"] * np.pi * big_r**2 * omega_r**2
        loading = np.stack(
            [
                p["thrust"] / norm,
                p["moment_cos"] / (norm * big_r),
                p["moment_sin"] / (norm * big_r),
            ],
            axis=-1,
        )
        states = np.stack([p["lam0"], p["lamc"], p["lams"]], axis=-1)
        area = 2.0 * p["loss_area"] / big_r**2 if self._momentum else 1.0
        return pitt_peters_residual(
            states,
            loading,
            p["v_x"] / omega_r,
            p["v_y"] / omega_r,
            p["axial_velocity"] / omega_r,
            area,
        )

    def _residual(self, x, states):
        fld = self._field
        st = fld.evaluate(x, states)
        ints = {name: fld.integrate(st, name) for name in self._loads}
        return self._op_residual(self._params(x, states, ints))

    def _residual_partials(self, x, states, keys, shared=False):
        """
        Residual partials wrt ``keys`` (inputs and/or 'inflow_states'), pattern order.

        ``shared``: the station field goes to the cache the loads component reads
        (PittPetersBladeElements.evaluate), in the linearization only.
        """
        fld = self._field
        st = fld.evaluate(x, states, partials=True, shared=shared)
        values, dints = fld.integrate_partials(st, [(name, 1.0) for name in self._loads], keys)
        ints = {name: values[..., i] for i, name in enumerate(self._loads)}
        p = self._params(x, states, ints)

        # Complex step of the 3x3 algebra over its per-rotor scalars: d[name] = dR/dp, (nr, nn, 3).
        base = np.stack([np.asarray(p[name], dtype=float) for name in _PARAMS])
        npar = len(_PARAMS)
        pert = base[None] + 1j * _CS_STEP * np.eye(npar)[:, :, None, None]
        res, _ = self._op_residual({name: pert[:, i] for i, name in enumerate(_PARAMS)})
        d = {name: res[i].imag / _CS_STEP for i, name in enumerate(_PARAMS)}

        spin = self._spin[:, None, None]
        direct = {
            "rpm": RPM_TO_RAD_S * d["omega"],
            "axial_velocity": d["axial_velocity"],
            "radius": d["radius"],
            "density": d["density"],
            "inplane_velocity": np.stack([d["v_x"], spin * d["v_y"]], axis=-1),
            "inflow_states": np.stack([d["lam0"], d["lamc"], d["lams"]], axis=-1),
        }
        # dR/d(integral) (nr, nn, 3, I) times d(integral)/d(input) (nr, nn, I, n).
        dload = np.stack([d[name] for name in self._loads], axis=-1)
        out = {}
        for key in keys:
            total = dload @ dints[key]
            if key in direct:
                total += direct[key].reshape(total.shape)
            out[key] = total
        return out

    # ---------------------------------------------------------------- OpenMDAO API
    def apply_nonlinear(self, inputs, outputs, residuals):
        res, valid = self._residual(self._values(inputs), outputs["inflow_states"])
        if not np.all(valid):
            self._raise_invalid(outputs["inflow_states"], valid)
        residuals["inflow_states"] = res

    def _raise_invalid(self, states, valid):
        bad = np.argwhere(~valid)
        raise om.AnalysisError(
            f"{self.msginfo}: inflow states {np.real(states[~valid]).tolist()} at (rotor, node) "
            f"{bad.tolist()} are outside the Pitt–Peters model (V_T + lambda > 0, V_m > 0 and a "
            "non-singular L matrix are required: no axial descent into the vortex-ring state, "
            "wake skew below about 110 deg)."
        )

    def _cold_start(self, x):
        omega_r = RPM_TO_RAD_S * np.real(x["rpm"]) * np.real(x["radius"])[:, None]
        mu_z = np.real(x["axial_velocity"]) / omega_r
        s = np.zeros(mu_z.shape + (3,))
        s[..., 0] = 0.05 + np.maximum(0.0, -mu_z)
        return s

    def _newton(self, x, states):
        tol, maxiter = self.options["tolerance"], self.options["max_iterations"]
        cplx = any(np.iscomplexobj(v) for v in x.values())
        x_real = {k: np.real(v) for k, v in x.items()}
        res, valid = self._residual(x, states)
        if not np.all(valid):
            return states, False, 0
        err = np.max(np.abs(res), axis=-1)
        extra = 2 if cplx else 0  # under complex step: settle the imaginary part as well
        for it in range(maxiter):
            if np.all(err <= tol):
                if extra == 0:
                    return states, True, it
                extra -= 1
            jac = self._residual_partials(x_real, np.real(states), ["inflow_states"])[
                "inflow_states"
            ]
            try:
                step_dir = -np.linalg.solve(jac, res[..., None])[..., 0]
            except np.linalg.LinAlgError:
                return states, False, it
            step = np.ones(err.shape)
            for _ in range(40):
                trial = states + step[..., None] * step_dir
                res_t, valid_t = self._residual(x, trial)
                err_t = np.where(valid_t, np.max(np.abs(res_t), axis=-1), np.inf)
                accept = (err_t <= (1.0 - 1e-4 * step) * err) | ((err <= tol) & valid_t)
                if np.all(accept):
                    break
                step = np.where(accept, step, 0.5 * step)
            else:
                return states, False, it
            states, res, err = trial, res_t, err_t
        return states, bool(np.all(err <= tol)), maxiter

    def solve_nonlinear(self, inputs, outputs):
        x = self._values(inputs)
        previous = outputs["inflow_states"]
        starts = [previous.copy()] if np.all(np.isfinite(previous)) else []
        starts.append(self._cold_start(x))
        states = previous
        for start in starts:
            states, ok, its = self._newton(x, start)
            self.newton_iterations = its
            if ok:
                outputs["inflow_states"] = states
                return
        res, valid = self._residual(x, states)
        err = np.where(valid, np.max(np.abs(res), axis=-1), np.inf)
        bad = np.argwhere(err > self.options["tolerance"])
        raise om.AnalysisError(
            f"{self.msginfo}: Pitt–Peters inflow did not converge at (rotor, node) "
            f"{bad.tolist()}: max |residual| = {np.real(err[err > self.options['tolerance']])}"
            f" (tolerance {self.options['tolerance']:g}), last states "
            f"{np.real(states[err > self.options['tolerance']]).tolist()}. The condition may be "
            "outside the model (axial descent, vortex-ring state, strong upflow through the disk)."
        )

    def linearize(self, inputs, outputs, partials):
        jac = self._residual_partials(
            self._values(inputs), outputs["inflow_states"], self._wrt, shared=True
        )
        for name in self._wrt:
            partials["inflow_states", name] = jac[name].ravel()
        self._inverse = np.linalg.inv(jac["inflow_states"])

    def solve_linear(self, d_outputs, d_residuals, mode):
        if mode == "fwd":
            d_outputs["inflow_states"] = np.einsum(
                "...ab,...b->...a", self._inverse, d_residuals["inflow_states"]
            )
        else:
            d_residuals["inflow_states"] = np.einsum(
                "...ba,...b->...a", self._inverse, d_outputs["inflow_states"]
            )
