"""Implicit frictional contact of an elastic block under a rigid cylinder in
FEniCSx (dolfinx 0.5), with asperity's friction laws at the contact nodes.

The model shared by `cattaneo_mindlin.py` and `energy_law.py`:

* Plane strain, a rectangular block [-L, L] x [-L, 0] clamped at its base,
  its top face the contact surface. Mixed displacement-pressure elements
  (Taylor-Hood P2-P1), so any Poisson ratio up to 0.5 is admissible: with
  nu = 0.5 and a rigid indenter Dundurs' beta vanishes and the normal and
  tangential problems uncouple, as Cattaneo-Mindlin's solution assumes.
* A rigid cylinder of radius R (parabolic profile x^2/2R, small strain: the
  gap is measured at the reference position), pushed down by delta and moved
  sideways by s (displacement control; the loads P and Q are the reactions).
* Node-to-rigid-surface contact at the P2 displacement nodes of the top face.
  Node i carries the tributary length w_i (the row sums of the boundary
  mass matrix, Simpson's weights for P2). The normal traction is a penalty,
  p_i = k_n max(0, o_i) with the overlap o_i = u_y + delta - X_i^2/2R. The
  tangential traction comes from asperity's friction law, stepped once per
  Newton iteration from the node's converged state with the slip increment
  of the load step (the block's tangential displacement relative to the
  indenter) and the normal traction, as Abaqus's VFRIC is called.
* The law is evaluated per unit nominal area (normal "force" p_i on the
  area 1 m^2, stick stiffness in Pa/m): the laws used here are positively
  homogeneous of degree one in (N, A_n, stick stiffness, stored force), so
  the nodal force is w_i times the returned traction. One law then serves
  nodes of any size.
* Newton-Raphson on R(U) = K U + f_c(U) with the consistent Jacobian
  K + df_c/dU, whose friction rows come from the law's tangents dF/d(slip)
  and dF/dN (`tangent="law"`). For comparison, `tangent="stick"` keeps the
  law's stick stiffness for every node in contact and drops dF/dN (a
  fixed-point, initial-stiffness update), `tangent="no_dfdn"` keeps dF/d(slip)
  but drops dF/dN.
* Parallel: dolfinx distributes the mesh; each rank steps the laws of the
  contact nodes whose dofs it owns, so every node's friction state lives on
  one rank. The linear solves are MUMPS LU.
"""

from __future__ import annotations

import json
import math
import sys
import time
from dataclasses import dataclass, field

import numpy as np
import ufl
from dolfinx import fem, mesh
from dolfinx.fem.petsc import assemble_matrix, assemble_vector
from mpi4py import MPI
from petsc4py import PETSc

import asperity

COMM = MPI.COMM_WORLD


def log(*args):
    """Print on rank 0 (to stderr, so that --json keeps stdout clean)."""
    if COMM.rank == 0:
        print(*args, file=sys.stderr, flush=True)


def graded_coordinates(core: float, h: float, length: float, growth: float) -> np.ndarray:
    """Node coordinates from 0 to `length`: spacing `h` up to `core`, then
    growing geometrically by `growth` per cell (the last cell stretched to
    end exactly at `length`)."""
    n_core = max(1, int(math.ceil(core / h - 1e-9)))
    xs = list(np.arange(n_core + 1) * h)
    step = h
    while xs[-1] < length:
        step *= growth
        xs.append(xs[-1] + step)
    xs = np.array(xs)
    # Scale the graded part so the last node is at `length`.
    graded = xs > n_core * h
    x0 = n_core * h
    xs[graded] = x0 + (xs[graded] - x0) * (length - x0) / (xs[-1] - x0)
    return xs


@dataclass
class Geometry:
    """The block, the indenter and the mesh (SI units)."""

    radius: float  # indenter radius R (m)
    half_width: float  # Hertz half-width the mesh is built around (m)
    size: float  # block half-width and depth L (m)
    cells_per_half_width: int  # mesh cells across the half-width a in the core
    growth: float = 1.15  # cell growth ratio outside the core
    core: float = 1.3  # core region |x| <= core * a, depth <= core * a


@dataclass
class Material:
    young: float  # E (Pa)
    poisson: float  # nu, in [0, 0.5]

    @property
    def shear(self) -> float:
        return self.young / (2.0 * (1.0 + self.poisson))

    @property
    def inverse_lame(self) -> float:
        """1/lambda (1/Pa); 0 for an incompressible material."""
        nu = self.poisson
        if nu >= 0.5:
            return 0.0
        return (1.0 + nu) * (1.0 - 2.0 * nu) / (nu * self.young) if nu > 0 else math.inf

    @property
    def plane_strain_modulus(self) -> float:
        """E* = E/(1 - nu^2) of the block against a rigid indenter (Pa)."""
        return self.young / (1.0 - self.poisson**2)

    @property
    def dundurs_beta(self) -> float:
        """Dundurs' beta for a rigid indenter, plane strain: (1-2nu)/(2(1-nu))."""
        nu = self.poisson
        return (1.0 - 2.0 * nu) / (2.0 * (1.0 - nu))


@dataclass
class StepRecord:
    delta: float
    shift: float
    normal_load: float
    tangential_load: float
    iterations: int
    residuals: list
    converged: bool


@dataclass
class Model:
    geometry: Geometry
    material: Material
    law: object  # an asperity.FrictionLaw
    penalty_factor: float = 1.0e3  # k_n = k_t = factor * E*/h_node (Pa/m)
    tangent: str = "law"  # "law", "stick" or "no_dfdn"
    tolerance: float = 1e-10
    max_iterations: int = 30
    friction_active: bool = True  # False: frictionless (the law is not stepped)
    history: list = field(default_factory=list)

    def __post_init__(self):
        g, m = self.geometry, self.material
        self.h = g.half_width / g.cells_per_half_width
        self.h_node = self.h / 2.0  # P2 node spacing
        self.k_normal = self.penalty_factor * m.plane_strain_modulus / self.h_node
        self._build_mesh()
        self._build_forms()
        self._locate_contact()
        self.state = self.law.fresh_state(self.n_contact)
        self.delta = 0.0
        self.shift = 0.0
        self.U_old = self.U.copy()
        self.converged_response = None
        self.converged_active = None
        self.pressure = np.zeros(self.n_contact)
        self.last_increment = (0.0, 0.0)
        self.in_contact = np.zeros(self.n_contact, dtype=bool)
        self.last = _frictionless(self.state)
        self.work = 0.0
        self.dissipation = 0.0
        self.normal_load = 0.0
        self.tangential_load = 0.0

    # ------------------------------------------------------------ set-up
    def _build_mesh(self):
        g = self.geometry
        a = g.half_width
        xs_half = graded_coordinates(g.core * a, self.h, g.size, g.growth)
        xs = np.concatenate([-xs_half[:0:-1], xs_half])
        ys = -graded_coordinates(g.core * a, self.h, g.size, g.growth)[::-1]
        nx, ny = len(xs) - 1, len(ys) - 1
        msh = mesh.create_rectangle(
            COMM,
            [np.array([0.0, 0.0]), np.array([float(nx), float(ny)])],
            [nx, ny],
            mesh.CellType.triangle,
            diagonal=mesh.DiagonalType.left_right,
        )
        x = msh.geometry.x
        i = np.rint(x[:, 0]).astype(int)
        j = np.rint(x[:, 1]).astype(int)
        x[:, 0] = xs[i]
        x[:, 1] = ys[j]
        self.mesh = msh
        self.cells = msh.topology.index_map(2).size_global

    def _build_forms(self):
        msh, m = self.mesh, self.material
        P2 = ufl.VectorElement("Lagrange", msh.ufl_cell(), 2)
        P1 = ufl.FiniteElement("Lagrange", msh.ufl_cell(), 1)
        W = fem.FunctionSpace(msh, ufl.MixedElement([P2, P1]))
        self.W = W
        (u, p) = ufl.TrialFunctions(W)
        (v, q) = ufl.TestFunctions(W)
        mu = fem.Constant(msh, PETSc.ScalarType(m.shear))
        inv_lambda = fem.Constant(msh, PETSc.ScalarType(m.inverse_lame))
        eps = lambda w: ufl.sym(ufl.grad(w))  # noqa: E731
        a = (
            2.0 * mu * ufl.inner(eps(u), eps(v))
            - p * ufl.div(v)
            - q * ufl.div(u)
            - inv_lambda * p * q
        ) * ufl.dx
        fdim = msh.topology.dim - 1
        y0 = float(msh.geometry.x[:, 1].min())
        y0 = COMM.allreduce(y0, op=MPI.MIN)
        bottom = mesh.locate_entities_boundary(msh, fdim, lambda x: np.isclose(x[1], y0))
        V, _ = W.sub(0).collapse()
        zero = fem.Function(V)
        dofs = fem.locate_dofs_topological((W.sub(0), V), fdim, bottom)
        self.bcs = [fem.dirichletbc(zero, dofs, W.sub(0))]
        self.K = assemble_matrix(fem.form(a), bcs=self.bcs)
        self.K.assemble()
        self.J = self.K.duplicate(copy=True)
        self.J.setOption(PETSc.Mat.Option.NEW_NONZERO_ALLOCATION_ERR, True)
        self.w = fem.Function(W)
        self.U = self.w.vector
        self.R = self.U.duplicate()
        self.dU = self.U.duplicate()
        # Strain energy: mu eps:eps + p^2/(2 lambda) (with p = -lambda div u).
        uu, pp = ufl.split(self.w)
        self.energy_form = fem.form(
            (mu * ufl.inner(eps(uu), eps(uu)) + 0.5 * inv_lambda * pp * pp) * ufl.dx
        )
        top = mesh.locate_entities_boundary(msh, fdim, lambda x: np.isclose(x[1], 0.0))
        tags = mesh.meshtags(msh, fdim, np.sort(top), np.full(len(top), 1, dtype=np.int32))
        ds = ufl.Measure("ds", domain=msh, subdomain_data=tags)
        b = assemble_vector(fem.form(v[1] * ds(1)))
        b.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
        self.weights_vec = b
        self.ksp = PETSc.KSP().create(COMM)
        self.ksp.setType("preonly")
        pc = self.ksp.getPC()
        pc.setType("lu")
        pc.setFactorSolverType("mumps")

    def _locate_contact(self):
        W = self.W
        top = lambda x: np.isclose(x[1], 0.0)  # noqa: E731
        size_local = W.dofmap.index_map.size_local * W.dofmap.index_map_bs
        comps = []
        for c in (0, 1):
            Vc, _ = W.sub(0).sub(c).collapse()
            dW, dV = fem.locate_dofs_geometrical((W.sub(0).sub(c), Vc), top)
            X = Vc.tabulate_dof_coordinates()[dV, 0]
            owned = dW < size_local
            dW, X = dW[owned], X[owned]
            order = np.argsort(X)
            comps.append((dW[order], X[order]))
        (dx, Xx), (dy, Xy) = comps
        assert len(dx) == len(dy) and np.allclose(Xx, Xy), "x and y dofs of a node on one rank"
        self.dof_x, self.dof_y, self.X = dx, dy, Xx
        self.n_contact = len(dx)
        self.weight = self.weights_vec.array_r[dy].copy()
        imap = W.dofmap.index_map
        self.gx = imap.local_to_global(dx.astype(np.int32)).astype(PETSc.IntType)
        self.gy = imap.local_to_global(dy.astype(np.int32)).astype(PETSc.IntType)
        self.contact_nodes = COMM.allreduce(self.n_contact)

    # ------------------------------------------------------------ contact
    def _contact(self, U_arr, delta, shift):
        """Nodal contact response at the displacement U_arr (owned values)."""
        g = self.geometry
        ux, uy = U_arr[self.dof_x], U_arr[self.dof_y]
        overlap = uy + delta - self.X**2 / (2.0 * g.radius)
        active = overlap > 0.0
        pressure = np.where(active, self.k_normal * overlap, 0.0)
        ux_old = self.U_old.array_r[self.dof_x]
        slip = np.zeros((self.n_contact, 2))
        # A node that comes into contact in this step starts its slip where
        # it touches: its slip increment is measured from the converged
        # state only if it was in contact there (the usual convention of
        # node-to-surface codes; without it the motion before the touch
        # would count as slip).
        slip[:, 0] = np.where(self.in_contact, (ux - ux_old) - (shift - self.shift), 0.0)
        if not self.friction_active:
            return pressure, active, slip, _frictionless(self.state)
        # Per unit nominal area. A node is in contact for the law if its
        # gap is closed now or was closed at the converged state. One that
        # opens within the step keeps its nominal area under zero load
        # (with adhesion the law holds mu(0) A(0) there: dropping to an
        # open gap at once would make the residual jump, and Newton chase
        # the jump); it passes an open gap (A_n = 0, N = 0: no contact) from
        # the next step on. One that closes within the step starts with
        # zero slip (above).
        held = self.in_contact
        r = self.law.step_block(
            self.state, pressure, slip, 1.0, area=(active | held).astype(float),
            tangents=3,
        )
        return pressure, active, slip, r

    def _residual(self, delta, shift):
        self.K.mult(self.U, self.R)
        pressure, active, slip, r = self._contact(self.U.array_r, delta, shift)
        w = self.weight
        # R = K U - f_ext: the indenter pushes the block down with w p and
        # drags it with w t (t the law's traction on the block).
        R = self.R.array
        R[self.dof_y] += w * pressure
        R[self.dof_x] -= w * r.tangential_force[:, 0]
        return pressure, active, slip, r

    def _jacobian(self, active, r):
        self.K.copy(self.J, structure=PETSc.Mat.Structure.SAME_NONZERO_PATTERN)
        w, kn = self.weight, self.k_normal
        dn = np.where(active, kn * w, 0.0)
        if self.tangent == "law":
            dts = r.dforce_dslip[:, 0, 0] * self.in_contact
            dtn = r.dforce_dnormal[:, 0]
        elif self.tangent == "no_dfdn":
            dts = r.dforce_dslip[:, 0, 0] * self.in_contact
            dtn = np.zeros(self.n_contact)
        elif self.tangent == "stick":
            dts = np.where(active & (r.regime != 3), -self.law_stick_stiffness, 0.0)
            dtn = np.zeros(self.n_contact)
        else:
            raise ValueError(f"tangent must be law, stick or no_dfdn, got {self.tangent!r}")
        J = self.J
        add = PETSc.InsertMode.ADD_VALUES
        for i in range(self.n_contact):
            gx, gy = self.gx[i], self.gy[i]
            J.setValue(gy, gy, dn[i], addv=add)
            J.setValue(gx, gx, -w[i] * dts[i], addv=add)
            if dtn[i] != 0.0 and active[i]:
                J.setValue(gx, gy, -w[i] * dtn[i] * kn, addv=add)
        J.assemble()

    @property
    def law_stick_stiffness(self) -> float:
        """The law's stick stiffness (the "stick" Jacobian needs one)."""
        k = getattr(self.law, "stick_stiffness", None)
        if k is None:
            raise ValueError("the 'stick' Jacobian needs a law with a stick_stiffness")
        return k

    # ------------------------------------------------------------ steps
    def step(self, delta: float, shift: float) -> StepRecord:
        """One load step to indenter depth `delta` and shift `shift` (m):
        a tangent predictor, Newton iterations, then the states, the work
        and the dissipation are committed. Every linear solve counts as an
        iteration."""
        it = 0
        if self.converged_response is not None:
            self._predict(delta, shift)
            it = 1
        pressure, active, slip, r = self._residual(delta, shift)
        # Convergence is measured against the residual the load increment
        # causes at the converged state (the predictor's right-hand side).
        scale = max(self.increment_norm(delta, shift), self.R.norm(), 1e-300)
        residuals = [self.R.norm() / scale]
        converged = residuals[-1] <= self.tolerance
        while not converged and it < self.max_iterations:
            self._jacobian(active, r)
            self.ksp.setOperators(self.J)
            self.R.scale(-1.0)
            self.ksp.solve(self.R, self.dU)
            it += 1
            pressure, active, slip, r = self._line_search(delta, shift, residuals[-1] * scale)
            residuals.append(self.R.norm() / scale)
            converged = residuals[-1] <= self.tolerance
        self._commit(delta, shift, pressure, active, r)
        rec = StepRecord(
            delta, shift, self.normal_load, self.tangential_load, it, residuals, converged
        )
        self.history.append(rec)
        return rec

    def start_friction(self):
        """Step the law from now on. The predictor of the next step takes
        the law's tangents at the current state with a zero slip increment
        (stick, the stick stiffness), since the frictionless steps left
        none."""
        self.friction_active = True
        pressure, active, slip, r = self._residual(self.delta, self.shift)
        self.converged_response, self.converged_active = r, active

    def _line_search(self, delta, shift, norm0):
        """U += alpha dU with alpha = 1, 1/2, 1/4, ... (at most 6 halvings)
        until the residual norm decreases. A full step is taken whenever it
        decreases the residual, so the quadratic phase is untouched; the
        halving breaks the two-cycles of semismooth Newton when a node at
        the contact edge or the stick-slip boundary flips its slip
        direction from one iterate to the next."""
        alpha = 1.0
        for _ in range(7):
            self.U.axpy(alpha, self.dU)
            self.U.ghostUpdate(addv=PETSc.InsertMode.INSERT, mode=PETSc.ScatterMode.FORWARD)
            out = self._residual(delta, shift)
            if self.R.norm() < norm0 or alpha < 0.02:
                return out
            self.U.axpy(-alpha, self.dU)
            alpha *= 0.5
        return out

    def _load_derivative(self, delta, shift):
        """dR/d(load) * increment at the converged state, from its
        tangents: the residual a linear response to the increment of delta
        and s would leave (a vector over the whole space)."""
        r, active = self.converged_response, self.converged_active
        dd, ds = delta - self.delta, shift - self.shift
        w, kn = self.weight, self.k_normal
        dn = np.where(active, kn * w, 0.0)
        rhs = self.R.duplicate()
        rhs.zeroEntries()
        arr = rhs.array
        # R_y = w kn (u_y + delta - X^2/2R): dR_y/d delta = w kn.
        arr[self.dof_y] = dn * dd
        # R_x = -w t(slip, p), slip = u_x - u_x,old - (s - s_old):
        # dR_x/ds = w dt/dslip, dR_x/d delta = -w dt/dp kn.
        arr[self.dof_x] = w * (
            self.in_contact * r.dforce_dslip[:, 0, 0] * ds - kn * active * r.dforce_dnormal[:, 0] * dd
        )
        return rhs

    def increment_norm(self, delta, shift) -> float:
        if self.converged_response is None:
            return 0.0
        return self._load_derivative(delta, shift).norm()

    def _predict(self, delta, shift):
        """The tangent (Euler) predictor: U = U_old - J_old^-1 dR/d(load)
        increment, with the converged state's regimes and tangents. Without
        it a stiff stick spring sends the first iterate of a tangential step
        into gross slip, and Newton on the zero sliding tangent then
        oscillates between the two slip directions."""
        # Continuing in the direction of the last step: the converged
        # tangents (slipping nodes keep slipping). At a reversal (or the
        # first step after a normal phase) the elastic predictor: the law's
        # tangents at the converged state for a zero slip increment
        # (stick), which is exact at the reversal.
        self.U_old.copy(self.U)
        increment = (delta - self.delta, shift - self.shift)
        last = self.last_increment
        if not (increment[0] * last[0] > 0 or increment[1] * last[1] > 0):
            pressure, active, slip, r = self._contact(self.U.array_r, self.delta, self.shift)
            self.converged_response, self.converged_active = r, active
        self._jacobian(self.converged_active, self.converged_response)
        self.ksp.setOperators(self.J)
        rhs = self._load_derivative(delta, shift)
        rhs.scale(-1.0)
        self.ksp.solve(rhs, self.dU)
        self.U_old.copy(self.U)
        self.U.axpy(1.0, self.dU)
        self.U.ghostUpdate(addv=PETSc.InsertMode.INSERT, mode=PETSc.ScatterMode.FORWARD)

    def _commit(self, delta, shift, pressure, active, r):
        w = self.weight
        P = COMM.allreduce(float(np.sum(w * pressure)))
        Q = COMM.allreduce(float(np.sum(w * r.tangential_force[:, 0])))
        # Work of the indenter on the block, trapezoidal in each step.
        self.work += 0.5 * (self.normal_load + P) * (delta - self.delta)
        self.work += 0.5 * (self.tangential_load + Q) * (shift - self.shift)
        self.dissipation += COMM.allreduce(float(np.sum(w * r.dissipation)))
        self.state = r.state
        self.last = r
        self.converged_response, self.converged_active = r, active
        self.in_contact = active.copy()
        self.pressure = pressure
        self.normal_load, self.tangential_load = P, Q
        self.last_increment = (delta - self.delta, shift - self.shift)
        self.delta, self.shift = delta, shift
        self.U.copy(self.U_old)

    # ------------------------------------------------------------ outputs
    def strain_energy(self) -> float:
        return COMM.allreduce(fem.assemble_scalar(self.energy_form), op=MPI.SUM)

    def penalty_energy(self) -> float:
        overlap = self.pressure / self.k_normal
        return COMM.allreduce(float(np.sum(0.5 * self.weight * self.k_normal * overlap**2)))

    def friction_stored_energy(self) -> float:
        return COMM.allreduce(float(np.sum(self.weight * self.last.stored_energy)))

    def stored_energy(self) -> float:
        """Strain energy + normal penalty + the law's stored energy (J/m)."""
        return self.strain_energy() + self.penalty_energy() + self.friction_stored_energy()

    def interface(self) -> dict:
        """The interface fields on rank 0, sorted by X: position (m),
        pressure and shear traction (Pa), regime, accumulated slip path (m)
        and dissipation per unit area (J/m^2)."""
        r = self.last
        local = np.column_stack([
            self.X,
            self.pressure,
            r.tangential_force[:, 0],
            r.regime.astype(float),
            self.state[:, 1],
            self.state[:, 0],
            self.weight,
        ])
        parts = COMM.gather(local, root=0)
        if COMM.rank != 0:
            return {}
        allrows = np.vstack(parts)
        allrows = allrows[np.argsort(allrows[:, 0])]
        keys = ["x", "pressure", "shear", "regime", "slip_path", "dissipation_density", "weight"]
        return {k: allrows[:, i] for i, k in enumerate(keys)}

    def tangential_stiffness(self) -> float:
        """dQ/ds at the current converged state for a small shift: one
        solve with the law's tangents for a zero slip increment (the
        elastic predictor's), used to size the tangential steps."""
        self.U_old.copy(self.U)
        pressure, active, slip, r = self._contact(self.U.array_r, self.delta, self.shift)
        if not self.friction_active:
            raise RuntimeError("tangential_stiffness needs friction (start_friction)")
        self._jacobian(active, r)
        self.ksp.setOperators(self.J)
        # slip = u_x - s: dR_x/ds = w dt/dslip; dU/ds = -J^-1 dR/ds.
        dts = r.dforce_dslip[:, 0, 0]
        rhs = self.R.duplicate()
        rhs.zeroEntries()
        rhs.array[self.dof_x] = -self.weight * dts
        du = rhs.duplicate()
        self.ksp.solve(rhs, du)
        dux = du.array_r[self.dof_x]
        # Q = sum w t: dQ/ds = sum w dt/dslip (du_x/ds - 1).
        return COMM.allreduce(float(np.sum(self.weight * dts * (dux - 1.0))))


def hertz_half_width(load: float, radius: float, modulus: float) -> float:
    """2-D Hertz: a = sqrt(4 P R / (pi E*)) for the load P per unit length."""
    return math.sqrt(4.0 * load * radius / (math.pi * modulus))


def fit_elliptic_edge(x: np.ndarray, y: np.ndarray) -> tuple[float, float]:
    """Least-squares fit of y^2 = A (1 - x^2/e^2) to points with y > 0;
    returns (e, sqrt(A)): the edge of a semi-elliptic profile such as the
    Hertz pressure p0 sqrt(1 - x^2/a^2), located between nodes."""
    m = np.vstack([np.ones_like(x), x**2]).T
    coef, *_ = np.linalg.lstsq(m, y**2, rcond=None)
    A, B = coef
    return math.sqrt(-A / B), math.sqrt(A)


def dump_json(obj) -> str:
    def conv(o):
        if isinstance(o, np.ndarray):
            return o.tolist()
        if isinstance(o, (np.floating, np.integer)):
            return o.item()
        raise TypeError(type(o))

    return json.dumps(obj, default=conv, indent=1)


def pyplot():
    """matplotlib.pyplot with the Agg backend, or None (plots skipped)."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        log("no matplotlib: no plots")
        return None
    return plt


def timer():
    t0 = time.perf_counter()
    return lambda: time.perf_counter() - t0


class _BlockResponse:
    """The fields of asperity's FrictionBlockResponse, for frictionless
    steps."""


def _frictionless(states):
    """The response of a frictionless step: no traction, states kept."""
    n = len(states)
    out = _BlockResponse()
    out.tangential_force = np.zeros((n, 2))
    out.dissipation = np.zeros(n)
    out.dforce_dslip = np.zeros((n, 2, 2))
    out.dforce_dnormal = np.zeros((n, 2))
    out.regime = np.full(n, 3, dtype=np.int32)
    out.stored_energy = np.zeros(n)
    out.state = states
    return out
