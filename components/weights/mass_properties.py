"""Mass properties of a set of bodies: total mass, centre of gravity and inertia tensor."""

from dataclasses import dataclass

import numpy as np
import openmdao.api as om

from lpc_mdo.core.checks import check_integer, check_range

_EYE = np.eye(3)
#: Columns of the ``item_mass_properties`` output: mass, cg and the item's inertia about the
#: vehicle cg (the six tensor entries).
ITEM_COLUMNS = ("mass", "x", "y", "z", "Ixx", "Iyy", "Izz", "Ixy", "Ixz", "Iyz")
_TENSOR = ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))


def transport_inertia(r):
    """
    Return the parallel-axis (transport) term P(r) = (r . r) 1 - r r^T and its derivative.

    A point mass m at offset r from a reference point adds m P(r) to the inertia tensor about
    that point (docs theory/weights 'Mass properties'). Complex-safe.

    Parameters
    ----------
    r : ndarray, (..., 3)
        Offsets.

    Returns
    -------
    p : ndarray, (..., 3, 3)
        P(r).
    dp_dr : ndarray, (..., 3, 3, 3)
        dP_ab/dr_l = 2 r_l delta_ab - delta_al r_b - r_a delta_bl.
    """
    r = np.asarray(r)
    rr = np.sum(r * r, axis=-1)
    p = rr[..., None, None] * _EYE - r[..., :, None] * r[..., None, :]
    dp = (
        2.0 * _EYE[:, :, None] * r[..., None, None, :]
        - _EYE[:, None, :] * r[..., None, :, None]
        - r[..., :, None, None] * _EYE[None, :, :]
    )
    return p, dp


@dataclass(frozen=True)
class MassItem:
    """
    One kind of body in :class:`MassPropertiesComp`.

    Attributes
    ----------
    name : str
        Prefix of the inputs ``{name}_mass``, ``{name}_cg`` and ``{name}_inertia``; a valid
        Python identifier.
    count : int
        Number of bodies of this kind (>= 1), e.g. 9 motors.
    own_inertia : bool
        True if the bodies have an inertia tensor about their own cg (input
        ``{name}_inertia``); False for point masses.
    """

    name: str
    count: int = 1
    own_inertia: bool = False

    def __post_init__(self):
        if not (isinstance(self.name, str) and self.name.isidentifier()):
            raise ValueError(f"MassItem.name = {self.name!r}; must be a Python identifier.")
        if not isinstance(self.count, int):
            raise ValueError(
                f"MassItem '{self.name}': 'count' must be an integer, got "
                f"{type(self.count).__name__} {self.count!r}"
            )
        check_integer("count", self.count, lower=1, where=f"MassItem '{self.name}'")
        if not isinstance(self.own_inertia, bool):
            raise ValueError(
                f"MassItem '{self.name}': own_inertia = {self.own_inertia!r}; "
                "must be True or False."
            )


def _check_items(name, value):
    if not isinstance(value, (list, tuple)) or not value:
        raise ValueError(f"Option '{name}' = {value!r}; must be a non-empty list of MassItem.")
    for item in value:
        if not isinstance(item, MassItem):
            raise ValueError(f"Option '{name}': {item!r} is not a MassItem.")
    names = [item.name for item in value]
    duplicates = sorted({n for n in names if names.count(n) > 1})
    if duplicates:
        raise ValueError(
            f"Option '{name}': duplicate MassItem names {duplicates}; each name must be unique."
        )


class MassPropertiesComp(om.ExplicitComponent):
    """
    Total mass, centre of gravity and inertia tensor about the cg of a set of bodies.

    Implements docs theory/weights 'Mass properties' (paper Sec. II.C, system mass properties with
    the parallel-axis theorem), vectorized over all N bodies:

    - m = sum_i m_i
    - cg = sum_i m_i p_i / m
    - I = sum_i [ I_i + m_i ((r_i . r_i) 1 - r_i r_i^T) ],  r_i = p_i - cg

    I_i is a body's own inertia tensor about its own cg (zero for point masses). Off-diagonal
    entries are tensor entries, I_xz = -integral(x z dm). Everything is in the body frame (x
    forward, y right, z down); the result does not depend on the origin.

    The bodies are grouped in kinds (option ``items``, a list of :class:`MassItem`); kind
    ``name`` with ``count`` c bodies has the inputs below. Outputs and partials are analytic:
    dcg/dm_i = r_i/m, dcg/dp_i = m_i/m 1, dI/dm_i = P(r_i), dI/dp_i = m_i dP/dr(r_i),
    dI/dI_i = 1 (the terms through cg cancel because sum_i m_i r_i = 0).

    Inputs
    ------
    {name}_mass : float, (c,), kg
        Masses (>= 0).
    {name}_cg : float, (c, 3) or (3,) if c = 1, m
        Centres of gravity, body frame.
    {name}_inertia : float, (c, 3, 3) or (3, 3) if c = 1, kg*m**2
        Own inertia tensors about the own cg, body axes; only if ``own_inertia``. Symmetric.

    Outputs
    -------
    total_mass : float, (1,), kg
        m.
    cg : float, (3,), m
        Centre of gravity of the set, body frame.
    inertia : float, (3, 3), kg*m**2
        Inertia tensor about ``cg``, body axes.
    item_mass_properties : float, (K, 10), (only with ``item_table``)
        One row per kind of body (the K ``items``), columns :data:`ITEM_COLUMNS`: its mass (kg),
        its mass-weighted cg (m; the mean of its bodies' positions while its mass is 0) and its
        contribution to ``inertia`` (kg m**2: I_i + m_i P(r_i) summed over its bodies, r_i from
        the vehicle cg; the rows add up to ``inertia``). Recorded with the other outputs, so a
        report reads the mass, cg and inertia of every item from a case file. Partials analytic:
        through the vehicle cg every row depends on every mass and position
        (dc/dm_j = r_j/m, dc/dp_j = m_j/m 1).

    Options
    -------
    items : list of MassItem
        Kinds of bodies, unique names.
    item_table : bool
        Add the ``item_mass_properties`` output. Default False.

    Raises
    ------
    om.AnalysisError
        In compute, if an input is not finite, a mass is negative, or the total mass is not > 0.
    """

    def initialize(self):
        self.options.declare(
            "items",
            types=(list, tuple),
            check_valid=_check_items,
            desc="kinds of bodies (MassItem: name, count, own_inertia)",
        )
        self.options.declare(
            "item_table", default=False, types=bool, desc="add the item_mass_properties output"
        )

    def setup(self):
        items = self.options["items"]
        self._slices = {}
        start = 0
        for item in items:
            c, name = item.count, item.name
            self._slices[name] = slice(start, start + c)
            start += c
            cg_shape = (3,) if c == 1 else (c, 3)
            inertia_shape = (3, 3) if c == 1 else (c, 3, 3)
            self.add_input(f"{name}_mass", np.zeros(c), units="kg", desc=f"mass of {name}")
            self.add_input(
                f"{name}_cg", np.zeros(cg_shape), units="m", desc=f"cg of {name}, body frame"
            )
            if item.own_inertia:
                self.add_input(
                    f"{name}_inertia",
                    np.zeros(inertia_shape),
                    units="kg*m**2",
                    desc=f"inertia tensor of {name} about its own cg, body axes",
                )
        self._num_bodies = start

        self.add_output("total_mass", 1.0, units="kg", desc="total mass")
        self.add_output("cg", np.zeros(3), units="m", desc="centre of gravity, body frame")
        self.add_output(
            "inertia", np.eye(3), units="kg*m**2", desc="inertia tensor about the cg, body axes"
        )

        if self.options["item_table"]:
            self.add_output(
                "item_mass_properties",
                np.zeros((len(items), len(ITEM_COLUMNS))),
                desc="per item: mass kg, cg m, inertia about the vehicle cg kg*m**2 "
                "(columns " + ", ".join(ITEM_COLUMNS) + ")",
            )
            ncol = len(ITEM_COLUMNS)
            # Dense in every mass and position (through the vehicle cg).
            self.declare_partials(
                "item_mass_properties", [f"{i.name}_{v}" for i in items for v in ("mass", "cg")]
            )
            for k, item in enumerate(items):
                if item.own_inertia:
                    # Row k's six tensor entries from the body's (a, b) input entries.
                    rows = np.tile(k * ncol + 4 + np.arange(6), item.count)
                    cols = (np.arange(item.count)[:, None] * 9
                            + np.array([3 * a + b for a, b in _TENSOR])).ravel()  # fmt: skip
                    self.declare_partials(
                        "item_mass_properties",
                        f"{item.name}_inertia",
                        rows=rows,
                        cols=cols,
                        val=1.0,
                    )

        for item in items:
            c, name = item.count, item.name
            self.declare_partials("total_mass", f"{name}_mass", val=np.ones((1, c)))
            self.declare_partials("cg", f"{name}_mass")
            self.declare_partials(
                "cg", f"{name}_cg", rows=np.tile(np.arange(3), c), cols=np.arange(3 * c)
            )
            self.declare_partials("inertia", [f"{name}_mass", f"{name}_cg"])
            if item.own_inertia:
                self.declare_partials(
                    "inertia",
                    f"{name}_inertia",
                    rows=np.tile(np.arange(9), c),
                    cols=np.arange(9 * c),
                    val=1.0,
                )

    def _gather(self, inputs):
        """Return masses (N,) and cgs (N, 3) of all bodies, checked."""
        masses, cgs = [], []
        for item in self.options["items"]:
            name = item.name
            mass = inputs[f"{name}_mass"]
            cg = inputs[f"{name}_cg"].reshape(item.count, 3)
            check_range(f"{name}_cg", cg, units="m", error=om.AnalysisError, where=self.msginfo)
            check_range(
                f"{name}_mass",
                mass,
                lower=0.0,
                units="kg",
                error=om.AnalysisError,
                where=self.msginfo,
            )
            masses.append(mass)
            cgs.append(cg)
        return np.concatenate(masses), np.concatenate(cgs)

    def compute(self, inputs, outputs):
        masses, points = self._gather(inputs)
        total = np.sum(masses)
        check_range(
            "total mass",
            total,
            lower=0.0,
            lower_open=True,
            units="kg",
            error=om.AnalysisError,
            where=self.msginfo,
        )
        cg = masses @ points / total
        p, _ = transport_inertia(points - cg)
        inertia = np.einsum("i,iab->ab", masses, p)
        for item in self.options["items"]:
            if item.own_inertia:
                own = inputs[f"{item.name}_inertia"]
                if not np.all(np.isfinite(own)):
                    raise om.AnalysisError(f"{self.msginfo}: {item.name}_inertia is not finite.")
                inertia = inertia + own.reshape(item.count, 3, 3).sum(axis=0)
        outputs["total_mass"] = total
        outputs["cg"] = cg
        outputs["inertia"] = inertia
        if self.options["item_table"]:
            outputs["item_mass_properties"] = self._item_table(inputs, masses, points, p)

    def _item_table(self, inputs, masses, points, p):
        """Rows of ``item_mass_properties`` (see the class docstring); p = P(r_i) of compute."""
        items = self.options["items"]
        table = np.zeros((len(items), len(ITEM_COLUMNS)), dtype=masses.dtype)
        for k, item in enumerate(items):
            sl = self._slices[item.name]
            m, pts = masses[sl], points[sl]
            total = np.sum(m)
            table[k, 0] = total
            table[k, 1:4] = m @ pts / total if total.real > 0.0 else np.mean(pts, axis=0)
            inertia = np.einsum("i,iab->ab", m, p[sl])
            if item.own_inertia:
                inertia = inertia + inputs[f"{item.name}_inertia"].reshape(-1, 3, 3).sum(axis=0)
            table[k, 4:] = [inertia[a, b] for a, b in _TENSOR]
        return table

    def compute_partials(self, inputs, partials):
        masses, points = self._gather(inputs)
        total = np.sum(masses)
        cg = masses @ points / total
        r = points - cg
        p, dp = transport_inertia(r)
        for item in self.options["items"]:
            name, sl = item.name, self._slices[item.name]
            partials["cg", f"{name}_mass"] = r[sl].T / total
            partials["cg", f"{name}_cg"] = np.repeat(masses[sl] / total, 3)
            partials["inertia", f"{name}_mass"] = p[sl].reshape(-1, 9).T
            # (c, a, b, l) -> rows (a, b), cols (body, l)
            dinertia = masses[sl, None, None, None] * dp[sl]
            partials["inertia", f"{name}_cg"] = dinertia.transpose(1, 2, 0, 3).reshape(
                9, 3 * item.count
            )
        if self.options["item_table"]:
            self._item_table_partials(partials, masses, points, total, r, p, dp)

    def _item_table_partials(self, partials, masses, points, total, r, p, dp):
        """Set the partials of ``item_mass_properties`` (analytic; see the class docstring)."""
        items = self.options["items"]
        ncol = len(ITEM_COLUMNS)
        ia, ib = np.array(_TENSOR).T
        blocks = {}
        for item in items:
            c = item.count
            blocks[item.name, "mass"] = np.zeros((len(items), ncol, c))
            blocks[item.name, "cg"] = np.zeros((len(items), ncol, c, 3))
        for k, item in enumerate(items):
            sl = self._slices[item.name]
            m, pts = masses[sl], points[sl]
            mk = np.sum(m)
            dm = blocks[item.name, "mass"][k]
            dcg = blocks[item.name, "cg"][k]
            dm[0] = 1.0
            if mk > 0.0:
                cg_k = m @ pts / mk
                dm[1:4] = ((pts - cg_k) / mk).T
                dcg[1:4] = (m / mk)[None, :, None] * _EYE[:, None, :]
            else:
                dcg[1:4] = _EYE[:, None, :] / item.count
            # Own bodies: d(m_i P(r_i)) at fixed vehicle cg.
            dm[4:] += p[sl][:, ia, ib].T
            dcg[4:] += (m[:, None, None, None] * dp[sl])[:, ia, ib, :].transpose(1, 0, 2)
            # Every body through the vehicle cg: d I_k / d c = -G_k, G_k = dP(S_k),
            # S_k = sum_{i in k} m_i r_i (dP is linear in r).
            s_k = m @ r[sl]
            g_k = transport_inertia(s_k)[1][ia, ib, :]  # (6, 3)
            for other in items:
                so = self._slices[other.name]
                # dc/dm_j = r_j / total, dc/dp_j = m_j / total 1.
                blocks[other.name, "mass"][k, 4:] -= g_k @ r[so].T / total
                blocks[other.name, "cg"][k, 4:] -= (
                    g_k[:, None, :] * (masses[so] / total)[None, :, None]
                )
        for item in items:
            partials["item_mass_properties", f"{item.name}_mass"] = blocks[
                item.name, "mass"
            ].reshape(len(items) * ncol, item.count)
            partials["item_mass_properties", f"{item.name}_cg"] = blocks[item.name, "cg"].reshape(
                len(items) * ncol, 3 * item.count
            )
